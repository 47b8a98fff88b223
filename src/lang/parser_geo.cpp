// Geometry and mesh-constraint statements (docs/geometry.md; grammar/geo.ebnf geometry_stmt,
// physstmt, constraint): entity creation, loops, surfaces, spheres, physical
// groups, embedding, transfinite/recombine settings, shape blocks.
#include "lang/parser_impl.h"

namespace sm::lang::detail {

EntityKind Parser::entity_of(Tok k) {
  switch (k) {
    case Tok::Curve: return EntityKind::Curve;
    case Tok::Surface: return EntityKind::Surface;
    case Tok::Volume: return EntityKind::Volume;
    default: return EntityKind::Point;
  }
}

bool Parser::at_entity(std::size_t n) {
  const Tok k = kind(n);
  return k == Tok::Point || k == Tok::Curve || k == Tok::Surface || k == Tok::Volume;
}

// ent := "Point" | "Curve" | "Line" | "Surface" | "Volume"
EntityKind Parser::expect_entity(std::string_view what) {
  if (!at_entity()) fail_expected(what);
  return entity_of(advance().kind);
}

// "(" expr ")"  after a creation keyword
ExprId Parser::parse_tag_in_parens(const Token& kw) {
  const Token open = expect(Tok::LParen, fmt::format("'(' and a tag after '{}'", text(kw)));
  const ExprId tag = parse_expr();
  expect_closing(Tok::RParen, open);
  return tag;
}

// list_or_all := "{" ":" "}" | list_value
ExprId Parser::parse_entity_list(bool& all) {
  all = false;
  if (at(Tok::LBrace) && at(Tok::Colon, 1) && at(Tok::RBrace, 2)) {
    advance();
    advance();
    advance();
    all = true;
    return ExprId{};
  }
  return parse_list_value();
}

StmtId Parser::parse_geometry_statement() {
  const Token t = peek();
  switch (t.kind) {
    case Tok::Point:
      if (at(Tok::LBrace, 1)) return parse_embed(t, EntityKind::Point);
      return parse_point();
    case Tok::Curve:
      if (at(Tok::LBrace, 1)) return parse_embed(t, EntityKind::Curve);
      if (at(Tok::Ident, 1)) return parse_curve_loop_or_embed(t);
      return parse_curve(advance());
    case Tok::Circle: case Tok::Ellipse: case Tok::Spline: case Tok::BSpline: case Tok::Bezier: case Tok::Nurbs:
      return parse_curve(advance());
    case Tok::Surface:
      if (at(Tok::LBrace, 1)) return parse_embed(t, EntityKind::Surface);
      return parse_surface(advance());
    case Tok::Plane: {
      const Token kw = advance();
      expect(Tok::Surface, "'Surface' after 'Plane'");
      return parse_surface(kw);
    }
    case Tok::Volume:
      if (at(Tok::LBrace, 1)) return parse_embed(t, EntityKind::Volume);
      return parse_volume(advance());
    case Tok::Compound: return parse_compound();
    case Tok::Sphere: case Tok::PolarSphere: return parse_sphere();
    case Tok::Parametric: return parse_parametric();
    case Tok::Coordinates: return parse_coordinates();
    case Tok::Euclidean: return parse_euclidean();
    case Tok::Physical: return parse_physical();
    case Tok::Coherence: return parse_coherence();
    case Tok::Split: return parse_split();
    case Tok::SetMaxTag: return parse_set_max_tag();
    case Tok::MeshSize: case Tok::Characteristic: return parse_mesh_size();
    case Tok::Transfinite: return parse_transfinite();
    case Tok::Recombine: return parse_recombine();
    case Tok::MeshAlgorithm: return parse_entity_setting(SettingKind::MeshAlgorithm);
    case Tok::MeshSizeFromBoundary: return parse_entity_setting(SettingKind::MeshSizeFromBoundary);
    case Tok::Smoother: return parse_entity_setting(SettingKind::Smoother);
    case Tok::Periodic: return parse_periodic();
    case Tok::ReverseMesh: return parse_reverse_mesh();
    case Tok::Translate: case Tok::Rotate: case Tok::Symmetry: case Tok::Dilate: case Tok::Duplicata:
    case Tok::Boundary: case Tok::CombinedBoundary: case Tok::PointsOf: case Tok::Extrude:
      return parse_shape_statement();
    case Tok::BoundingBox: {
      const Token kw = advance();
      CommandStmt node{ast_.intern("BoundingBox"), kw.range, ExprId{}};
      if (at(Tok::LBrace)) node.arg = parse_braced_list();
      expect_semicolon();
      return add(kw, node);
    }
    default: break;
  }
  diags_.report(t.range, Diag::ExpectedStatement, describe(t));
  throw SyntaxError{};
}

// point_stmt := "Point" "(" expr ")" "=" ( "{" items "}" | "(" items ")" ) ";"
StmtId Parser::parse_point() {
  const Token kw = advance();
  PointStmt node;
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign, "'=' after 'Point(...)'");
  if (at(Tok::LParen)) {
    const Token open = advance();
    ExprList items = parse_items_until(Tok::RParen, open);
    node.coords = add_expr(open, ListExpr{std::move(items)});
  } else {
    node.coords = parse_list_value();
  }
  expect_semicolon();
  return add(kw, node);
}

