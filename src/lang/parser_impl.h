// The recursive-descent parser's state and productions, split over
// parser.cpp (statements, blocks, recovery), parser_expr.cpp (expressions),
// parser_stmt.cpp (assignments, commands, fields) and parser_geo.cpp (geometry).
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "lang/ast.h"
#include "lang/diagnostics.h"
#include "lang/lexer.h"
#include "lang/parser.h"

namespace sm::lang::detail {

/// Thrown after a syntax error has been reported: unwinds to the enclosing
/// statement list, which resynchronizes (panic mode).
struct SyntaxError {};

/// Source text for a message, shortened to at most 40 characters.
std::string clip(std::string_view text);

class Parser {
 public:
  Parser(const SourceManager& sources, FileId file, Ast& ast, Diagnostics& diags, const ParseOptions& options);
  ParseResult run();

 private:
  // ---- tokens (parser.cpp)
  const Token& peek(std::size_t n = 0);
  Tok kind(std::size_t n = 0) { return peek(n).kind; }
  bool at(Tok k, std::size_t n = 0) { return peek(n).kind == k; }
  Token advance();
  bool accept(Tok k);
  std::string_view text(const Token& t) const { return lexer_.text(t); }
  bool at_word(std::string_view w, std::size_t n = 0) { return at(Tok::Ident, n) && text(peek(n)) == w; }
  std::uint32_t line_of(SourceRange r) const;
  SourceRange since(const Token& first) const;  // from `first` to the last consumed token

  // ---- errors and recovery (parser.cpp)
  [[noreturn]] void fail_expected(std::string_view what);
  Token expect(Tok k, std::string_view what = {});
  Token expect_closing(Tok k, const Token& opener);
  void expect_semicolon();
  std::string describe(const Token& t) const;
  void synchronize(std::size_t start_offset);
  bool is_statement_boundary(Tok k) const;
  /// After the nesting limit or the error limit the rest of the file is skipped.
  bool stopped() const { return depth_reported_ || diags_.too_many_errors(); }
  /// No "unclosed block" error: the file was cut by an unterminated string or
  /// comment, or parsing stopped.
  bool quiet_at_end() { return stopped() || (peek().kind == Tok::Eof && lexer_.truncated()); }

  // ---- nesting depth
  struct DepthGuard {
    explicit DepthGuard(Parser& p);
    ~DepthGuard() { --p_.depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
    Parser& p_;
  };

  // ---- statements and blocks (parser.cpp)
  enum class Block : std::uint8_t { For, If, Macro };
  struct OpenBlock {
    Block kind;
    Token opener;
  };
  StmtList parse_block(const Token& opener, Block kind);
  void close_block(const Token& opener, Tok end, std::string_view end_kw);
  bool at_block_end();
  StmtId parse_statement();
  StmtId parse_if();
  StmtId parse_for();
  StmtId parse_macro();
  void parse_macro_name(StrId& name, ExprId& name_expr, std::string_view what);
  StmtId parse_call();
  StmtId parse_return();
  StmtId parse_exit_abort();
  StmtId parse_assert();
  StmtId add(const Token& first, StmtNode node, SourceRange keyword = {});
  void warn_statement_after(const Token& kw, SourceRange stmt_range);

  // ---- expressions (parser_expr.cpp)
  ExprId parse_expr();
  ExprId parse_binary(int min_prec);
  ExprId parse_unary();
  ExprId parse_postfix();
  ExprId parse_primary();
  ExprId parse_name_primary();
  ExprId parse_call_args(const Token& func, BuiltinId fn);
  ExprId parse_item();
  ExprList parse_items_until(Tok closer, const Token& opener);
  ExprId parse_braced_list();
  ExprId parse_list_value();
  Name parse_name();
  Name parse_name_after(const Token& ident);
  OptionRef parse_option_after(const Token& category, ExprId index);
  Token expect_member_word(std::string_view what);
  ExprId parse_entity_expr();
  ExprId parse_transform();
  ExprId parse_extrude();   // parser_extrude.cpp
  ShapeItem parse_shape_entry();
  ExprId parse_boundary();
  ExprId parse_coastline_query();
  ExprId parse_intersect();
  ExprId add_expr(const Token& first, ExprNode node);
  ExprId error_expr(const Token& at);
  /// The builtin called at token n: a builtin name followed by `(` or `[`
  /// (kNone otherwise: `name(i)` of any other name is indexing).
  BuiltinId call_at(std::size_t n = 0);
  bool starts_string_expr(std::size_t n = 0);

  // ---- assignments, commands, fields (parser_stmt.cpp)
  StmtId parse_ident_statement();
  StmtId parse_assignment(const Token& first);
  StmtId parse_command(const Token& word);
  StmtId parse_homology(const Token& word);
  StmtId parse_print();
  StmtId parse_define_constant();
  OnelabAttr parse_onelab_attr_after(const Token& key, Tok closer);
  StmtId parse_delete();
  StmtId parse_field_statement();
  StmtId parse_background_field();
  StmtId parse_plugin();
  StmtId parse_view();
  StmtId parse_color();
  StmtId parse_visibility();
  StmtId parse_set_factory();
  bool is_affop(Tok k) const;
  AffOp affop_of(Tok k) const;

  // ---- geometry and mesh constraints (parser_geo.cpp)
  StmtId parse_geometry_statement();
  StmtId parse_point();
  StmtId parse_curve(const Token& kw);
  StmtId parse_curve_loop_or_embed(const Token& kw);
  StmtId parse_surface(const Token& kw);
  StmtId parse_volume(const Token& kw);
  StmtId parse_compound();
  StmtId parse_sphere();
  StmtId parse_parametric();
  StmtId parse_coordinates();
  StmtId parse_euclidean();
  StmtId parse_physical();
  StmtId parse_coherence();
  StmtId parse_split();
  StmtId parse_set_max_tag();
  StmtId parse_embed(const Token& first, EntityKind ent);
  StmtId parse_mesh_size();
  StmtId parse_transfinite();
  StmtId parse_recombine();
  StmtId parse_entity_setting(SettingKind kind);
  StmtId parse_periodic();
  StmtId parse_reverse_mesh();
  StmtId parse_shape_statement();
  ShapeBlock parse_shape_block(const Token& owner);
  ShapeBlock parse_transform_body(const Token& owner);
  ExprId parse_tag_in_parens(const Token& kw);
  ExprId parse_entity_list(bool& all);
  EntityKind expect_entity(std::string_view what);
  bool at_entity(std::size_t n = 0);
  static EntityKind entity_of(Tok k);

  const SourceManager& sources_;
  Ast& ast_;
  Diagnostics& diags_;
  ParseOptions options_;
  Lexer lexer_;
  std::deque<Token> ahead_;
  Token prev_;
  std::uint32_t depth_ = 0;
  bool depth_reported_ = false;
  std::vector<OpenBlock> blocks_;
  std::size_t errors_at_start_ = 0;
};

}  // namespace sm::lang::detail
