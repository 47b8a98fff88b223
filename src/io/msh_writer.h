// Gmsh MSH writer: versions 2.2 and 4.1, ASCII and binary, with physical
// groups and names, following the layout Gmsh 4.8.4 itself writes (see
// Gmsh 4.8.4's reference manual, the MSH format chapter) so that every file loads in Gmsh.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/mesh_model.h"
#include "io/node_data.h"

namespace sm::io {

struct MshOptions {
  int version = 41;              // 22 or 41 (Mesh.MshFileVersion 2.2 / 4.1)
  bool binary = false;           // Mesh.Binary
  bool save_all = false;         // Mesh.SaveAll: also entities outside physical groups
  bool save_parametric = false;  // Mesh.SaveParametric (4.1 only): curve t, surface u v
  std::vector<NodeData> node_data{};  // Mesh.NodeData: one $NodeData section each (time 0, step 0)
  /// ASCII text is formatted on this many threads (General.NumThreads; <= 0: the
  /// hardware's) in chunks of fixed bounds, appended in order: the same bytes for any count.
  int threads = 1;
};

/// Serialises to a string (tests, small meshes).
std::string msh_to_string(const MeshModel& mesh, const MshOptions& opt);

/// Writes the file atomically. On failure returns false and sets *error to the
/// reason, without the path (as every save_* here: callers say "cannot write
/// 'PATH': REASON"); the target path is then untouched.
bool save_msh(const MeshModel& mesh, const MshOptions& opt, const std::string& path, std::string* error);

/// Writes mesh(i) to paths[i] for each i, all renamed into place only once every one is
/// complete (Mesh.PartitionSplitMeshFiles: one file per part); on failure *error names the
/// file that failed and no target is touched. mesh(i) is called once per file, in order,
/// and what it returns is written before mesh(i + 1) is asked for: the caller may build
/// each mesh in one reused object, so that memory holds one part at a time.
bool save_msh_files(const std::function<const MeshModel&(std::size_t)>& mesh, const MshOptions& opt,
                    const std::vector<std::string>& paths, std::string* error);

}  // namespace sm::io
