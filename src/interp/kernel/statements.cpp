// The statement table (kernel/statements.def): which handler runs each statement
// kind the evaluator does not run itself.
#include "interp/kernel/statements.h"

#include <array>
#include <cstddef>

#include "base/check.h"
#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"

namespace sm::interp {

using lang::StmtKind;

namespace {

struct Row {
  StmtKind kind;
  StmtHandler handler;   // nullptr: a core statement
};

constexpr Row kRows[] = {
#define CORE_STMT(kind) {StmtKind::kind, nullptr},
#define KERNEL_STMT(kind, handler) {StmtKind::kind, &handler},
#include "interp/kernel/statements.def"
#undef CORE_STMT
#undef KERNEL_STMT
};

// One row per statement kind, in StmtKind's order, so that the kind indexes the table.
static_assert(std::size(kRows) == std::variant_size_v<lang::StmtNode>, "statements.def: one row per StmtKind");
constexpr bool rows_follow_kinds() {
  for (std::size_t i = 0; i < std::size(kRows); ++i)
    if (static_cast<std::size_t>(kRows[i].kind) != i) return false;
  return true;
}
static_assert(rows_follow_kinds(), "statements.def: rows out of StmtKind's order");

}  // namespace

StmtHandler kernel_stmt_handler(StmtKind kind) { return kRows[static_cast<std::size_t>(kind)].handler; }

void exec_kernel_stmt(Interpreter& in, lang::StmtId id) {
  const StmtHandler h = kernel_stmt_handler(in.ast().stmt(id).kind());
  SM_ASSERT(h != nullptr, "a core statement reached the kernel's table");
  h(in, id);
}

}  // namespace sm::interp