// curve_stmt := ("Line" | "Curve" | "Spline" | "CatmullRom" | "BSpline" | "Bezier") "(" expr ")" "=" list_value ";"
//             | ("Circle" | "Ellipse") "(" expr ")" "=" list_value [ "Plane" "{" items "}" ] ";"
//             | "Nurbs" "(" expr ")" "=" list_value "Knots" list_value "Order" expr ";"
StmtId Parser::parse_curve(const Token& kw) {
  CurveStmt node;
  switch (kw.kind) {
    case Tok::Spline: node.kind = CurveKind::Spline; break;
    case Tok::BSpline: node.kind = CurveKind::BSpline; break;
    case Tok::Bezier: node.kind = CurveKind::Bezier; break;
    case Tok::Nurbs: node.kind = CurveKind::Nurbs; break;
    case Tok::Circle: node.kind = CurveKind::Circle; break;
    case Tok::Ellipse: node.kind = CurveKind::Ellipse; break;
    default: node.kind = CurveKind::Line; break;
  }
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign, fmt::format("'=' after '{}(...)'", text(kw)));
  node.points = parse_list_value();
  if ((node.kind == CurveKind::Circle || node.kind == CurveKind::Ellipse) && accept(Tok::Plane))
    node.plane = parse_braced_list();
  if (node.kind == CurveKind::Nurbs) {
    expect(Tok::Knots, "'Knots' after the Nurbs control points");
    node.knots = parse_list_value();
    expect(Tok::Order, "'Order' after the Nurbs knots");
    node.order = parse_expr();
  }
  expect_semicolon();
  return add(kw, node);
}

// curve_loop := "Curve" IDENT "(" expr ")" "=" list_value ";"     (IDENT: Loop; not checked, as Gmsh)
// surface_loop := "Surface" IDENT "(" expr ")" "=" list_value ";"
StmtId Parser::parse_curve_loop_or_embed(const Token&) {
  const Token kw = advance();   // Curve / Line / Surface
  const Token word = advance();  // Loop
  const SourceRange keyword = since(kw);
  const ExprId tag = parse_tag_in_parens(word);
  expect(Tok::Assign, fmt::format("'=' after '{} {}(...)'", text(kw), text(word)));
  const ExprId list = parse_list_value();
  expect_semicolon();
  if (kw.kind == Tok::Surface) return add(kw, SurfaceLoopStmt{tag, list}, keyword);
  return add(kw, CurveLoopStmt{tag, list}, keyword);
}

// surface_stmt := "Plane" "Surface" "(" expr ")" "=" list_value ";"
//               | "Surface" "(" expr ")" "=" list_value [ "In" "Sphere" "{" expr "}" ] ";"
//               | "Surface" IDENT "(" expr ")" "=" list_value ";"      (surface loop)
StmtId Parser::parse_surface(const Token& kw) {
  if (kw.kind == Tok::Surface && at(Tok::Ident)) {
    const Token word = advance();
    const ExprId tag = parse_tag_in_parens(word);
    expect(Tok::Assign, "'=' after 'Surface Loop(...)'");
    const ExprId list = parse_list_value();
    expect_semicolon();
    return add(kw, SurfaceLoopStmt{tag, list}, SourceRange{kw.range.file, kw.range.begin, word.range.end});
  }
  SurfaceStmt node;
  node.kind = kw.kind == Tok::Plane ? SurfaceKind::Plane : SurfaceKind::Filling;
  const SourceRange keyword = since(kw);
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign, "'=' after 'Surface(...)'");
  node.loops = parse_list_value();
  if (node.kind == SurfaceKind::Filling && accept(Tok::In)) {
    expect(Tok::Sphere, "'Sphere' after 'In'");
    const Token open = expect(Tok::LBrace, "'{' after 'In Sphere'");
    node.in_sphere = parse_expr();
    expect_closing(Tok::RBrace, open);
  }
  expect_semicolon();
  return add(kw, node, keyword);
}

