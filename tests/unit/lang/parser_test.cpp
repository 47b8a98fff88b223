// Parser: AST shapes (via dump) for every construct, precedence, Gmsh tutorials.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "lang_test_util.h"

using namespace sm::lang;
using sm::lang::testing::ast_of;

TEST_CASE("parser: precedence follows Gmsh (^ over unary minus, | & over *)") {
  CHECK(ast_of("x = -2^2;") == "(assign = x (- (^ 2 2)))");
  CHECK(ast_of("x = 2^3^2;") == "(assign = x (^ 2 (^ 3 2)))");
  CHECK(ast_of("x = 2^-1;") == "(assign = x (^ 2 (- 1)))");
  CHECK(ast_of("x = 6|1*2;") == "(assign = x (* (| 6 1) 2))");
  CHECK(ast_of("x = a+b*c-d;") == "(assign = x (- (+ (var a) (* (var b) (var c))) (var d)))");
  CHECK(ast_of("x = -a*b;") == "(assign = x (* (- (var a)) (var b)))");
  CHECK(ast_of("x = !a == b;") == "(assign = x (== (! (var a)) (var b)))");
  CHECK(ast_of("x = a || b && c == d < e + f;") ==
        "(assign = x (|| (var a) (&& (var b) (== (var c) (< (var d) (+ (var e) (var f)))))))");
  CHECK(ast_of("x = 7 % 3 / 2;") == "(assign = x (/ (% 7 3) 2))");
  CHECK(ast_of("x = 1 << 2 >> 1;") == "(assign = x (>> (<< 1 2) 1))");
  CHECK(ast_of("x = c ? a : b ? 1 : 2;") == "(assign = x (? (var c) (var a) (? (var b) 1 2)))");
}

TEST_CASE("parser: names, lists, ranges, indexing, calls, options") {
  CHECK(ast_of("x~{i}~{j+1} = 3;") == "(assign = (name x ~(var i) ~(+ (var j) 1)) 3)");
  CHECK(ast_of("L[] = {1:10:3, 20, a[]};") == "(assign = (whole L) (list (range 1 10 3) 20 (whole a)))");
  CHECK(ast_of("L() += 5;") == "(assign += (whole L) 5)");
  CHECK(ast_of("L[2] *= L(1);") == "(assign *= (index L 2) (index L 1))");
  CHECK(ast_of("L[{0:2}] = {7,8,9};") == "(assign = (slice L (range 0 2)) (list 7 8 9))");
  CHECK(ast_of("n = #L[] + #L();") == "(assign = n (+ (# (whole L)) (# (whole L))))");
  CHECK(ast_of("b = a++;") == "(assign = b (post++ (var a)))");
  CHECK(ast_of("a--;") == "(-- a)");
  CHECK(ast_of("y = Sqrt(2) + Atan2[1, 2];") == "(assign = y (+ (call Sqrt 2) (call Atan2 1 2)))");
  CHECK(ast_of("s = StrCat(\"a\", Sprintf(\"%g\", x), Today);") ==
        "(assign = s (call StrCat \"a\" (call Sprintf \"%g\" (var x)) (const Today)))");
  CHECK(ast_of("e = Exists(x~{2});") == "(assign = e (call Exists (var (name x ~2))))");
  CHECK(ast_of("S2N[\"v\"] = 1;") == "(assign = (s2n \"v\") 1)");
  CHECK(ast_of("Mesh.Algorithm = 6;") == "(assign = (option Mesh.Algorithm) 6)");
  CHECK(ast_of("View[0].Name = \"a\";") == "(assign = (option View[0].Name) \"a\")");
  CHECK(ast_of("General.Color.Text = Red;") == "(assign = (option General.Color.Text) (var Red))");
  CHECK(ast_of("Mesh.Smoothing++;") == "(++ (option Mesh.Smoothing))");
  CHECK(ast_of("x = Mesh.Algorithm * 2;") == "(assign = x (* (option Mesh.Algorithm) 2))");
  CHECK(ast_of("x = Pi + newp;") == "(assign = x (+ (const Pi) (const newp)))");
  CHECK(ast_of("l = -{1, 2} * 3;") == "(assign = l (* (- (list 1 2)) 3))");
  CHECK(ast_of("x = 1:3;") == "(assign = x (range 1 3))");
}

