// Parser core: token lookahead, error reporting with panic-mode recovery,
// statement dispatch, and the block statements (If, For, Macro) with their
// unclosed-opener diagnostics. Productions are quoted from grammar/geo.ebnf.
#include "lang/parser.h"

#include <algorithm>

#include "lang/parser_impl.h"

namespace sm::lang {

ParseResult parse_file(const SourceManager& sources, FileId file, Ast& ast, Diagnostics& diags,
                       const ParseOptions& options) {
  detail::Parser p(sources, file, ast, diags, options);
  return p.run();
}

namespace detail {

Parser::Parser(const SourceManager& sources, FileId file, Ast& ast, Diagnostics& diags, const ParseOptions& options)
    : sources_(sources), ast_(ast), diags_(diags), options_(options), lexer_(sources, file, diags) {
  prev_ = Token{Tok::Eof, SourceRange{file, 0, 0}};
}

// ---------------------------------------------------------------- tokens

const Token& Parser::peek(std::size_t n) {
  while (ahead_.size() <= n) ahead_.push_back(lexer_.next());
  return ahead_[n];
}

Token Parser::advance() {
  peek();
  const Token t = ahead_.front();
  if (t.kind != Tok::Eof) ahead_.pop_front();
  prev_ = t;
  return t;
}

bool Parser::accept(Tok k) {
  if (!at(k)) return false;
  advance();
  return true;
}

std::uint32_t Parser::line_of(SourceRange r) const { return sources_.line_col(r.begin_loc()).line; }

SourceRange Parser::since(const Token& first) const {
  return SourceRange{first.range.file, first.range.begin, std::max(first.range.end, prev_.range.end)};
}

// ---------------------------------------------------------------- errors

// Source text quoted in a message, cut so that a 50 MB identifier or number
// does not end up in the message.
std::string clip(std::string_view text) {
  constexpr std::size_t kMax = 40;
  return text.size() <= kMax ? std::string(text) : std::string(text.substr(0, kMax - 3)) + "...";
}

std::string Parser::describe(const Token& t) const {
  switch (t.kind) {
    case Tok::Eof: return "end of file";
    case Tok::Ident: return fmt::format("identifier '{}'", clip(text(t)));
    case Tok::Number: return fmt::format("number '{}'", clip(text(t)));
    case Tok::String: return fmt::format("string {}", clip(text(t)));
    case Tok::Constant: return fmt::format("'{}'", text(t));
    default: break;
  }
  if (is_keyword(t.kind)) return fmt::format("'{}'", text(t));
  return std::string(tok_name(t.kind));
}

// Reports "expected <what>, found <token>" at the current token and unwinds.
// Nothing is reported on an Error token (the lexer already did) or at the end
// of a file truncated by an unterminated string/comment.
void Parser::fail_expected(std::string_view what) {
  const Token t = peek();
  const bool quiet = t.kind == Tok::Error || (t.kind == Tok::Eof && lexer_.truncated());
  if (!quiet) diags_.report(t.range, Diag::ExpectedToken, what, describe(t));
  throw SyntaxError{};
}

Token Parser::expect(Tok k, std::string_view what) {
  if (at(k)) return advance();
  fail_expected(what.empty() ? tok_name(k) : what);
}

// A closing token: on a mismatch the error names the opener's line and a note
// points back at it.
Token Parser::expect_closing(Tok k, const Token& opener) {
  if (at(k)) return advance();
  const Token t = peek();
  if (t.kind != Tok::Error && !(t.kind == Tok::Eof && lexer_.truncated())) {
    const std::string_view closer = tok_name(k).substr(1, 1);
    diags_.report(t.range, Diag::UnclosedDelimiter, closer, text(opener), line_of(opener.range), describe(t))
        .note(opener.range, fmt::format("'{}' opened here", text(opener)));
  }
  throw SyntaxError{};
}

// A missing ';' is reported just after the previous token (where it belongs)
// without unwinding: the statement itself was complete.
void Parser::expect_semicolon() {
  if (accept(Tok::Semicolon)) return;
  const Token t = peek();
  if (t.kind == Tok::Error || (t.kind == Tok::Eof && lexer_.truncated())) return;
  if (t.kind == Tok::RBrace || t.kind == Tok::RParen || t.kind == Tok::RBracket) {
    // A stray closer (`{1, 2}};`): one error at it, then skip to the ';'.
    diags_.report(t.range, Diag::ExpectedToken, "';' after the statement", describe(t));
    while (at(Tok::RBrace) || at(Tok::RParen) || at(Tok::RBracket)) advance();
    accept(Tok::Semicolon);
    return;
  }
  diags_.report(SourceRange{prev_.range.file, prev_.range.end, prev_.range.end}, Diag::ExpectedSemicolon);
}

bool Parser::is_statement_boundary(Tok k) const {
  switch (k) {
    case Tok::For: case Tok::EndFor: case Tok::If: case Tok::ElseIf: case Tok::Else: case Tok::EndIf:
    case Tok::Macro: case Tok::Return:
      return true;
    default:
      return false;
  }
}

// Panic mode: skip to just after the next ';' outside braces opened while
// skipping, or to a block keyword. Always makes progress past the statement's
// first token.
void Parser::synchronize(std::size_t start_offset) {
  int brace_depth = 0;
  for (;;) {
    const Token t = peek();
    if (t.kind == Tok::Eof) return;
    const bool progressed = t.range.begin > start_offset;
    if (progressed && brace_depth == 0 && is_statement_boundary(t.kind)) return;
    if (t.kind == Tok::LBrace) ++brace_depth;
    if (t.kind == Tok::RBrace) brace_depth = std::max(0, brace_depth - 1);
    advance();
    if (t.kind == Tok::Semicolon && brace_depth == 0) return;
  }
}

Parser::DepthGuard::DepthGuard(Parser& p) : p_(p) {
  if (++p_.depth_ > p_.options_.max_depth) {
    if (!p_.depth_reported_) {
      p_.depth_reported_ = true;
      p_.diags_.report(p_.peek().range, Diag::NestingTooDeep, p_.options_.max_depth);
    }
    --p_.depth_;
    throw SyntaxError{};
  }
}

// ---------------------------------------------------------------- statements

StmtId Parser::add(const Token& first, StmtNode node, SourceRange keyword) {
  return ast_.add_stmt(since(first), keyword.valid() ? keyword : first.range, std::move(node));
}

// file := { stmt }
ParseResult Parser::run() {
  errors_at_start_ = diags_.error_count();
  ParseResult result;
  while (!at(Tok::Eof) && !stopped()) {
    const Token t = peek();
    if (t.kind == Tok::EndFor || t.kind == Tok::EndIf || t.kind == Tok::ElseIf || t.kind == Tok::Else ||
        t.kind == Tok::Return) {
      const Token end = advance();
      static constexpr std::string_view kOpeners[] = {"For", "If", "If", "If", "Macro"};
      const std::size_t i = end.kind == Tok::EndFor ? 0 : end.kind == Tok::EndIf ? 1 : end.kind == Tok::ElseIf ? 2
                          : end.kind == Tok::Else ? 3 : 4;
      diags_.report(end.range, Diag::UnmatchedEnd, text(end), kOpeners[i]);
      accept(Tok::Semicolon);
      continue;
    }
    const std::size_t start = t.range.begin;
    try {
      const StmtId s = parse_statement();
      if (s.valid()) result.stmts.push_back(s);
    } catch (const SyntaxError&) {
      synchronize(start);
    }
  }
  result.ok = diags_.error_count() == errors_at_start_;
  return result;
}

// True at a token that ends the innermost open block (or the file).
bool Parser::at_block_end() {
  switch (kind()) {
    case Tok::Eof: case Tok::EndFor: case Tok::EndIf: case Tok::ElseIf: case Tok::Else: case Tok::Return:
      return true;
    default:
      return false;
  }
}

// block := { stmt }   (up to the keyword that ends the innermost open block)
// An end keyword belonging to an outer block, or to no block, is reported here.
StmtList Parser::parse_block(const Token& opener, Block kind) {
  blocks_.push_back({kind, opener});
  StmtList body;
  while (!stopped()) {
    const Tok k = this->kind();
    if (k == Tok::Eof) break;
    if (at_block_end()) {
      const bool mine = (kind == Block::For && k == Tok::EndFor) ||
                        (kind == Block::If && (k == Tok::EndIf || k == Tok::ElseIf || k == Tok::Else)) ||
                        (kind == Block::Macro && k == Tok::Return);
      if (mine) break;
      if (k == Tok::Return &&
          std::any_of(blocks_.begin(), blocks_.end(), [](const OpenBlock& b) { return b.kind == Block::Macro; })) {
        // `Return` nested in an If/For of a macro body: an early return.
        body.push_back(parse_return());
        continue;
      }
      const Block wanted = k == Tok::EndFor ? Block::For : k == Tok::Return ? Block::Macro : Block::If;
      const bool outer =
          std::any_of(blocks_.begin(), blocks_.end() - 1, [&](const OpenBlock& b) { return b.kind == wanted; });
      if (outer) break;  // the enclosing block's end: the caller reports this block as unclosed
      const Token end = advance();
      static constexpr std::string_view kNames[] = {"For", "If", "Macro"};
      diags_.report(end.range, Diag::UnmatchedEnd, text(end), kNames[static_cast<int>(wanted)]);
      accept(Tok::Semicolon);
      continue;
    }
    const std::size_t start = peek().range.begin;
    try {
      DepthGuard guard(*this);
      const StmtId s = parse_statement();
      if (s.valid()) body.push_back(s);
    } catch (const SyntaxError&) {
      synchronize(start);
    }
  }
  blocks_.pop_back();
  return body;
}

// block_end := end_keyword [ ";" ]
// Consumes the end keyword of a block opened by `opener`, or reports the block
// left open: at the token found instead, with a note at the opener.
void Parser::close_block(const Token& opener, Tok end, std::string_view end_kw) {
  if (at(end)) {
    advance();
    accept(Tok::Semicolon);
    return;
  }
  if (quiet_at_end()) return;
  const Token found = peek();
  const std::string_view opener_text = text(opener);
  if (found.kind == Tok::Eof) {
    diags_.report(found.range, Diag::UnterminatedBlock, opener_text, end_kw)
        .note(opener.range, fmt::format("'{}' opened here", opener_text));
  } else {
    diags_.report(found.range, Diag::ExpectedToken, fmt::format("'{}' to close '{}'", end_kw, opener_text),
                  describe(found))
        .note(opener.range, fmt::format("'{}' opened here", opener_text));
  }
}

StmtId Parser::parse_statement() {
  const Token t = peek();
  switch (t.kind) {
    case Tok::Semicolon: advance(); return StmtId{};  // empty statement
    case Tok::If: return parse_if();
    case Tok::For: return parse_for();
    case Tok::Macro: return parse_macro();
    case Tok::Call: return parse_call();
    case Tok::Exit: case Tok::Abort: return parse_exit_abort();
    case Tok::Assert: return parse_assert();
    case Tok::Printf: case Tok::Warning: case Tok::ErrorCmd: return parse_print();
    case Tok::DefineConstant: return parse_define_constant();
    case Tok::Delete: case Tok::Recursive: return parse_delete();
    case Tok::Field: case Tok::Coastline: return parse_field_statement();
    case Tok::Plugin: return parse_plugin();
    case Tok::View:  // `View[0].Name = ...` is an option assignment; `View "name" {...}` a view
      if (at(Tok::LBracket, 1) || at(Tok::Dot, 1)) return parse_assignment(advance());
      return parse_view();
    case Tok::Color: return parse_color();
    case Tok::Hide: case Tok::Show: return parse_visibility();
    case Tok::SetFactory: return parse_set_factory();
    case Tok::Ident: return parse_ident_statement();
    case Tok::Constant: {
      diags_.report(t.range, Diag::KeywordAsName, text(t));
      throw SyntaxError{};
    }
    default: break;
  }
  if (is_keyword(t.kind)) return parse_geometry_statement();
  if (t.kind == Tok::RBrace || t.kind == Tok::RParen || t.kind == Tok::RBracket) {
    // stray closers: one error for the whole run
    diags_.report(t.range, Diag::ExpectedStatement, describe(t));
    while (at(Tok::RBrace) || at(Tok::RParen) || at(Tok::RBracket)) advance();
    accept(Tok::Semicolon);
    return StmtId{};
  }
  if (t.kind == Tok::Error) throw SyntaxError{};
  if (!(t.kind == Tok::Eof && lexer_.truncated())) diags_.report(t.range, Diag::ExpectedStatement, describe(t));
  throw SyntaxError{};
}

// if_stmt := "If" "(" expr ")" block { "ElseIf" "(" expr ")" block } [ "Else" block ] "EndIf"
StmtId Parser::parse_if() {
  const Token kw = advance();
  IfStmt node;
  Token branch_kw = kw;
  for (;;) {
    IfBranch br;
    br.keyword = branch_kw.range;
    try {
      const Token open = expect(Tok::LParen, "'(' after 'If'");
      br.cond = parse_expr();
      expect_closing(Tok::RParen, open);
    } catch (const SyntaxError&) {
      // keep the branch (so its body is still checked); skip the rest of the header line
      const std::uint32_t line = line_of(branch_kw.range);
      while (!at(Tok::Eof) && line_of(peek().range) == line && !is_statement_boundary(kind())) advance();
      br.cond = error_expr(peek());
    }
    br.body = parse_block(kw, Block::If);
    node.branches.push_back(std::move(br));
    if (at(Tok::ElseIf)) {
      branch_kw = advance();
      if (node.has_else) diags_.report(branch_kw.range, Diag::ElseAfterElse, "ElseIf");
      continue;
    }
    break;
  }
  while (at(Tok::Else)) {
    const Token e = advance();
    if (node.has_else) diags_.report(e.range, Diag::ElseAfterElse, "Else");
    node.has_else = true;
    node.else_keyword = e.range;
    StmtList more = parse_block(kw, Block::If);
    node.else_body.insert(node.else_body.end(), more.begin(), more.end());
    while (at(Tok::ElseIf)) {  // ElseIf after Else: report, parse, drop
      const Token ei = advance();
      diags_.report(ei.range, Diag::ElseAfterElse, "ElseIf");
      try {
        const Token open = expect(Tok::LParen);
        parse_expr();
        expect_closing(Tok::RParen, open);
      } catch (const SyntaxError&) {
      }
      parse_block(kw, Block::If);
    }
  }
  close_block(kw, Tok::EndIf, "EndIf");
  return add(kw, std::move(node));
}

// for_stmt := "For" "(" expr ":" expr [ ":" expr ] ")" block "EndFor"
//           | "For" IDENT "In" "{" expr ":" expr [ ":" expr ] "}" block "EndFor"
StmtId Parser::parse_for() {
  const Token kw = advance();
  ForStmt node;
  try {
    Token open;
    if (at(Tok::Ident)) {
      const Token var = advance();
      node.var = ast_.intern(text(var));
      node.var_range = var.range;
      expect(Tok::In, "'In' after the loop variable");
      open = expect(Tok::LBrace, "'{' before the loop range");
    } else {
      open = expect(Tok::LParen, "'(' or a loop variable after 'For'");
    }
    node.from = parse_expr();
    expect(Tok::Colon, "':' in the loop range (For loops take a range 'a:b' or 'a:b:c')");
    node.to = parse_expr();
    if (accept(Tok::Colon)) node.step = parse_expr();
    expect_closing(open.kind == Tok::LBrace ? Tok::RBrace : Tok::RParen, open);
  } catch (const SyntaxError&) {
    const std::uint32_t line = line_of(kw.range);
    while (!at(Tok::Eof) && line_of(peek().range) == line && !is_statement_boundary(kind())) advance();
    if (!node.from.valid()) node.from = error_expr(peek());
    if (!node.to.valid()) node.to = error_expr(peek());
  }
  node.body = parse_block(kw, Block::For);
  close_block(kw, Tok::EndFor, "EndFor");
  return add(kw, std::move(node));
}

// macro_name := IDENT | STRING | sexpr | keyword: the name a Macro defines or a Call runs.
// A keyword is a name here (`Macro Circle`, `Call Circle;`), not a command.
void Parser::parse_macro_name(StrId& name, ExprId& name_expr, std::string_view what) {
  if (at(Tok::Ident) && call_at() == BuiltinId::kNone) {
    name = ast_.intern(text(advance()));
  } else if (at(Tok::String)) {
    const Token s = advance();
    name = ast_.intern(text(s).substr(1, text(s).size() - 2));
  } else if (starts_string_expr()) {
    name_expr = parse_expr();
  } else if (is_keyword(kind())) {
    name = ast_.intern(text(advance()));
  } else {
    fail_expected(what);
  }
}

// macro_stmt := ("Macro" | "Function") (IDENT | sexpr) block "Return"
StmtId Parser::parse_macro() {
  const Token kw = advance();
  MacroStmt node;
  if (std::any_of(blocks_.begin(), blocks_.end(), [](const OpenBlock& b) { return b.kind == Block::Macro; }))
    diags_.report(kw.range, Diag::NestedMacro);
  parse_macro_name(node.name, node.name_expr, "a macro name");
  node.body = parse_block(kw, Block::Macro);
  close_block(kw, Tok::Return, "Return");
  return add(kw, std::move(node));
}

// A nested `Return` (inside If/For in a macro): leaves the macro.
StmtId Parser::parse_return() {
  const Token kw = advance();
  accept(Tok::Semicolon);
  return add(kw, ReturnStmt{});
}

// call_stmt := "Call" (IDENT | sexpr) ";"
StmtId Parser::parse_call() {
  const Token kw = advance();
  CallStmt node;
  parse_macro_name(node.name, node.name_expr, "a macro name after 'Call'");
  expect_semicolon();
  const StmtId id = add(kw, std::move(node));
  warn_statement_after(kw, ast_.stmt(id).range);
  return id;
}

// Gmsh runs the rest of the line before a Call/Include takes effect; we run in
// order, so say so when more statements follow on the same line.
void Parser::warn_statement_after(const Token& kw, SourceRange stmt_range) {
  const Token t = peek();
  if (t.kind == Tok::Eof || is_statement_boundary(t.kind) || t.kind == Tok::Error) return;
  if (line_of(t.range) !=
      line_of(SourceRange{stmt_range.file, stmt_range.end ? stmt_range.end - 1 : 0, stmt_range.end}))
    return;
  diags_.report(t.range, Diag::StatementAfterCall, text(kw));
}

// exit_stmt := "Exit" [ expr ] ";" | "Abort" ";"
StmtId Parser::parse_exit_abort() {
  const Token kw = advance();
  if (kw.kind == Tok::Abort) {
    expect_semicolon();
    return add(kw, AbortStmt{});
  }
  ExitStmt node;
  if (!at(Tok::Semicolon) && !at_block_end()) node.code = parse_expr();
  expect_semicolon();
  return add(kw, std::move(node));
}

// assert_stmt := "Assert" "(" expr "," sexpr { "," item } ")" ";"      (* native *)
StmtId Parser::parse_assert() {
  const Token kw = advance();
  const Token open = expect(Tok::LParen, "'(' after 'Assert'");
  AssertStmt node;
  node.cond = parse_expr();
  if (accept(Tok::Comma)) {
    node.message = parse_expr();
    while (accept(Tok::Comma)) node.args.push_back(parse_item());
  }
  expect_closing(Tok::RParen, open);
  expect_semicolon();
  return add(kw, std::move(node));
}

}  // namespace detail
}  // namespace sm::lang
