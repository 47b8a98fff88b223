// Evaluator: semantics, runtime errors with locations and call notes, limits.
#include <unistd.h>
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "interp_test_util.h"

using sm::interp::testing::run_script;

TEST_CASE("interp: assignment, lists and Printf") {
  auto r = run_script("x = 2; l[] = {1, x, 3}; l[] += x^2; Printf(\"%g %g\", #l[], l[3]);\n");
  CHECK(r.ok);
  CHECK(r.out == "4 4\n");
}

TEST_CASE("interp: For leaves the variable at last + step, body sees its own counter") {
  auto r = run_script("For i In {1:3}\n i = 100;\nEndFor\nPrintf(\"%g\", i);\n");
  CHECK(r.out == "4\n");
  r = run_script("For i In {3:1}\nPrintf(\"x\");\nEndFor\nPrintf(\"%g\", i);\n");
  CHECK(r.out == "3\n");
  r = run_script("n = 0;\nFor i In {1:5:0}\nn++;\nEndFor\nPrintf(\"%g %g\", n, i);\n");
  CHECK(r.out == "1 1\n");
}

TEST_CASE("interp: && and || evaluate both sides") {
  auto r = run_script("a = 0;\nb = (0 && a++);\nc = (1 || a++);\nPrintf(\"%g %g %g\", a, b, c);\n");
  CHECK(r.out == "2 0 1\n");
}

TEST_CASE("interp: Call/Include take effect where they stand") {
  auto r = run_script("Macro M\nv = 7;\nReturn\nv = 1; Call M; Printf(\"%g\", v);\n");
  CHECK(r.out == "7\n");
}

TEST_CASE("interp: Return leaves a macro early") {
  auto r = run_script("Macro M\nv = 1;\nIf (1)\nReturn\nEndIf\nv = 2;\nReturn\nCall M;\nPrintf(\"%g\", v);\n");
  CHECK(r.ok);
  CHECK(r.out == "1\n");
}