TEST_CASE("parser: control flow blocks") {
  CHECK(ast_of("For i In {1:4} s += i; EndFor") == "(for i 1 4 _ ((assign += s (var i))))");
  CHECK(ast_of("For (1:3:2) x = 1; EndFor") == "(for _ 1 3 2 ((assign = x 1)))");
  CHECK(ast_of("If (a) x=1; ElseIf (b) x=2; Else x=3; EndIf") ==
        "(if ((var a) ((assign = x 1))) ((var b) ((assign = x 2))) (else ((assign = x 3))))");
  CHECK(ast_of("Macro Foo x = 1; If (x) Return; EndIf Return") ==
        "(macro Foo ((assign = x 1) (if ((var x) ((return))))))");
  CHECK(ast_of("Function \"Bar\" Return") == "(macro Bar ())");
  CHECK(ast_of("Call Foo;") == "(call-macro Foo)");
  CHECK(ast_of("Call StrCat(\"F\", \"oo\");") == "(call-macro (call StrCat \"F\" \"oo\"))");
  CHECK(ast_of("Exit;") == "(exit)");
  CHECK(ast_of("Exit 3;") == "(exit 3)");
  CHECK(ast_of("Abort;") == "(abort)");
  CHECK(ast_of("Assert(x > 1, \"x is %g\", x);") == "(assert (> (var x) 1) \"x is %g\" (var x))");
  CHECK(ast_of("Printf(\"%g %g\", a, 1:3) >> \"f.txt\";") == "(Printf \"%g %g\" (var a) (range 1 3) >> \"f.txt\")");
  CHECK(ast_of("Error(\"bad\");") == "(Error \"bad\")");
  CHECK(ast_of("DefineConstant[ a = 1, b = {2, Name \"B\", Min 0, Choices{0,1}, ReadOnly} c s = \"t\" ];") ==
        "(define-constant (a 1) (b 2 (Name \"B\") (Min 0) (Choices (list 0 1)) (ReadOnly)) (c _) (s \"t\"))");
  CHECK(ast_of("Delete x;") == "(delete Variable x)");
  CHECK(ast_of("Delete Physicals;") == "(delete Physicals)");
  CHECK(ast_of("Include \"other.geo\";") == "(include \"other.geo\")");
  CHECK(ast_of("Save StrCat(\"a\", \".msh\");") == "(command Save (call StrCat \"a\" \".msh\"))");
  CHECK(ast_of("Mesh 2;") == "(command Mesh 2)");
  CHECK(ast_of("RefineMesh;") == "(command RefineMesh)");
  CHECK(ast_of("SetNumber(\"a\", 2);") == "(command SetNumber (list \"a\" 2))");
  CHECK(ast_of("SetFactory(\"Built-in\");") == "(set-factory \"Built-in\")");
}