// volume_stmt := "Volume" "(" expr ")" "=" list_value ";"
StmtId Parser::parse_volume(const Token& kw) {
  VolumeStmt node;
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign, "'=' after 'Volume(...)'");
  node.loops = parse_list_value();
  expect_semicolon();
  return add(kw, node);
}

// compound := "Compound" ("Spline" | "BSpline") "(" expr ")" "=" list_value "Using" expr ";"
//           | "Compound" ent list_value ";"
StmtId Parser::parse_compound() {
  const Token kw = advance();
  if (at(Tok::Spline) || at(Tok::BSpline)) {
    const Token which = advance();
    CurveStmt node;
    node.kind = which.kind == Tok::Spline ? CurveKind::CompoundSpline : CurveKind::CompoundBSpline;
    node.tag = parse_tag_in_parens(which);
    expect(Tok::Assign);
    node.points = parse_list_value();
    expect(Tok::Using, "'Using' and a number of intervals");
    node.using_n = parse_expr();
    expect_semicolon();
    return add(kw, node, since(kw));
  }
  const EntityKind ent = expect_entity("'Curve', 'Surface', 'Spline' or 'BSpline' after 'Compound'");
  const SourceRange keyword = since(kw);
  const ExprId tags = parse_list_value();
  expect_semicolon();
  return add(kw, CompoundStmt{ent, tags}, keyword);
}

// sphere_stmt := ("Sphere" | "PolarSphere") "(" expr ")" "=" list_value ";"
StmtId Parser::parse_sphere() {
  const Token kw = advance();
  SphereStmt node;
  node.polar = kw.kind == Tok::PolarSphere;
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign, fmt::format("'=' after '{}(...)'", text(kw)));
  node.points = parse_list_value();
  expect_semicolon();
  return add(kw, node);
}

// parametric := "Parametric" "Surface" "(" expr ")" "=" expr expr expr ";"
StmtId Parser::parse_parametric() {
  const Token kw = advance();
  expect(Tok::Surface, "'Surface' after 'Parametric'");
  ParametricSurfaceStmt node;
  node.tag = parse_tag_in_parens(kw);
  expect(Tok::Assign);
  node.fx = parse_expr();
  node.fy = parse_expr();
  node.fz = parse_expr();
  expect_semicolon();
  return add(kw, node, since(kw));
}

// coordinates := "Coordinates" "Surface" expr ";"
StmtId Parser::parse_coordinates() {
  const Token kw = advance();
  expect(Tok::Surface, "'Surface' after 'Coordinates'");
  const ExprId g = parse_expr();
  expect_semicolon();
  return add(kw, CoordinatesSurfaceStmt{g});
}

// euclidean := ("Euclidean" | "Euclidian") "Coordinates" ";"
StmtId Parser::parse_euclidean() {
  const Token kw = advance();
  expect(Tok::Coordinates, fmt::format("'Coordinates' after '{}'", text(kw)));
  expect_semicolon();
  return add(kw, EuclideanCoordinatesStmt{});
}

// physical := "Physical" ent "(" expr [ "," expr ] ")" ("=" | "+=" | "-=") list_value ";"
// A single string argument (literal or string function) is the name; the
// evaluator also accepts a string value given as `tag`.
StmtId Parser::parse_physical() {
  const Token kw = advance();
  PhysicalStmt node;
  node.ent = expect_entity("an entity kind after 'Physical'");
  const SourceRange keyword = since(kw);
  const Token open = expect(Tok::LParen, "'(' and a tag or name");
  const bool string_first = starts_string_expr();
  const ExprId first = parse_expr();
  if (accept(Tok::Comma)) {
    node.name = first;
    node.tag = parse_expr();
  } else if (string_first) {
    node.name = first;
  } else {
    node.tag = first;
  }
  expect_closing(Tok::RParen, open);
  if (!at(Tok::Assign) && !at(Tok::PlusAssign) && !at(Tok::MinusAssign)) fail_expected("'=', '+=' or '-='");
  node.op = affop_of(advance().kind);
  node.entities = parse_list_value();
  expect_semicolon();
  return add(kw, node, keyword);
}

// coherence := "Coherence" [ "Mesh" | "Geometry" ] ";" | "Coherence" "Point" "{" items "}" ";"
StmtId Parser::parse_coherence() {
  const Token kw = advance();
  CoherenceStmt node;
  if (at(Tok::Point)) {
    advance();
    node.what = CoherenceKind::Points;
    node.points = parse_braced_list();
  } else if (at_word("Mesh")) {
    advance();
    node.what = CoherenceKind::Mesh;
  } else if (at_word("Geometry")) {
    advance();
  }
  expect_semicolon();
  return add(kw, node);
}

