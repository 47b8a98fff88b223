// Mesh size field statements (`Field[n] = Type;`, options, actions, Background
// Field). The field kernel arrives with a later issue; until then they report
// 'not supported yet' once per kind of statement.
#include "interp/builtins/dispatch.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

void exec_field_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  check_stmt_exprs(in, id);
  switch (s.kind()) {
    case StmtKind::FieldNew: in.not_supported_stmt(id, "Field[] ="); break;
    case StmtKind::FieldOption: in.not_supported_stmt(id, "Field[].Option ="); break;
    case StmtKind::FieldAction: in.not_supported_stmt(id, "Field[].Action"); break;
    case StmtKind::BackgroundField: in.not_supported_stmt(id, "Background Field"); break;
    case StmtKind::DeleteField: in.not_supported_stmt(id, "Delete Field"); break;
    default: in.not_supported_stmt(id, "field statement"); break;
  }
}

}  // namespace sm::interp