TEST_CASE("parser: geometry statements") {
  CHECK(ast_of("Point(1) = {0, 0, 0, lc};") == "(point 1 (list 0 0 0 (var lc)))");
  CHECK(ast_of("Line(1) = {1, 2};") == "(Line 1 (list 1 2))");
  CHECK(ast_of("CatmullRom(3) = {1:5};") == "(Spline 3 (list (range 1 5)))");
  CHECK(ast_of("BSpline(newl) = {IP + 1 : IP + 9, IP + 1};") ==
        "(BSpline (const newl) (list (range (+ (var IP) 1) (+ (var IP) 9)) (+ (var IP) 1)))");
  CHECK(ast_of("Circle(3) = {1, 2, 3} Plane{0, 0, 1};") == "(Circle 3 (list 1 2 3) :plane (list 0 0 1))");
  CHECK(ast_of("Line Loop(1) = {1, -2};") == "(curve-loop 1 (list 1 (- 2)))");
  CHECK(ast_of("Plane Surface(2) = 1;") == "(plane-surface 2 1)");
  CHECK(ast_of("Surface(3) = {1} In Sphere{4};") == "(surface 3 (list 1) :in-sphere 4)");
  CHECK(ast_of("Surface Loop(1) = {1, 2};") == "(surface-loop 1 (list 1 2))");
  CHECK(ast_of("PolarSphere(1) = {1, 2};") == "(polar-sphere 1 (list 1 2))");
  CHECK(ast_of("Physical Surface(\"sea\", 7) += {1};") == "(physical Surface 7 \"sea\" += (list 1))");
  CHECK(ast_of("Physical Line(5) = 3;") == "(physical Curve 5 _ = 3)");
  CHECK(ast_of("Point{5} In Surface{1};") == "(embed Point (list 5) Surface 1)");
  CHECK(ast_of("Delete { Surface{1}; Curve{4}; }") == "(delete (shapes (Surface 1) (Curve 4)))");
  CHECK(ast_of("Recursive Delete { Physical Surface{1}; }") == "(recursive-delete (shapes (PhysicalSurface 1)))");
  CHECK(ast_of("t[] = Translate{1, 0, 0}{ Duplicata{ Point{1}; } };") ==
        "(assign = (whole t) (Translate (params 1 0 0) (shapes (Duplicata (params) (shapes (Point 1))))))");
  CHECK(ast_of("Rotate {{0,0,1}, {0,0,0}, Pi/2} { Curve{1:4}; }") ==
        "(shape-stmt (Rotate (params (list 0 0 1) (list 0 0 0) (/ (const Pi) 2)) (shapes (Curve (range 1 4)))))");
  CHECK(ast_of("b[] = Boundary{ Surface{1}; };") == "(assign = (whole b) (Boundary (shapes (Surface 1))))");
  CHECK(ast_of("c[] = Curve{:};") == "(assign = (whole c) (query Curve :))");
  CHECK(ast_of("p = Point{3};") == "(assign = p (query Point 3))");
  CHECK(ast_of("g[] = Physical Surface{2};") == "(assign = (whole g) (query PhysicalSurface 2))");
  CHECK(ast_of("q[] = Point In BoundingBox{0,0,0,1,1,1};") == "(assign = (whole q) (in-box Point 0 0 0 1 1 1))");
  CHECK(ast_of("Transfinite Curve{1, -3} = 30 Using Progression 1.2;") ==
        "(transfinite-curve (list 1 (- 3)) 30 Progression 1.2)");
  CHECK(ast_of("Transfinite Surface{1} = {1,2,3,4} Alternate;") ==
        "(transfinite-surface (list 1) (list 1 2 3 4) Alternate)");
  CHECK(ast_of("Recombine Surface{:};") == "(recombine Surface :)");
  CHECK(ast_of("MeshSize{1, 2} = 0.1;") == "(mesh-size (list 1 2) 0.1)");
  CHECK(ast_of("Characteristic Length{:} = 0.1;") == "(mesh-size : 0.1)");
  CHECK(ast_of("Coherence;") == "(coherence Geometry)");
  CHECK(ast_of("Coherence Mesh;") == "(coherence Mesh)");
  CHECK(ast_of("Split Curve{3} Point{7, 8};") == "(split-curve 3 (list 7 8))");
  CHECK(ast_of("Compound Spline(5) = {1, 2} Using 10;") == "(CompoundSpline 5 (list 1 2) :using 10)");
  CHECK(ast_of("Compound Curve{1, 2};") == "(compound Curve (list 1 2))");
  CHECK(ast_of("Periodic Curve{1} = {3} Translate{1, 0, 0};") ==
        "(periodic Curve (list 1) (list 3) (translate 1 0 0))");
  CHECK(ast_of("Euclidian Coordinates;") == "(euclidean-coordinates)");
  CHECK(ast_of("Coordinates Surface 1;") == "(coordinates-surface 1)");
  CHECK(ast_of("Parametric Surface(1) = \"u\" \"v\" \"0\";") == "(parametric-surface 1 \"u\" \"v\" \"0\")");
  CHECK(ast_of("Nurbs(1) = {1, 2, 3} Knots {0, 0, 1, 1} Order 2;") ==
        "(Nurbs 1 (list 1 2 3) :knots (list 0 0 1 1) :order 2)");
}

