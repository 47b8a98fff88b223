// Mesh commands (`Mesh 2;`, `Save "f.msh";`, `RefineMesh;`, ...) and the
// post-processing statements. The mesher and writers arrive with later issues;
// until then each reports 'not supported yet' once per command.
#include <array>

#include "interp/builtins/dispatch.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

bool exec_mesh_command(Interpreter& in, StmtId id, std::string_view command) {
  static constexpr std::array<std::string_view, 18> kKnown = {
      "Mesh", "Save", "Merge", "Print", "SystemCall", "CreateDir", "OptimizeMesh", "SetName",
      "SetOrder", "Sleep", "PartitionMesh", "RefineMesh", "RecombineMesh", "RenumberMeshNodes",
      "RenumberMeshElements", "SyncModel", "BoundingBox", "Coherence"};
  for (std::string_view k : kKnown) {
    if (k == command) {
      check_stmt_exprs(in, id);
      in.not_supported_stmt(id, command);
      return true;
    }
  }
  return false;
}

void exec_mesh_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  check_stmt_exprs(in, id);
  switch (s.kind()) {
    case StmtKind::Plugin: in.not_supported_stmt(id, "Plugin"); break;
    case StmtKind::View: in.not_supported_stmt(id, "View"); break;
    case StmtKind::Color: in.not_supported_stmt(id, "Color"); break;
    default: in.not_supported_stmt(id, "Coherence Mesh"); break;
  }
}

}  // namespace sm::interp
