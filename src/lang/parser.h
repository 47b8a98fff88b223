// Parsing .geo text into the shared Ast: recursive descent, one function per
// production of grammar/geo.ebnf, panic-mode recovery at statement boundaries.
#pragma once

#include <cstdint>

#include "lang/ast.h"
#include "lang/diagnostics.h"
#include "lang/source.h"

namespace sm::lang {

struct ParseOptions {
  /// Deepest nesting of expressions, blocks and brackets before a
  /// nesting-too-deep error (keeps the recursion far from the stack limit).
  std::uint32_t max_depth = 1000;
};

struct ParseResult {
  StmtList stmts;   ///< top-level statements, in order
  bool ok = false;  ///< no error was reported while parsing this file
};

/// Parses one loaded file into `ast` (which may already hold other files: the
/// interpreter parses an Included file into the same Ast when it reaches the
/// Include). Reports every independent syntax error to `diags`; the result must
/// not be evaluated unless `ok` (the interpreter checks diags.error_count()).
ParseResult parse_file(const SourceManager& sources, FileId file, Ast& ast, Diagnostics& diags,
                       const ParseOptions& options = {});

}  // namespace sm::lang