TEST_CASE("parser: fields, coastlines, plugins") {
  CHECK(ast_of("Field[1] = Distance;") == "(field-new 1 Distance)");
  CHECK(ast_of("Field[newf] = Min;") == "(field-new (const newf) Min)");
  CHECK(ast_of("Field[1].CurvesList = {1:4};") == "(field-option 1 CurvesList (list (range 1 4)))");
  CHECK(ast_of("Field[2].F = Sprintf(\"F4^3 + %g\", lc);") ==
        "(field-option 2 F (call Sprintf \"F4^3 + %g\" (var lc)))");
  CHECK(ast_of("Field[2].Run;") == "(field-action 2 Run)");
  CHECK(ast_of("Background Field = 7;") == "(Background-field 7)");
  CHECK(ast_of("Delete Field[3];") == "(delete-field 3)");
  CHECK(ast_of("Coastline[1] = GSHHS;") == "(coastline-new 1 GSHHS)");
  CHECK(ast_of("Coastline[1].Region = {-12, 3, 48, 62};") == "(coastline-option 1 Region (list (- 12) 3 48 62))");
  CHECK(ast_of("loops[] = Coastline{1};") == "(assign = (whole loops) (coastline 1))");
  CHECK(ast_of("Plugin(GSHHS).iField = 1;") == "(plugin GSHHS iField 1)");
  CHECK(ast_of("Plugin(GSHHS).Run;") == "(plugin GSHHS Run)");
}

TEST_CASE("parser: Field and Coastline statements are nodes of their own kind") {
  const auto kind_of = [](const std::string& text) {
    SourceManager sm;
    Diagnostics diags(sm);
    Ast ast;
    const ParseResult r = parse_file(sm, sm.add_buffer("t.geo", text).file, ast, diags, {});
    REQUIRE(r.stmts.size() == 1);
    return ast.stmt(r.stmts[0]).kind();
  };
  CHECK(kind_of("Field[1] = Threshold;") == StmtKind::FieldNew);
  CHECK(kind_of("Field[1].InField = 2;") == StmtKind::FieldOption);
  CHECK(kind_of("Field[1].Run;") == StmtKind::FieldAction);
  CHECK(kind_of("Delete Field[1];") == StmtKind::DeleteField);
  CHECK(kind_of("Coastline[1] = GSHHS;") == StmtKind::CoastlineNew);
  CHECK(kind_of("Coastline[1].Levels = {1};") == StmtKind::CoastlineOption);
  CHECK(kind_of("Coastline[1].Run;") == StmtKind::CoastlineAction);
  CHECK(kind_of("Delete Coastline[1];") == StmtKind::DeleteCoastline);
  CHECK(ast_of("Coastline[2].Run;") == "(coastline-action 2 Run)");
  CHECK(ast_of("Delete Coastline[2];") == "(delete-coastline 2)");
  CHECK(ast_of("Coastline[1].FileName = \"a.b\";") == "(coastline-option 1 FileName \"a.b\")");
}

namespace {
// The text of a Gmsh tutorial from the gmsh-doc package (gzipped or not), or "".
std::string read_tutorial(const std::string& name) {
  for (const char* dir : {"/usr/share/doc/gmsh-doc/doc/gmsh/tutorial/", "/usr/share/doc/gmsh/tutorial/",
                          "/usr/share/doc/gmsh-doc/tutorial/"}) {
    for (const char* ext : {".geo.gz", ".geo"}) {
      const std::string path = dir + name + ext;
      if (std::FILE* f = std::fopen(path.c_str(), "rb")) std::fclose(f);
      else continue;
      const std::string cmd = (std::string(ext) == ".geo.gz" ? "zcat '" : "cat '") + path + "' 2>/dev/null";
      std::FILE* p = popen(cmd.c_str(), "r");
      if (!p) continue;
      std::string text;
      char buf[4096];
      std::size_t n;
      while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) text.append(buf, n);
      pclose(p);
      if (!text.empty()) return text;
    }
  }
  return {};
}
}  // namespace

