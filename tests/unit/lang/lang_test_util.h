// Helpers shared by the lang unit tests: a source manager with one buffer,
// lexing to kinds, parsing to an S-expression dump and rendered diagnostics.
#pragma once

#include <string>
#include <vector>

#include "lang/ast.h"
#include "lang/diagnostics.h"
#include "lang/lexer.h"
#include "lang/source.h"

namespace sm::lang::testing {

struct Lexed {
  std::vector<Tok> kinds;
  std::vector<std::string> texts;
  std::string diags;
  std::size_t errors = 0;
};

inline Lexed lex_all(const std::string& text) {
  SourceManager sm;
  Diagnostics diags(sm);
  const FileId f = sm.add_buffer("t.geo", text).file;
  Lexer lx(sm, f, diags);
  Lexed out;
  for (;;) {
    const Token t = lx.next();
    if (t.kind == Tok::Eof) break;
    out.kinds.push_back(t.kind);
    out.texts.emplace_back(lx.text(t));
  }
  out.diags = diags.render_all();
  out.errors = diags.error_count();
  return out;
}

}  // namespace sm::lang::testing

#include "lang/parser.h"

namespace sm::lang::testing {

struct Parsed {
  std::string ast;    ///< dump() of the top-level statements
  std::string diags;  ///< rendered diagnostics
  std::size_t errors = 0;
  bool ok = false;
};

inline Parsed parse_text(const std::string& text, ParseOptions options = {}) {
  SourceManager sm;
  Diagnostics diags(sm);
  const FileId f = sm.add_buffer("t.geo", text).file;
  Ast ast;
  const ParseResult r = parse_file(sm, f, ast, diags, options);
  return {dump(ast, r.stmts), diags.render_all(), diags.error_count(), r.ok};
}

/// The dump of a single-statement script, without the trailing newline.
inline std::string ast_of(const std::string& text) {
  Parsed p = parse_text(text);
  if (!p.ok) return "ERRORS: " + p.diags;
  if (!p.ast.empty() && p.ast.back() == '\n') p.ast.pop_back();
  return p.ast;
}

}  // namespace sm::lang::testing