TEST_CASE("interp: runtime errors are located") {
  auto r = run_script("x = 1;\ny = x + zz;\n");
  CHECK_FALSE(r.ok);
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "2:9 unknown-variable");
  r = run_script("x = 1;\ny = 3 / (x - 1);\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "2:10 division-by-zero");
  r = run_script("l[] = {1,2};\nPrintf(\"%g\", l[5]);\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "2:16 index-out-of-range");
  r = run_script("z = 3;\nz[1] = 5;\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0].find("not-a-list") != std::string::npos);
  r = run_script("x = 7 % 0;\n");
  CHECK(r.kinds.at(0) == "1:9 division-by-zero");
}

TEST_CASE("interp: the first runtime error stops the run") {
  auto r = run_script("Printf(\"a\");\nx = nope;\nPrintf(\"b\");\n");
  CHECK(r.out == "a\n");
  CHECK(r.kinds.size() == 1);
}

TEST_CASE("interp: errors inside macros get a 'called from' note per frame") {
  auto r = run_script("Macro Inner\n  x = undefined_thing;\nReturn\nMacro Outer\n  Call Inner;\nReturn\nCall Outer;\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "2:7 unknown-variable");
  CHECK(r.rendered.find("called from here (macro 'Inner')") != std::string::npos);
  CHECK(r.rendered.find("called from here (macro 'Outer')") != std::string::npos);
  CHECK(r.rendered.find("test.geo:5:3: note") != std::string::npos);
  CHECK(r.rendered.find("test.geo:7:1: note") != std::string::npos);
}

TEST_CASE("interp: unknown names get suggestions") {
  auto r = run_script("value = 1;\nPrintf(\"%g\", valeu);\n");
  CHECK(r.rendered.find("did you mean 'value'?") != std::string::npos);
  r = run_script("Mesh.Algoritm = 6;\n");
  CHECK(r.kinds.at(0) == "1:1 unknown-option");
  CHECK(r.rendered.find("did you mean 'Mesh.Algorithm'?") != std::string::npos);
  r = run_script("x = Sqr(2);\n");
  CHECK(r.kinds.at(0) == "1:5 unknown-variable");   // `Sqr(2)` is indexing, as in Gmsh
  CHECK(r.rendered.find("did you mean the function 'Sqrt'?") != std::string::npos);
  r = run_script("Macro Build\nReturn\nCall Biuld;\n");
  CHECK(r.kinds.at(0) == "3:1 unknown-macro");
  CHECK(r.rendered.find("did you mean 'Build'?") != std::string::npos);
}

TEST_CASE("interp: options are validated") {
  auto r = run_script("Mesh.Algorithm = 4;\n");
  CHECK(r.kinds.at(0) == "1:18 invalid-option-value");
  r = run_script("Mesh.Algorithm = 5; Printf(\"%g\", Mesh.Algorithm);\n");
  CHECK(r.out == "5\n");
  r = run_script("Mesh.NbNodes = 5;\n");
  CHECK(r.kinds.at(0) == "1:16 invalid-option-value");
}

TEST_CASE("interp: hostile loops and ranges stop with clear limits") {
  auto r = run_script("l[] = {1:1e12};\n");
  CHECK(r.kinds.at(0) == "1:8 limit-exceeded");
  r = run_script("For i In {1:1e15}\nEndFor\n");
  CHECK(r.kinds.at(0) == "1:1 limit-exceeded");
  r = run_script("l[] = {1:5:0};\n");
  CHECK(r.kinds.at(0) == "1:12 invalid-range");
  r = run_script("Macro R\nCall R;\nReturn\nCall R;\n");
  CHECK(r.kinds.at(0) == "2:1 call-too-deep");
  r = run_script("l[1e9] = 1;\n");
  CHECK(r.kinds.at(0).find("limit-exceeded") != std::string::npos);
}

TEST_CASE("interp: Error() reports and goes on, Assert stops") {
  auto r = run_script("Error(\"bad %g\", 1);\nPrintf(\"after\");\n");
  CHECK(r.out == "after\n");
  CHECK(r.kinds.at(0) == "1:1 user-error");
  CHECK(r.rendered.find("bad 1") != std::string::npos);
  r = run_script("x = 2;\nAssert(x == 3, \"x is %g\", x);\nPrintf(\"no\");\n");
  CHECK(r.out.empty());
  CHECK(r.kinds.at(0) == "2:8 assertion-failed");
  CHECK(r.rendered.find("assertion failed: x is 2") != std::string::npos);
  r = run_script("Warning(\"careful\");\n");
  CHECK(r.ok);
  CHECK(r.kinds.at(0) == "1:1 user-warning");
}

TEST_CASE("interp: Exit and Abort stop the script") {
  auto r = run_script("Printf(\"a\");\nExit 3;\nPrintf(\"b\");\n");
  CHECK(r.out == "a\n");
  CHECK(r.exit_request == 3);
  r = run_script("Error(\"e\");\nExit;\n");
  CHECK(r.exit_request == 1);
  r = run_script("Exit;\n");
  CHECK(r.exit_request == 0);
  r = run_script("Printf(\"a\");\nAbort;\nPrintf(\"b\");\n");
  CHECK(r.out == "a\n");
  CHECK(r.ok);
}

TEST_CASE("interp: DefineConstant keeps -setnumber values") {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream out;
  sm::interp::Interpreter in(sources, diags, out);
  CHECK(in.preset_number("a", 7).empty());
  CHECK(in.preset_number("Mesh.Algorithm", 5).empty());
  CHECK_FALSE(in.preset_number("Mesh.Algorthm", 5).empty());
  in.run_buffer("t.geo", "DefineConstant[a = 1, b = 2];\nPrintf(\"%g %g %g\", a, b, Mesh.Algorithm);\n");
  CHECK(out.str() == "7 2 5\n");
}

TEST_CASE("interp: statements without a kernel yet are reported once per kind and skipped") {
  // Post-processing (Plugin) has no kernel in stereomesh's scope; a View only shows data in
  // Gmsh's window: a display-only note, which is not an error or a warning.
  auto r = run_script("Plugin(Crack).Dimension = 1;\nPlugin(Crack).Run;\nView \"v\" { SP(0,0,0){1}; };\n"
                      "x = 2;\nPrintf(\"%g\", x);\n");
  CHECK(r.out == "2\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "1:1 not-supported-yet");
  CHECK(r.rendered.find("3:1: note: 'View' changes only what Gmsh's window shows") != std::string::npos);
  // Their expressions are still evaluated.
  r = run_script("Plugin(Crack).Dimension = nothing;\n");
  CHECK(r.kinds.at(0) == "1:27 unknown-variable");
}

TEST_CASE("interp: Printf redirection and Include relative to the script") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_interp_test_redirect_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  {
    std::ofstream(dir / "sub" / "inc.geo")
        << "Printf(\"%g\", 10) > \"nums.txt\";\nPrintf(\"%g\", 20) >> \"nums.txt\";\n";
    std::ofstream(dir / "main.geo") << "Include \"sub/inc.geo\";\nl[] = ListFromFile(\"sub/nums.txt\");\n"
                                       "Printf(\"l\", l[]);\n";
  }
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream out;
  sm::interp::Interpreter in(sources, diags, out);
  in.run_file((dir / "main.geo").string());
  CHECK(diags.render_all() == "");
  CHECK(out.str() == "l [0]10 [1]20\n");
  CHECK(fs::exists(dir / "sub" / "nums.txt"));
  fs::remove_all(dir);
}

TEST_CASE("interp: include cycles and missing includes are errors") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_interp_test_cycle_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "a.geo") << "Include \"b.geo\";\n";
  std::ofstream(dir / "b.geo") << "x = 1;\nInclude \"a.geo\";\n";
  std::ofstream(dir / "c.geo") << "Include \"missing.geo\";\n";
  {
    sm::lang::SourceManager sources;
    sm::lang::Diagnostics diags(sources);
    std::ostringstream out;
    sm::interp::Interpreter in(sources, diags, out);
    in.run_file((dir / "a.geo").string());
    REQUIRE(diags.all().size() == 1);
    CHECK(diags.all()[0].kind == sm::lang::Diag::IncludeCycle);
    CHECK(diags.render_all().find("b.geo:2:9") != std::string::npos);
  }
  {
    sm::lang::SourceManager sources;
    sm::lang::Diagnostics diags(sources);
    std::ostringstream out;
    sm::interp::RunSettings settings;
    settings.include_dirs.push_back((dir / "nowhere").string());
    sm::interp::Interpreter in(sources, diags, out, settings);
    in.run_file((dir / "c.geo").string());
    REQUIRE(diags.all().size() == 1);
    CHECK(diags.all()[0].kind == sm::lang::Diag::IncludeNotFound);
    CHECK(diags.render_all().find("nowhere") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("interp: Include searches -I directories and the stdlib") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_interp_test_search_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "lib");
  std::ofstream(dir / "lib" / "helper.geo") << "helper = 5;\n";
  sm::interp::RunSettings settings;
  settings.include_dirs.push_back((dir / "lib").string());
  auto r = run_script("Include \"helper.geo\";\nPrintf(\"%g\", helper);\n", "t.geo", settings);
  CHECK(r.out == "5\n");
  r = run_script("Include \"earth.geo\";\nPrintf(\"%g\", EarthRadius);\n");
  CHECK(r.ok);
  CHECK(r.out == "6.371e+06\n");
  fs::remove_all(dir);
}

TEST_CASE("interp: Include inside a running loop keeps the loop's nodes valid") {
  // Parsing the included file grows the shared Ast while the For body runs.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_interp_test_loop_include_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream inc(dir / "body.geo");
    inc << "count += 1;\n";
    for (int i = 0; i < 2000; ++i) inc << "tmp_" << i << " = " << i << " * 2 + 1;\n";
  }
  std::ofstream(dir / "main.geo")
      << "count = 0;\nFor i In {1:3}\n  Include \"body.geo\";\n  Printf(\"%g %g\", i, count);\nEndFor\n";
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  std::ostringstream out;
  sm::interp::Interpreter in(sources, diags, out);
  in.run_file((dir / "main.geo").string());
  CHECK(diags.render_all() == "");
  CHECK(out.str() == "1 1\n2 2\n3 3\n");
  fs::remove_all(dir);
}

TEST_CASE("interp: deep expressions evaluate without exhausting the stack") {
  std::string chain = "z = 1";
  for (int i = 0; i < 200000; ++i) chain += "+1";
  auto r = run_script(chain + ";\nPrintf(\"%g\", z);\n");
  CHECK(r.ok);
  CHECK(r.out == "200001\n");
  // Blocks nested 900 deep inside a macro recursing 200 deep: a clean error.
  std::string rec = "n = 0;\nMacro R\nn++;\n";
  for (int i = 0; i < 900; ++i) rec += "If (1) ";
  rec += "If (n < 300) Call R; EndIf ";
  for (int i = 0; i < 900; ++i) rec += "EndIf ";
  rec += "\nReturn\nCall R;\n";
  r = run_script(rec);
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0].find("limit-exceeded") != std::string::npos);
  // 200 identical frames are summarised.
  r = run_script("Macro R\nCall R;\nReturn\nCall R;\n");
  CHECK(r.rendered.find("... 188 more frames ...") != std::string::npos);
}