// split := "Split" "Curve" "{" expr "}" "Point" "{" items "}" ";"
StmtId Parser::parse_split() {
  const Token kw = advance();
  expect(Tok::Curve, "'Curve' after 'Split'");
  SplitCurveStmt node;
  const Token open = expect(Tok::LBrace);
  node.curve = parse_expr();
  expect_closing(Tok::RBrace, open);
  expect(Tok::Point, "'Point{...}' after the curve");
  node.points = parse_braced_list();
  expect_semicolon();
  return add(kw, node);
}

// set_max_tag := "SetMaxTag" ent "(" expr ")" ";"
StmtId Parser::parse_set_max_tag() {
  const Token kw = advance();
  SetMaxTagStmt node;
  node.ent = expect_entity("an entity kind after 'SetMaxTag'");
  node.tag = parse_tag_in_parens(kw);
  expect_semicolon();
  return add(kw, node);
}

// embed := ent "{" items "}" "In" ent "{" expr "}" ";"
StmtId Parser::parse_embed(const Token&, EntityKind ent) {
  const Token kw = advance();
  EmbedStmt node;
  node.ent = ent;
  node.tags = parse_braced_list();
  expect(Tok::In, "'In' (embedding: 'Point{...} In Surface{...};')");
  node.target = expect_entity("an entity kind after 'In'");
  const Token open = expect(Tok::LBrace);
  node.target_tag = parse_expr();
  expect_closing(Tok::RBrace, open);
  expect_semicolon();
  return add(kw, node);
}

// mesh_size := ("MeshSize" | "Characteristic" "Length") list_or_all "=" expr ";"
StmtId Parser::parse_mesh_size() {
  const Token kw = advance();
  if (kw.kind == Tok::Characteristic) expect(Tok::Length, "'Length' after 'Characteristic'");
  const SourceRange keyword = since(kw);
  MeshSizeStmt node;
  node.points = parse_entity_list(node.all);
  expect(Tok::Assign, "'=' and a size");
  node.size = parse_expr();
  expect_semicolon();
  return add(kw, node, keyword);
}

// transfinite := "Transfinite" "Curve" list_or_all "=" expr [ "Using" IDENT expr ] ";"
//              | "Transfinite" "Surface" list_or_all [ "=" list_value ] [ IDENT ] ";"
StmtId Parser::parse_transfinite() {
  const Token kw = advance();
  if (at(Tok::Curve)) {
    advance();
    const SourceRange keyword = since(kw);
    TransfiniteCurveStmt node;
    node.curves = parse_entity_list(node.all);
    expect(Tok::Assign, "'=' and a number of nodes");
    node.nodes = parse_expr();
    if (accept(Tok::Using)) {
      node.distribution = ast_.intern(text(expect(Tok::Ident, "'Progression', 'Bump' or 'Beta'")));
      node.coef = parse_expr();
    }
    expect_semicolon();
    return add(kw, node, keyword);
  }
  expect(Tok::Surface, "'Curve' or 'Surface' after 'Transfinite'");
  const SourceRange keyword = since(kw);
  TransfiniteSurfaceStmt node;
  node.surfaces = parse_entity_list(node.all);
  if (accept(Tok::Assign)) node.corners = parse_list_value();
  if (at(Tok::Ident)) node.arrangement = ast_.intern(text(advance()));
  expect_semicolon();
  return add(kw, node, keyword);
}

// recombine := "Recombine" ent list_or_all [ "=" expr ] ";"
StmtId Parser::parse_recombine() {
  const Token kw = advance();
  RecombineStmt node;
  node.ent = expect_entity("'Surface' after 'Recombine'");
  const SourceRange keyword = since(kw);
  node.tags = parse_entity_list(node.all);
  if (accept(Tok::Assign)) node.angle = parse_expr();
  expect_semicolon();
  return add(kw, node, keyword);
}

// entity_setting := ("MeshAlgorithm" | "MeshSizeFromBoundary" | "Smoother") ent list_or_all "=" expr ";"
StmtId Parser::parse_entity_setting(SettingKind kind) {
  const Token kw = advance();
  EntitySettingStmt node;
  node.kind = kind;
  node.ent = expect_entity(fmt::format("an entity kind after '{}'", text(kw)));
  const SourceRange keyword = since(kw);
  node.tags = parse_entity_list(node.all);
  expect(Tok::Assign);
  node.value = parse_expr();
  expect_semicolon();
  return add(kw, node, keyword);
}

