// The kernel's statement table (kernel/statements.def): the handler of each statement
// kind that needs the geometry model, the fields, the coastlines or the mesher.
#pragma once

#include "lang/ast.h"

namespace sm::interp {

class Interpreter;

using StmtHandler = void (*)(Interpreter& in, lang::StmtId s);

/// The handler of `kind`, or nullptr for a statement the evaluator runs itself.
StmtHandler kernel_stmt_handler(lang::StmtKind kind);

/// Runs statement `s`, which must be of a kind with a handler.
void exec_kernel_stmt(Interpreter& in, lang::StmtId s);

}  // namespace sm::interp