TEST_CASE("interp: per-run limits") {
  sm::interp::RunSettings settings;
  settings.limits.max_statements = 1000;
  settings.limits.max_list_size = 50;
  settings.limits.max_string_size = 10;
  settings.limits.max_call_depth = 5;
  auto r = run_script("For i In {1:2000}\nEndFor\n", "t.geo", settings);
  CHECK(r.kinds.at(0) == "1:1 limit-exceeded");
  r = run_script("l[] = {1:100};\n", "t.geo", settings);
  CHECK(r.kinds.at(0) == "1:8 limit-exceeded");
  r = run_script("l[] = LinSpace(0, 1, 60);\n", "t.geo", settings);
  CHECK(r.kinds.at(0) == "1:22 builtin-error");
  r = run_script("s = StrCat(\"abcdef\", \"ghijkl\");\n", "t.geo", settings);
  CHECK(r.kinds.at(0) == "1:5 builtin-error");
  r = run_script("n = 0;\nMacro R\nn++;\nCall R;\nReturn\nCall R;\n", "t.geo", settings);
  CHECK(r.kinds.at(0) == "4:1 call-too-deep");
  r = run_script("For i In {1:10}\nEndFor\nl[] = {1:40};\ns = \"short\";\n", "t.geo", settings);
  CHECK(r.ok);
}

TEST_CASE("interp: errors inside loops say which iteration failed") {
  auto r = run_script("l[] = {1, 2, 0, 4};\nFor i In {0:3}\n  x = 1 / l[i];\nEndFor\n");
  REQUIRE(r.kinds.size() == 1);
  CHECK(r.kinds[0] == "3:11 division-by-zero");
  CHECK(r.rendered.find("test.geo:2:1: note: inside this 'For' loop (i = 2)") != std::string::npos);
  r = run_script("n = 0;\nFor (1:5)\n  n++;\n  If (n == 4)\n    y = undefined;\n  EndIf\nEndFor\n");
  CHECK(r.rendered.find("inside this 'For' loop (iteration 4)") != std::string::npos);
}