TEST_CASE("parser: Gmsh tutorials t1, t4, t10 parse without errors") {
  for (const char* name : {"t1", "t4", "t10"}) {
    const std::string text = read_tutorial(name);
    if (text.empty()) {
      MESSAGE("SKIPPED: Gmsh tutorial " << name << ".geo not found (install the gmsh-doc package)");
      continue;
    }
    const auto r = sm::lang::testing::parse_text(text);
    INFO(name << ": " << r.diags);
    CHECK(r.ok);
    CHECK(r.diags.empty());
    CHECK(r.ast.find("(plane-surface") != std::string::npos);
  }
}

TEST_CASE("parser: documented extensions and corner cases") {
  CHECK(ast_of("Macro Circle Return") == "(macro Circle ())");
  CHECK(ast_of("Call Circle;") == "(call-macro Circle)");
  CHECK(ast_of("Printf(\"%g %g\", {1, 2});") == "(Printf \"%g %g\" (list 1 2))");
  CHECK(ast_of("n = #{1, 2};") == "(assign = n (# (list 1 2)))");
  CHECK(ast_of("Field[1].Min = 1;") == "(field-option 1 Min 1)");
  CHECK(ast_of("Mesh.Smoother = 3;") == "(assign = (option Mesh.Smoother) 3)");
  CHECK(ast_of("Translate {-0.02, 0, 0} { Point{5}; }") ==
        "(shape-stmt (Translate (params (- 0.02) 0 0) (shapes (Point 5))))");
  CHECK(ast_of("Point(1) = (0, 1, 2);") == "(point 1 (list 0 1 2))");
  CHECK(ast_of("For i In {1:3} EndFor;") == "(for i 1 3 _ ())");
  CHECK(ast_of("Mesh = 3;") == "(assign = Mesh 3)");
  CHECK(ast_of("x = 'single';") == "(assign = x \"single\")");
  CHECK(ast_of("x = a?b:c;") == "(assign = x (? (var a) (var b) (var c)))");
  CHECK(ast_of("L[] = {c ? 1 : 2 : 5};") == "(assign = (whole L) (list (range (? (var c) 1 2) 5)))");
}

TEST_CASE("parser: ONELAB forms (DefineNumber, labelled Choices)") {
  CHECK(ast_of("R = DefineNumber[1.4, Min 0.1, Max 2, Step 0.01, Name \"Parameters/R\"];") ==
        "(assign = R (call DefineNumber 1.4))");
  CHECK(ast_of("DefineConstant[ op = {0, Choices{0=\"None\", 1=\"Union\"}, Name \"Op\"} ];") ==
        "(define-constant (op 0 (Choices (list 0 1)) (Name \"Op\")))");
}

TEST_CASE("parser: several files share one Ast (Include at run time)") {
  SourceManager sm;
  Diagnostics diags(sm);
  Ast ast;
  const FileId main = sm.add_buffer("main.geo", "Include \"lib.geo\";\nCall Lib;\n").file;
  const ParseResult r1 = parse_file(sm, main, ast, diags);
  const std::size_t exprs_before = ast.expr_count();
  const FileId lib = sm.add_buffer("lib.geo", "Macro Lib\n  x = 1;\nReturn\n").file;
  const ParseResult r2 = parse_file(sm, lib, ast, diags);
  CHECK(r1.ok);
  CHECK(r2.ok);
  CHECK(ast.expr_count() > exprs_before);
  CHECK(dump(ast, r1.stmts) == "(include \"lib.geo\")\n(call-macro Lib)\n");
  CHECK(dump(ast, r2.stmts) == "(macro Lib ((assign = x 1)))\n");
  CHECK(ast.stmt(r2.stmts[0]).range.file == lib);
  CHECK(ast.stmt(r1.stmts[0]).keyword.end - ast.stmt(r1.stmts[0]).keyword.begin == 7);
  CHECK(ast.intern("Lib") == ast.find("Lib"));
}
