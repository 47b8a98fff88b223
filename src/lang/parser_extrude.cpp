// `Extrude {...} {shapes and mesh parameters}` (grammar/geo.ebnf extrude): the parameters of
// the first braces as written (the evaluator tells translation, rotation and twist apart by
// their count and shape), then the shapes with Gmsh's extrusion mesh parameters among them.
#include "lang/parser_impl.h"

namespace sm::lang::detail {

// extrude := "Extrude" "{" items "}" "{" { shape_entry | extrude_param } "}"
ExprId Parser::parse_extrude() {
  const Token kw = advance();
  DepthGuard guard(*this);
  TransformExpr t;
  t.kind = TransformKind::Extrude;
  const Token open = expect(Tok::LBrace, "'{' after 'Extrude'");
  t.params = parse_items_until(Tok::RBrace, open);
  const Token body = expect(Tok::LBrace, "'{' and the shapes to extrude");
  while (!at(Tok::RBrace)) {
    if (at(Tok::Eof)) expect_closing(Tok::RBrace, body);
    if (at_word("Layers")) {
      const Token w = advance();
      const Token lb = expect(Tok::LBrace, "'{' after 'Layers'");
      t.extrude.layers = parse_items_until(Tok::RBrace, lb);
      t.extrude.layers_range = since(w);
      expect_semicolon();
    } else if (at(Tok::Recombine)) {
      const Token w = advance();
      t.extrude.has_recombine = true;
      t.extrude.recombine = at(Tok::Semicolon) ? add_expr(w, NumberExpr{1}) : parse_expr();
      expect_semicolon();
    } else if (at_word("ScaleLast") || at_word("QuadTriNoNewVerts") || at_word("QuadTriAddVerts")) {
      // Gmsh's 3D-only options (the last layer scaled, pyramids for quad-to-triangle
      // faces of volumes): they change no 2D element, so -2 meshes alike without them.
      advance();
      if (at_word("RecombLaterals")) advance();
      expect_semicolon();
    } else {
      t.shapes.push_back(parse_shape_entry());
    }
  }
  advance();  // '}'
  return add_expr(kw, std::move(t));
}

}  // namespace sm::lang::detail
