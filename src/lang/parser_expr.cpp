// Expression productions: one precedence table for the binary operators with
// Gmsh's quirks (docs/language.md: `^` right-associative and tighter than unary
// minus, `|` `&` tighter than `*`), names with `~{}` suffixes, lists, ranges,
// calls, option reads and geometry queries.
#include <algorithm>

#include "lang/parser_impl.h"

namespace sm::lang::detail {

namespace {

// Binding power of a binary operator (0: not one). Higher binds tighter. The
// prefix operators sit between `|`/`&` (7) and `^` (9): see parse_unary.
constexpr int kCaretPrec = 9;
int binary_prec(Tok k) {
  switch (k) {
    case Tok::PipePipe: return 1;
    case Tok::AmpAmp: return 2;
    case Tok::EqEq: case Tok::NotEq: return 3;
    case Tok::Less: case Tok::Greater: case Tok::LessEq: case Tok::GreaterEq:
    case Tok::ShiftLeft: case Tok::ShiftRight: return 4;
    case Tok::Plus: case Tok::Minus: return 5;
    case Tok::Star: case Tok::Slash: case Tok::Percent: return 6;
    case Tok::Pipe: case Tok::Amp: return 7;
    case Tok::Caret: return kCaretPrec;
    default: return 0;
  }
}

}  // namespace

ExprId Parser::add_expr(const Token& first, ExprNode node) { return ast_.add_expr(since(first), std::move(node)); }

ExprId Parser::error_expr(const Token& at) { return ast_.add_expr(at.range, ErrorExpr{}); }

bool Parser::starts_string_expr(std::size_t n) {
  const Token& t = peek(n);
  if (t.kind == Tok::String) return true;
  if (t.kind == Tok::Constant) return constant_is_string(constant_from_text(text(t)));
  const BuiltinId fn = call_at(n);
  return fn != BuiltinId::kNone && builtin_function(fn).result == BuiltinResult::Str;
}

BuiltinId Parser::call_at(std::size_t n) {
  if (!at(Tok::Ident, n) || !(at(Tok::LParen, n + 1) || at(Tok::LBracket, n + 1))) return BuiltinId::kNone;
  return find_builtin_function(text(peek(n)));
}

// expr := or_expr [ "?" expr ":" expr ]
ExprId Parser::parse_expr() {
  DepthGuard guard(*this);
  const Token first = peek();
  const ExprId cond = parse_binary(1);
  if (!accept(Tok::Question)) return cond;
  const ExprId then_expr = parse_expr();
  expect(Tok::Colon, "':' in the conditional expression");
  const ExprId else_expr = parse_expr();
  return add_expr(first, TernaryExpr{cond, then_expr, else_expr});
}

// or_expr := unary { binop unary }      (precedence and associativity: binary_prec)
ExprId Parser::parse_binary(int min_prec) {
  const Token first = peek();
  ExprId lhs = parse_unary();
  for (;;) {
    const int prec = binary_prec(kind());
    if (prec == 0 || prec < min_prec) return lhs;
    const Token op = advance();
    ExprId rhs;
    if (op.kind == Tok::Caret) {
      DepthGuard guard(*this);  // right recursion: 2^2^2^... nests
      rhs = parse_binary(kCaretPrec);
    } else {
      rhs = parse_binary(prec + 1);
    }
    lhs = add_expr(first, BinaryExpr{op.kind, lhs, rhs});
  }
}

// unary := ("-" | "+" | "!") unary_operand | postfix
// The operand of a prefix operator takes `^` but nothing weaker: -2^2 = -(2^2).
ExprId Parser::parse_unary() {
  if (at(Tok::Minus) || at(Tok::Plus) || at(Tok::Not)) {
    const Token op = advance();
    DepthGuard guard(*this);
    const ExprId operand = parse_binary(kCaretPrec);
    return add_expr(op, UnaryExpr{op.kind, operand});
  }
  return parse_postfix();
}

// postfix := primary [ "++" | "--" ]
ExprId Parser::parse_postfix() {
  const Token first = peek();
  const ExprId e = parse_primary();
  if (at(Tok::PlusPlus) || at(Tok::MinusMinus)) {
    const ExprKind k = ast_.expr(e).kind();
    if (k == ExprKind::Var || k == ExprKind::Index || k == ExprKind::Option) {
      const Token op = advance();
      return add_expr(first, PostfixExpr{op.kind, e});
    }
  }
  return e;
}

// primary := NUMBER | STRING | const | "(" expr ")" | "{" [ items ] "}" | "#" postfix
//          | name_primary | entity_expr | transform | boundary | coastline_query
ExprId Parser::parse_primary() {
  const Token t = peek();
  switch (t.kind) {
    case Tok::Number: {
      const Token n = advance();
      double v = 0;
      if (!number_value(text(n), v)) diags_.report(n.range, Diag::NumberOutOfRange, clip(text(n)));
      return add_expr(n, NumberExpr{v});
    }
    case Tok::String: {
      const Token s = advance();
      const std::string_view raw = text(s);
      return add_expr(s, StringExpr{ast_.intern(raw.substr(1, raw.size() - 2))});
    }
    case Tok::Constant: {
      const Token c = advance();
      return add_expr(c, ConstantExpr{constant_from_text(text(c))});
    }
    case Tok::LParen: {
      const Token open = advance();
      const ExprId e = parse_expr();
      expect_closing(Tok::RParen, open);
      return e;
    }
    case Tok::LBrace: return parse_braced_list();
    case Tok::Hash: {
      const Token h = advance();
      const ExprId operand = parse_postfix();
      return add_expr(h, LengthExpr{operand});
    }
    case Tok::Ident:
      if (at_word("Intersect") && at(Tok::Curve, 1)) return parse_intersect();
      return parse_name_primary();
    case Tok::View:  // option category: View[0].Name
      if (at(Tok::LBracket, 1) || at(Tok::Dot, 1)) return parse_name_primary();
      break;
    case Tok::Point: case Tok::Curve: case Tok::Surface: case Tok::Volume: case Tok::Physical:
      return parse_entity_expr();
    case Tok::Translate: case Tok::Rotate: case Tok::Symmetry: case Tok::Dilate: case Tok::Duplicata:
      return parse_transform();
    case Tok::Extrude: return parse_extrude();
    case Tok::Boundary: case Tok::CombinedBoundary: case Tok::PointsOf:
      return parse_boundary();
    case Tok::Coastline: return parse_coastline_query();
    default: break;
  }
  if (t.kind == Tok::Error || (t.kind == Tok::Eof && lexer_.truncated())) throw SyntaxError{};
  diags_.report(t.range, Diag::ExpectedExpression, describe(t));
  throw SyntaxError{};
}

// name := IDENT { "~" "{" expr "}" } | ("StringToName" | "S2N") ("[" | "(") expr ("]" | ")")
Name Parser::parse_name() {
  const Token id = expect(Tok::Ident, "a name");
  return parse_name_after(id);
}

Name Parser::parse_name_after(const Token& ident) {
  Name n;
  const std::string_view w = text(ident);
  if ((w == "StringToName" || w == "S2N") && (at(Tok::LBracket) || at(Tok::LParen))) {
    const Token open = advance();
    n.from_string = parse_expr();
    expect_closing(open.kind == Tok::LBracket ? Tok::RBracket : Tok::RParen, open);
  } else {
    n.ident = ast_.intern(w);
  }
  while (at(Tok::Tilde) && at(Tok::LBrace, 1)) {
    advance();
    const Token open = advance();
    n.suffixes.push_back(parse_expr());
    expect_closing(Tok::RBrace, open);
  }
  n.range = since(ident);
  return n;
}

// A member word after '.': any identifier, keyword or constant spelling
// (`Mesh.Smoothing`, `Geometry.Color.Points`, `Field[1].Min`...).
Token Parser::expect_member_word(std::string_view what) {
  if (at(Tok::Ident) || at(Tok::Constant) || is_keyword(kind())) return advance();
  fail_expected(what);
}

// option := IDENT [ "[" expr "]" ] "." word [ "." word ]   (the '.' is next)
OptionRef Parser::parse_option_after(const Token& category, ExprId index) {
  OptionRef o;
  o.category = ast_.intern(text(category));
  o.index = index;
  expect(Tok::Dot);
  o.member = ast_.intern(text(expect_member_word("an option name after '.'")));
  if (at(Tok::Dot)) {
    advance();
    o.sub_member = ast_.intern(text(expect_member_word("an option name after '.'")));
  }
  o.range = since(category);
  return o;
}

// name_primary := FUNC ("(" [items] ")" | "[" [items] "]")
//               | name [ "[" "]" | "(" ")" | ("["|"(") "{" items "}" ("]"|")")
//                      | ("["|"(") expr ("]"|")") [ "." word [ "." word ] ] ]
//               | IDENT "." word [ "." word ]
ExprId Parser::parse_name_primary() {
  if (const BuiltinId fn = call_at(); fn != BuiltinId::kNone) return parse_call_args(advance(), fn);
  const Token id = advance();
  if (at(Tok::Dot) && (at(Tok::Ident, 1) || at(Tok::Constant, 1) || is_keyword(kind(1))))
    return add_expr(id, OptionExpr{parse_option_after(id, ExprId{})});
  Name name = parse_name_after(id);
  if (at(Tok::LBracket) || at(Tok::LParen)) {
    const Token open = advance();
    const Tok close = open.kind == Tok::LBracket ? Tok::RBracket : Tok::RParen;
    const bool paren = open.kind == Tok::LParen;
    if (accept(close)) return add_expr(id, WholeListExpr{std::move(name), paren});
    if (at(Tok::LBrace)) {
      const Token lb = advance();
      ExprList idx = parse_items_until(Tok::RBrace, lb);
      expect_closing(close, open);
      return add_expr(id, SliceExpr{std::move(name), std::move(idx), paren});
    }
    const ExprId index = parse_expr();
    expect_closing(close, open);
    if (at(Tok::Dot) && name.suffixes.empty() && name.ident.valid())
      return add_expr(id, OptionExpr{parse_option_after(id, index)});
    return add_expr(id, IndexExpr{std::move(name), index, paren});
  }
  return add_expr(id, VarExpr{std::move(name)});
}

// call := FUNC ("(" [ items ] ")" | "[" [ items ] "]")
//       | ("DefineNumber" | "DefineString") ("[" | "(") item { "," onelab_attr } ("]" | ")")
ExprId Parser::parse_call_args(const Token& func, BuiltinId fn) {
  const Token open = advance();
  CallExpr call;
  call.func = ast_.intern(text(func));
  call.func_range = func.range;
  call.square = open.kind == Tok::LBracket;
  call.fn = fn;
  const Tok closer = call.square ? Tok::RBracket : Tok::RParen;
  if (builtin_function(fn).pass == BuiltinPass::Onelab && !at(closer)) {
    // DefineNumber[value, Name "..", Min 0, Choices{...}]: the value is the only
    // argument; the ONELAB attributes are parsed and ignored.
    call.args.push_back(parse_item());
    while (accept(Tok::Comma)) {
      if (at(closer)) break;
      parse_onelab_attr_after(expect_member_word("a parameter attribute such as 'Name' or 'Min'"), closer);
    }
    expect_closing(closer, open);
  } else {
    call.args = parse_items_until(closer, open);
  }
  return add_expr(func, std::move(call));
}

// item := expr [ ":" expr [ ":" expr ] ]
ExprId Parser::parse_item() {
  const Token first = peek();
  const ExprId from = parse_expr();
  if (!at(Tok::Colon)) return from;
  advance();
  RangeExpr r;
  r.from = from;
  r.to = parse_expr();
  if (accept(Tok::Colon)) r.step = parse_expr();
  return add_expr(first, r);
}

// items := item { "," item }     (followed by the closer)
ExprList Parser::parse_items_until(Tok closer, const Token& opener) {
  ExprList items;
  if (accept(closer)) return items;
  for (;;) {
    items.push_back(parse_item());
    if (accept(Tok::Comma)) continue;
    expect_closing(closer, opener);
    return items;
  }
}

// list := "{" [ items ] "}"
ExprId Parser::parse_braced_list() {
  const Token open = expect(Tok::LBrace);
  DepthGuard guard(*this);
  ExprList items = parse_items_until(Tok::RBrace, open);
  return add_expr(open, ListExpr{std::move(items)});
}

// list_value := item      (a braced list is an expression; braces are optional
//                          around a single item: `Plane Surface(2) = 1;`)
ExprId Parser::parse_list_value() { return parse_item(); }

// entity_expr := ent "{" (items | ":") "}" | "Physical" ent "{" items "}"
//              | ent "In" "BoundingBox" "{" items "}"
ExprId Parser::parse_entity_expr() {
  const Token first = peek();
  bool physical = false;
  if (accept(Tok::Physical)) physical = true;
  const EntityKind ent = expect_entity(physical ? "an entity kind after 'Physical'" : "an entity kind");
  if (!physical && at(Tok::In)) {
    advance();
    expect(Tok::BoundingBox, "'BoundingBox' after 'In'");
    const Token open = expect(Tok::LBrace, "'{' after 'BoundingBox'");
    ExprList box = parse_items_until(Tok::RBrace, open);
    return add_expr(first, EntityInBoxExpr{ent, std::move(box)});
  }
  const Token open = expect(Tok::LBrace, "'{' after the entity kind");
  EntityQueryExpr q;
  q.ent = ent;
  q.physical = physical;
  if (at(Tok::Colon) && at(Tok::RBrace, 1)) {
    advance();
    advance();
    q.all = true;
  } else {
    q.tags = parse_items_until(Tok::RBrace, open);
  }
  return add_expr(first, std::move(q));
}

// transform := "Translate" "{" items "}" transform_body | "Rotate" "{" items "}" transform_body
//            | "Symmetry" "{" items "}" transform_body | "Dilate" "{" items "}" transform_body
//            | "Duplicata" shape_block
ExprId Parser::parse_transform() {
  const Token kw = advance();
  DepthGuard guard(*this);
  TransformExpr t;
  switch (kw.kind) {
    case Tok::Translate: t.kind = TransformKind::Translate; break;
    case Tok::Rotate: t.kind = TransformKind::Rotate; break;
    case Tok::Symmetry: t.kind = TransformKind::Symmetry; break;
    case Tok::Dilate: t.kind = TransformKind::Dilate; break;
    default: t.kind = TransformKind::Duplicata; break;
  }
  if (t.kind == TransformKind::Duplicata) {
    t.shapes = parse_shape_block(kw);
  } else {
    const Token open = expect(Tok::LBrace, fmt::format("'{{' after '{}'", text(kw)));
    t.params = parse_items_until(Tok::RBrace, open);
    t.shapes = parse_transform_body(kw);
  }
  return add_expr(kw, std::move(t));
}

// boundary := ("Boundary" | "CombinedBoundary" | "PointsOf") shape_block
ExprId Parser::parse_boundary() {
  const Token kw = advance();
  DepthGuard guard(*this);
  BoundaryExpr b;
  b.kind = kw.kind == Tok::Boundary ? BoundaryKind::Boundary
         : kw.kind == Tok::CombinedBoundary ? BoundaryKind::CombinedBoundary : BoundaryKind::PointsOf;
  b.shapes = parse_shape_block(kw);
  return add_expr(kw, std::move(b));
}

// coastline_query := "Coastline" "{" items "}"          (* native *)
ExprId Parser::parse_coastline_query() {
  const Token kw = advance();
  const Token open = expect(Tok::LBrace, "'{' after 'Coastline' (or '[' for a coastline definition)");
  ExprList ids = parse_items_until(Tok::RBrace, open);
  return add_expr(kw, CoastlineQueryExpr{std::move(ids)});
}

// intersect := "Intersect" "Curve" "{" items "}" "Surface" "{" expr "}"
// (Gmsh 4.8.4's Parser/Gmsh.y: the built-in kernel's curve-surface intersection)
ExprId Parser::parse_intersect() {
  const Token kw = advance();
  DepthGuard guard(*this);
  expect(Tok::Curve, "'Curve' after 'Intersect'");
  const Token open = expect(Tok::LBrace, "'{' after 'Curve'");
  IntersectExpr node;
  node.curves = parse_items_until(Tok::RBrace, open);
  expect(Tok::Surface, "'Surface' after the curves");
  const Token open2 = expect(Tok::LBrace, "'{' after 'Surface'");
  node.surface = parse_expr();
  expect_closing(Tok::RBrace, open2);
  return add_expr(kw, std::move(node));
}

}  // namespace sm::lang::detail
