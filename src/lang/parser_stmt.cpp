// Statement productions that start with a name or a language keyword:
// assignments (all affops, list/element/sub-list/option forms, ++/--),
// commands (Include, Save, Mesh...), Printf/Warning/Error, DefineConstant,
// Delete, Field/Coastline, Background Field, Plugin, View, Color, SetFactory.
#include <algorithm>
#include <vector>

#include "base/edit_distance.h"
#include "lang/parser_impl.h"

namespace sm::lang::detail {

namespace {

// `IDENT sexpr ;` commands (docs/language.md `command`).
constexpr std::string_view kStringCommands[] = {
    "Merge", "Save", "Print", "SystemCall", "NonBlockingSystemCall", "CreateDir", "OptimizeMesh", "SetName",
    "MergeWithBoundingBox",
};
// `IDENT expr ;` commands.
constexpr std::string_view kNumberCommands[] = {"Mesh", "SetOrder", "Sleep", "PartitionMesh"};
// `IDENT ;` commands.
constexpr std::string_view kBareCommands[] = {
    "RefineMesh", "RecombineMesh", "RenumberMeshNodes", "RenumberMeshElements", "SyncModel", "CreateTopology",
    "ClassifySurfaces", "Draw", "NewModel", "CreateGeometry",
};
// Gmsh's (co)homology requests (Parser/Gmsh.y's HomologyCommand): words of their own there,
// so never a variable's name.
constexpr std::string_view kHomologyCommands[] = {"Homology", "Cohomology", "Betti"};

template <std::size_t N>
bool in(const std::string_view (&list)[N], std::string_view w) {
  return std::find(std::begin(list), std::end(list), w) != std::end(list);
}

// A misspelled command or keyword is within 2 of the real one; long words
// (hostile input) are not compared at all.
std::size_t capped_edit_distance(std::string_view a, std::string_view b) {
  if (a.size() > 40 || b.size() > 40) return 99;
  return edit_distance(a, b);
}

// The statement word closest to `w` (a keyword or command), or "".
std::string_view closest_statement_word(std::string_view w) {
  static constexpr std::string_view kWords[] = {
#define SM_KW(kind, text) text,
      SM_GEO_KEYWORDS(SM_KW)
#undef SM_KW
      "Include", "Background", "BoundaryLayer", "SetNumber", "SetString",
  };
  std::string_view best;
  std::size_t best_d = 3;
  auto consider = [&](std::string_view cand) {
    const std::size_t d = capped_edit_distance(w, cand);
    const std::size_t allowed = cand.size() <= 4 ? 1 : 2;  // short words: one typo only
    if (d < best_d && d <= allowed) {
      best_d = d;
      best = cand;
    }
  };
  for (std::string_view k : kWords) consider(k);
  for (std::string_view k : kStringCommands) consider(k);
  for (std::string_view k : kNumberCommands) consider(k);
  for (std::string_view k : kBareCommands) consider(k);
  for (std::string_view k : kHomologyCommands) consider(k);
  return best;
}

}  // namespace

bool Parser::is_affop(Tok k) const {
  return k == Tok::Assign || k == Tok::PlusAssign || k == Tok::MinusAssign || k == Tok::StarAssign ||
         k == Tok::SlashAssign;
}

AffOp Parser::affop_of(Tok k) const {
  switch (k) {
    case Tok::PlusAssign: return AffOp::Add;
    case Tok::MinusAssign: return AffOp::Sub;
    case Tok::StarAssign: return AffOp::Mul;
    case Tok::SlashAssign: return AffOp::Div;
    default: return AffOp::Assign;
  }
}

// ident_stmt := "Include" sexpr ";" | command | IDENT "Field" "=" list_value ";"
//             | ("SetNumber" | "SetString") "(" items ")" ";" | assign
StmtId Parser::parse_ident_statement() {
  const Token t = peek();
  const std::string_view w = text(t);
  const Tok next = kind(1);
  if (next == Tok::Field) return parse_background_field();
  if (in(kHomologyCommands, w) && (next == Tok::Semicolon || next == Tok::LBrace || next == Tok::LParen))
    return parse_homology(advance());
  const bool assignment_like = next == Tok::Dot || is_affop(next) || next == Tok::LBracket || next == Tok::LParen ||
                               next == Tok::Tilde || next == Tok::PlusPlus || next == Tok::MinusMinus;
  if (!assignment_like) {
    if (w == "Include" || in(kStringCommands, w) || in(kNumberCommands, w) || in(kBareCommands, w))
      return parse_command(advance());
  }
  if ((w == "SetNumber" || w == "SetString") && next == Tok::LParen) {
    const Token word = advance();
    const Token open = advance();
    ExprList args = parse_items_until(Tok::RParen, open);
    const ExprId list = add_expr(open, ListExpr{std::move(args)});
    expect_semicolon();
    return add(word, CommandStmt{ast_.intern(w), word.range, list});
  }
  return parse_assignment(advance());
}

// command := "Include" sexpr ";" | STRCMD sexpr ";" | NUMCMD expr ";" | BARECMD ";"
StmtId Parser::parse_command(const Token& word) {
  const std::string_view w = text(word);
  if (w == "Include") {
    IncludeStmt node;
    if (at(Tok::Semicolon)) fail_expected("a file name after 'Include'");
    node.path = parse_expr();
    expect_semicolon();
    const StmtId id = add(word, node);
    warn_statement_after(word, ast_.stmt(id).range);
    return id;
  }
  CommandStmt node;
  node.command = ast_.intern(w);
  node.command_range = word.range;
  if (!at(Tok::Semicolon)) node.arg = parse_expr();
  expect_semicolon();
  return add(word, node);
}

// homology := ("Homology" | "Cohomology" | "Betti")
//             [ "(" expr ")" "{" item "," item "}" | "{" item [ "," item ] "}" ] ";"
// The command's argument: a list of the dimensions (when given: a number or a list), the
// domain and the subdomain (when given), as written.
StmtId Parser::parse_homology(const Token& word) {
  CommandStmt node;
  node.command = ast_.intern(text(word));
  node.command_range = word.range;
  ExprList parts;
  const bool dims = at(Tok::LParen);
  if (dims) {
    const Token open = advance();
    parts.push_back(parse_expr());
    expect_closing(Tok::RParen, open);
    if (!at(Tok::LBrace)) fail_expected("'{' and the domain and subdomain after the dimensions");
  }
  if (at(Tok::LBrace)) {
    const Token open = advance();
    ExprList lists = parse_items_until(Tok::RBrace, open);
    if (lists.empty() || lists.size() > 2 || (dims && lists.size() != 2))
      fail_expected(fmt::format("{} in '{}'", dims ? "{domain, subdomain}" : "{domain} or {domain, subdomain}",
                                text(word)));
    for (ExprId e : lists) parts.push_back(e);
    node.arg = add_expr(open, ListExpr{std::move(parts)});
  }
  expect_semicolon();
  return add(word, node);
}

// assign := lvalue affop list_value ";" | lvalue ("++" | "--") ";"
// lvalue := name [ "[" "]" | "(" ")" | ("["|"(") "{" items "}" ("]"|")") | ("["|"(") expr ("]"|")") ]
//         | option
StmtId Parser::parse_assignment(const Token& first) {
  LValue lv;
  if (at(Tok::Dot) && text(first) != "StringToName" && text(first) != "S2N") {
    lv.kind = LValue::Kind::Option;
    lv.option = parse_option_after(first, ExprId{});
  } else {
    lv.name = parse_name_after(first);
    if (at(Tok::LBracket) || at(Tok::LParen)) {
      const Token open = advance();
      const Tok close = open.kind == Tok::LBracket ? Tok::RBracket : Tok::RParen;
      lv.paren = open.kind == Tok::LParen;
      if (accept(close)) {
        lv.kind = LValue::Kind::WholeList;
      } else if (at(Tok::LBrace)) {
        const Token lb = advance();
        lv.indices = parse_items_until(Tok::RBrace, lb);
        expect_closing(close, open);
        lv.kind = LValue::Kind::SubList;
      } else {
        lv.index = parse_expr();
        expect_closing(close, open);
        lv.kind = LValue::Kind::Element;
        if (at(Tok::Dot)) {
          if (!lv.name.ident.valid() || !lv.name.suffixes.empty()) fail_expected("an assignment operator");
          lv.kind = LValue::Kind::Option;
          lv.option = parse_option_after(first, lv.index);
          lv.index = ExprId{};
        }
      }
    }
  }
  lv.range = since(first);
  if (at(Tok::PlusPlus) || at(Tok::MinusMinus)) {
    const bool inc = advance().kind == Tok::PlusPlus;
    expect_semicolon();
    return add(first, IncDecStmt{std::move(lv), inc});
  }
  if (!is_affop(kind())) {
    const Token t = peek();
    if (lv.kind == LValue::Kind::Var && lv.name.suffixes.empty() && lv.name.ident.valid() &&
        (t.kind == Tok::String || t.kind == Tok::Number || t.kind == Tok::Semicolon || t.kind == Tok::Ident)) {
      auto h = diags_.report(first.range, Diag::UnknownCommand, clip(text(first)));
      if (const std::string_view near = closest_statement_word(text(first)); !near.empty())
        h.note(first.range, fmt::format("did you mean '{}'?", near));
      throw SyntaxError{};
    }
    fail_expected("'=' or another assignment operator");
  }
  const AffOp op = affop_of(advance().kind);
  AssignStmt node;
  node.target = std::move(lv);
  node.op = op;
  node.value = parse_list_value();
  expect_semicolon();
  return add(first, std::move(node));
}

// print := ("Printf" | "Warning" | "Error") "(" expr { "," item } ")" [ (">" | ">>") expr ] ";"
StmtId Parser::parse_print() {
  const Token kw = advance();
  PrintStmt node;
  node.kind = kw.kind == Tok::Printf    ? PrintKind::Printf
              : kw.kind == Tok::Warning ? PrintKind::Warning
                                        : PrintKind::Error;
  const Token open = expect(Tok::LParen, fmt::format("'(' after '{}'", text(kw)));
  node.format = parse_expr();
  while (accept(Tok::Comma)) node.args.push_back(parse_item());
  expect_closing(Tok::RParen, open);
  if (at(Tok::Greater) || at(Tok::ShiftRight)) {
    node.redirect = advance().kind == Tok::Greater ? Redirect::Write : Redirect::Append;
    node.file = parse_expr();
  }
  expect_semicolon();
  return add(kw, std::move(node));
}

// define_constant := "DefineConstant" "[" { dc_entry [ "," ] } "]" ";"
// dc_entry := name [ "=" ( expr | "{" expr { "," onelab_attr } "}" ) ]
// onelab_attr := word [ expr | "{" [ items ] "}" ]
StmtId Parser::parse_define_constant() {
  const Token kw = advance();
  const Token open = expect(Tok::LBracket, "'[' after 'DefineConstant'");
  DefineConstantStmt node;
  while (!at(Tok::RBracket)) {
    if (at(Tok::Eof)) expect_closing(Tok::RBracket, open);
    const Token first = peek();
    DefineEntry e;
    e.name = parse_name();
    if (accept(Tok::Assign)) {
      if (at(Tok::LBrace)) {
        const Token lb = advance();
        e.braced = true;
        e.value = parse_item();
        while (accept(Tok::Comma)) {
          if (at(Tok::RBrace)) break;
          const Token key = expect_member_word("a parameter attribute such as 'Name' or 'Min'");
          e.attrs.push_back(parse_onelab_attr_after(key, Tok::RBrace));
        }
        expect_closing(Tok::RBrace, lb);
      } else {
        e.value = parse_item();
      }
    }
    e.range = since(first);
    node.entries.push_back(std::move(e));
    accept(Tok::Comma);
  }
  advance();  // ']'
  expect_semicolon();
  return add(kw, std::move(node));
}

// onelab_attr := word [ expr | onelab_list ]
// onelab_list := "{" [ item [ "=" expr ] { "," item [ "=" expr ] } ] "}"   (Choices{0="None", 1="A"})
OnelabAttr Parser::parse_onelab_attr_after(const Token& key, Tok closer) {
  OnelabAttr a;
  a.key = ast_.intern(text(key));
  if (at(Tok::LBrace)) {
    const Token open = advance();
    ListExpr choices;
    while (!accept(Tok::RBrace)) {
      choices.items.push_back(parse_item());
      if (accept(Tok::Assign)) parse_expr();  // the label of a choice (display only)
      if (!accept(Tok::Comma) && !at(Tok::RBrace)) expect_closing(Tok::RBrace, open);
    }
    a.value = add_expr(open, std::move(choices));
  } else if (!at(Tok::Comma) && !at(closer)) {
    a.value = parse_expr();
  }
  a.range = since(key);
  return a;
}

// delete := "Delete" shape_block [ ";" ] | "Recursive" "Delete" shape_block [ ";" ]
//         | "Delete" ("Field" | "Coastline") "[" expr "]" ";"
//         | "Delete" ("Variables" | "Model" | "Physicals" | "Meshes" | "All" | "Options") ";"
//         | "Delete" name ";"
StmtId Parser::parse_delete() {
  if (at(Tok::Recursive) && (at(Tok::Hide, 1) || at(Tok::Show, 1))) return parse_visibility();
  const Token kw = advance();
  if (kw.kind == Tok::Recursive) {
    expect(Tok::Delete, "'Delete' after 'Recursive'");
    DeleteShapesStmt node{true, parse_shape_block(kw)};
    accept(Tok::Semicolon);
    return add(kw, std::move(node));
  }
  if (at(Tok::LBrace)) {
    DeleteShapesStmt node{false, parse_shape_block(kw)};
    accept(Tok::Semicolon);
    return add(kw, std::move(node));
  }
  if (at(Tok::Field) || at(Tok::Coastline)) {
    const bool coast = advance().kind == Tok::Coastline;
    const Token open = expect(Tok::LBracket);
    const ExprId id = parse_expr();
    expect_closing(Tok::RBracket, open);
    expect_semicolon();
    return coast ? add(kw, DeleteCoastlineStmt{id}) : add(kw, DeleteFieldStmt{id});
  }
  DeleteStmt node;
  if (at(Tok::Ident) && at(Tok::Semicolon, 1)) {
    const std::string_view w = text(peek());
    static constexpr std::pair<std::string_view, DeleteWhat> kWhat[] = {
        {"Variables", DeleteWhat::Variables}, {"Model", DeleteWhat::Model}, {"Physicals", DeleteWhat::Physicals},
        {"Meshes", DeleteWhat::Meshes},       {"All", DeleteWhat::All},     {"Options", DeleteWhat::Options}};
    for (const auto& [word, what] : kWhat)
      if (w == word) node.what = what;
  }
  if (node.what == DeleteWhat::Variable) node.name = parse_name();
  else advance();
  expect_semicolon();
  return add(kw, std::move(node));
}

// field_stmt := ("Field" | "Coastline") "[" expr "]" ( "=" word ";"
//               | "." word ( "=" ( "{" [ items ] "}" | expr ) ";" | ";" ) )
StmtId Parser::parse_field_statement() {
  const Token kw = advance();
  const bool coast = kw.kind == Tok::Coastline;
  const Token open = expect(Tok::LBracket, fmt::format("'[' after '{}'", text(kw)));
  const ExprId id = parse_expr();
  expect_closing(Tok::RBracket, open);
  if (accept(Tok::Assign)) {
    const Token type = expect_member_word(coast ? "a coastline kind" : "a field type");
    expect_semicolon();
    const StrId word = ast_.intern(text(type));
    return coast ? add(kw, CoastlineNewStmt{id, word, type.range}) : add(kw, FieldNewStmt{id, word, type.range});
  }
  expect(Tok::Dot, "'=' or '.' after ']'");
  const Token opt = expect_member_word(coast ? "a coastline option" : "a field option");
  const StrId member = ast_.intern(text(opt));
  if (accept(Tok::Semicolon))
    return coast ? add(kw, CoastlineActionStmt{id, member, opt.range})
                 : add(kw, FieldActionStmt{id, member, opt.range});
  expect(Tok::Assign, "'=' after the option name");
  const bool braced = at(Tok::LBrace);
  const ExprId value = braced ? parse_braced_list() : parse_expr();
  expect_semicolon();
  return coast ? add(kw, CoastlineOptionStmt{id, member, opt.range, value, braced})
               : add(kw, FieldOptionStmt{id, member, opt.range, value, braced});
}

// background_field := IDENT "Field" "=" list_value ";"    (IDENT: Background | BoundaryLayer)
StmtId Parser::parse_background_field() {
  const Token word = advance();
  const std::string_view w = text(word);
  if (w != "Background" && w != "BoundaryLayer") {
    auto h = diags_.report(word.range, Diag::UnknownCommand, clip(w));
    if (const std::string_view near = closest_statement_word(w); !near.empty())
      h.note(word.range, fmt::format("did you mean '{}'?", near));
    throw SyntaxError{};
  }
  advance();  // Field
  expect(Tok::Assign, fmt::format("'=' after '{} Field'", w));
  BackgroundFieldStmt node{ast_.intern(w), parse_list_value()};
  expect_semicolon();
  return add(word, node, since(word));
}

// plugin := "Plugin" "(" word ")" "." word [ "=" expr ] ";"
StmtId Parser::parse_plugin() {
  const Token kw = advance();
  const Token open = expect(Tok::LParen, "'(' after 'Plugin'");
  const Token name = expect_member_word("a plugin name");
  expect_closing(Tok::RParen, open);
  expect(Tok::Dot, "'.' after 'Plugin(...)'");
  const Token member = expect_member_word("a plugin option or action");
  PluginStmt node{ast_.intern(text(name)), ast_.intern(text(member)), member.range, ExprId{}};
  if (accept(Tok::Assign)) node.value = at(Tok::LBrace) ? parse_braced_list() : parse_expr();
  expect_semicolon();
  return add(kw, node);
}

// view := "View" expr "{" { IDENT "(" [ items ] ")" "{" [ items ] "}" ";" } "}" [ ";" ]
StmtId Parser::parse_view() {
  const Token kw = advance();
  ViewStmt node;
  node.name = parse_expr();
  const Token open = expect(Tok::LBrace, "'{' after the view name");
  while (!at(Tok::RBrace)) {
    if (at(Tok::Eof)) expect_closing(Tok::RBrace, open);
    const Token type = expect(Tok::Ident, "a view element such as 'SP' or 'T2'");
    ViewItem item;
    item.type = ast_.intern(text(type));
    const Token lp = expect(Tok::LParen);
    item.coords = parse_items_until(Tok::RParen, lp);
    const Token lb = expect(Tok::LBrace);
    item.values = parse_items_until(Tok::RBrace, lb);
    expect_semicolon();
    item.range = since(type);
    node.items.push_back(std::move(item));
  }
  advance();
  accept(Tok::Semicolon);
  return add(kw, std::move(node));
}

// color := "Color" (IDENT | "{" items "}") shape_block [ ";" ]
StmtId Parser::parse_color() {
  const Token kw = advance();
  ColorStmt node;
  if (at(Tok::LBrace)) {
    node.color = parse_braced_list();
  } else {
    const Token c = expect(Tok::Ident, "a color name or '{r, g, b}'");
    node.color = add_expr(c, VarExpr{Name{ast_.intern(text(c)), {}, ExprId{}, c.range}});
  }
  node.shapes = parse_shape_block(kw);
  accept(Tok::Semicolon);
  return add(kw, std::move(node));
}

// visibility := ["Recursive"] ("Hide" | "Show") (shape_block [ ";" ] | expr ";")
StmtId Parser::parse_visibility() {
  const Token kw = advance();
  VisibilityStmt node;
  node.recursive = kw.kind == Tok::Recursive;
  const Token verb = node.recursive ? advance() : kw;
  node.show = verb.kind == Tok::Show;
  if (at(Tok::LBrace)) {
    node.shapes = parse_shape_block(kw);
    accept(Tok::Semicolon);
  } else {
    node.pattern = parse_expr();   // "*", or an entity name pattern
    expect_semicolon();
  }
  return add(kw, std::move(node));
}

// set_factory := "SetFactory" "(" expr ")" ";"
StmtId Parser::parse_set_factory() {
  const Token kw = advance();
  const Token open = expect(Tok::LParen, "'(' after 'SetFactory'");
  const ExprId name = parse_expr();
  expect_closing(Tok::RParen, open);
  expect_semicolon();
  return add(kw, SetFactoryStmt{name});
}

}  // namespace sm::lang::detail