// periodic := "Periodic" ent list "=" list [ ( "Translate" | "Rotate" | "Affine" ) "{" items "}" ] ";"
//           | "Periodic" "Surface" expr list "=" expr list ";"
// (Gmsh 4.8.4's Parser/Gmsh.y: the second form pairs a slave surface's curves with a master's)
StmtId Parser::parse_periodic() {
  const Token kw = advance();
  PeriodicStmt node;
  node.ent = expect_entity("'Curve' or 'Surface' after 'Periodic'");
  const SourceRange keyword = since(kw);
  if (node.ent == EntityKind::Surface && !at(Tok::LBrace)) {
    node.slave_surface = parse_expr();
    node.slaves = parse_braced_list();
    expect(Tok::Assign);
    node.master_surface = parse_expr();
    node.masters = parse_braced_list();
    expect_semicolon();
    return add(kw, node, keyword);
  }
  node.slaves = parse_braced_list();
  expect(Tok::Assign);
  node.masters = parse_braced_list();
  if (at(Tok::Translate) || at(Tok::Rotate) || at_word("Affine")) {
    const Token t = advance();
    node.transform = t.kind == Tok::Translate ? PeriodicTransform::Translate
                     : t.kind == Tok::Rotate  ? PeriodicTransform::Rotate
                                              : PeriodicTransform::Affine;
    const Token open = expect(Tok::LBrace);
    node.transform_args = parse_items_until(Tok::RBrace, open);
  }
  expect_semicolon();
  return add(kw, node, keyword);
}

// reverse_mesh := ("ReverseMesh" | "Reverse") ent list_or_all ";"
StmtId Parser::parse_reverse_mesh() {
  const Token kw = advance();
  ReverseMeshStmt node;
  node.ent = expect_entity(fmt::format("'Curve' or 'Surface' after '{}'", text(kw)));
  const SourceRange keyword = since(kw);
  node.tags = parse_entity_list(node.all);
  expect_semicolon();
  return add(kw, node, keyword);
}

// shape_stmt := (transform | boundary) [ ";" ]      (Gmsh does not require the ';')
StmtId Parser::parse_shape_statement() {
  const Token first = peek();
  const ExprId e = parse_primary();
  accept(Tok::Semicolon);
  return add(first, ShapeExprStmt{e});
}

// shape_block := "{" { shape_entry } "}"
// shape_entry := ["Physical"] ent "{" (items | ":") "}" ";" | creation_stmt
ShapeBlock Parser::parse_shape_block(const Token& owner) {
  const Token open = expect(Tok::LBrace, fmt::format("'{{' after '{}'", text(owner)));
  DepthGuard guard(*this);
  ShapeBlock block;
  while (!at(Tok::RBrace)) {
    if (at(Tok::Eof)) expect_closing(Tok::RBrace, open);
    block.push_back(parse_shape_entry());
  }
  advance();  // '}'
  return block;
}

ShapeItem Parser::parse_shape_entry() {
  const Token first = peek();
  ShapeItem item;
  if ((at(Tok::Physical) && at_entity(1) && at(Tok::LBrace, 2)) || (at_entity() && at(Tok::LBrace, 1))) {
    item.kind = ShapeItem::Kind::Entities;
    item.physical = accept(Tok::Physical);
    item.ent = entity_of(advance().kind);
    const Token lb = advance();
    if (at(Tok::Colon) && at(Tok::RBrace, 1)) {
      advance();
      advance();
      item.all = true;
    } else {
      item.tags = parse_items_until(Tok::RBrace, lb);
    }
    expect_semicolon();
  } else if (at(Tok::Translate) || at(Tok::Rotate) || at(Tok::Symmetry) || at(Tok::Dilate) || at(Tok::Duplicata) ||
             at(Tok::Extrude)) {
    item.kind = ShapeItem::Kind::Nested;
    item.nested = at(Tok::Extrude) ? parse_extrude() : parse_transform();
    accept(Tok::Semicolon);
  } else if (is_keyword(kind()) && !at(Tok::Physical)) {
    item.kind = ShapeItem::Kind::Create;
    item.create = parse_geometry_statement();
  } else {
    fail_expected("a shape such as 'Point{...};' or '}'");
  }
  item.range = since(first);
  return item;
}

// transform_body := "{" ( transform [ ";" ] | { shape_entry } ) "}"
ShapeBlock Parser::parse_transform_body(const Token& owner) { return parse_shape_block(owner); }

}  // namespace sm::lang::detail
