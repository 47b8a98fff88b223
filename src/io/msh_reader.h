// Reading a mesh file back, as `Merge "file.msh";` needs it: MSH 2.2 and 4.1 in ASCII
// (what Gmsh 4.8.4 and stereomesh write), nodes by tag and the elements of each model
// entity, for the element types stereomesh makes (points, lines, triangles, quadrangles).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

/// The elements of one type on one model entity, as the file classifies them.
struct MshBlock {
  int dim = 0;
  int tag = 0;
  ElementType type = ElementType::Point1;
  std::vector<int> physical_tags;        // ascending, without repeats
  std::vector<std::uint64_t> nodes;      // node tags, nodes_per_element(type) per element
};

struct MshFile {
  double version = 0;                    // 2.2 or 4.1
  std::map<std::uint64_t, Vec3> nodes;   // by tag
  std::vector<MshBlock> blocks;          // by increasing (dim, tag, type)
  std::vector<PhysicalGroup> physical_names;
};

/// The file's content, or `error` with the 1-based `line` it is about.
struct MshReadResult {
  MshFile file;
  std::string error;
  std::size_t line = 0;
  bool ok() const { return error.empty(); }
};

/// Reads the text of an MSH 2.2 or 4.1 ASCII file. Sections other than $MeshFormat,
/// $PhysicalNames, $Entities, $Nodes and $Elements are skipped; a binary file, another
/// version, an element type other than points, lines, triangles and quadrangles, an
/// element on a node the file does not define, or a count the text cannot hold is an
/// error.
MshReadResult read_msh(std::string_view text);

}  // namespace sm::io
