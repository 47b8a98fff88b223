// The output formats, one row each (io/output_format.cpp): the name -format takes, the
// file extension that picks it, its Mesh.Format number, the writer, and what the format
// can hold. The CLI (-format, the default -o name, --help) and `Save` read only this.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "io/mesh_model.h"
#include "io/mesh_partition.h"
#include "io/node_data.h"
#include "io/ocean_grid.h"
#include "io/picture.h"

namespace sm::io {

/// What a writer reads besides the mesh, so that the caller prepares only that.
enum class OutputInput {
  Mesh,        ///< the mesh with its node coordinates as Mesh.NodeCoordinates asks (MSH, VTK)
  Picture,     ///< PictureOptions (SVG, PNG)
  OceanGrid,   ///< OceanGridOptions: depths and boundary strings (fort.14, hgrid.gr3, UGRID)
};

/// Everything any writer reads; each reads its part (OutputFormat::input).
struct OutputSettings {
  bool binary = false;            ///< Mesh.Binary
  bool save_all = false;          ///< Mesh.SaveAll
  bool save_parametric = false;   ///< Mesh.SaveParametric (MSH 4.1)
  int msh_version = 41;           ///< 22 or 41, from OutputFormat::msh_file_version or Mesh.MshFileVersion
  PictureOptions picture;
  OceanGridOptions ocean;
  std::vector<NodeData> node_data;  ///< Mesh.NodeData, for the rows that hold node data
  /// Mesh.NbPartitions' partition of the mesh, for the rows that hold partitions; nullptr: none.
  const MeshPartition* partition = nullptr;
  bool split_files = false;       ///< Mesh.PartitionSplitMeshFiles: MSH one file per part
  bool partition_topology = true; ///< Mesh.PartitionCreateTopology: MSH interface curves and points
  int threads = 1;                  ///< General.NumThreads, for the writers that use threads (MSH)
};

/// The file of part `part` (1-based) with Mesh.PartitionSplitMeshFiles: "dir/x.msh" ->
/// "dir/x_3.msh" (the extension replaced by _N.msh), as Gmsh 4.8.4 names them.
std::string partition_file_name(const std::string& path, int part);

/// Writes `mesh` to `path` atomically; false with *error (without the path) on failure.
using OutputWriter = bool (*)(const MeshModel& mesh, const OutputSettings& settings, const std::string& path,
                              std::string* error);

struct OutputFormat {
  std::string_view name;               ///< -format NAME
  std::string_view extension;          ///< ".msh": picks the format by the file name (the first row that has it)
  std::string_view default_file_name;  ///< "fort.14": the file -o defaults to beside the script; "": the
                                       ///< script's name with `extension`
  int mesh_format = 0;                 ///< Gmsh's Mesh.Format number (1 msh, 16 vtk); 0: none, chosen by name
  double msh_file_version = 0;         ///< Mesh.MshFileVersion the name implies (2.2, 4.1); 0: the option's
  OutputInput input = OutputInput::Mesh;
  OutputWriter write = nullptr;
  bool holds_quads = false;            ///< quadrangles
  bool holds_partitions = false;       ///< mesh partitions
  bool holds_node_data = false;        ///< values per node
  std::string_view note;               ///< --help: "(a picture)" after the name; rows in a run with the
                                       ///< same note are listed "a or b (note)"
  std::string_view needs_file_name;    ///< why standard output or a FIFO will not do, "" when it will
  bool depth_required = false;         ///< every node has a depth (all 0 without Mesh.DepthField)
};

/// Every format, in the order --help lists them; the first is the default (MSH).
std::span<const OutputFormat> output_formats();
/// The row called `name`, or nullptr.
const OutputFormat* find_output_format(std::string_view name);
/// The first row with Mesh.Format `mesh_format`, or nullptr.
const OutputFormat* output_format_of_number(int mesh_format);
/// The first row whose extension is `extension` (".vtk"), or nullptr.
const OutputFormat* output_format_of_extension(std::string_view extension);

/// "msh, msh2, ..., gr3": every name, for "unknown format" messages.
std::string output_format_names();
/// ".msh, .vtk, ... or .gr3": the extensions that pick a format, each once.
std::string output_format_extensions();
/// The --help description of -format: "output format: msh, ...", lines broken before
/// `width` columns and continued at column `indent`.
std::string output_format_help(std::size_t indent, std::size_t width);

}  // namespace sm::io
