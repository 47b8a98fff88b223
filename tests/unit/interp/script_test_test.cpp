// The --test driver: expectation parsing, pass/fail decisions, summary line.
#include <unistd.h>
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp/script_test.h"

using namespace sm::interp;

TEST_CASE("script tests: expectations are read from comments") {
  const auto ex = parse_expectations(
      "Printf(\"%g\", 1); // expect: 1\n"
      "// expect:   two  \n"
      "x = ; // expect error: 3:5: expected-expression\n"
      "// expect warning: 4:1: user-warning\n"
      "// expectation: not an expectation\n");
  CHECK(ex.stdout_lines == std::vector<std::string>{"1", "  two"});
  CHECK(ex.diagnostics == std::vector<std::string>{"3:5: expected-expression", "warning 4:1: user-warning"});
}

TEST_CASE("script tests: the driver passes and fails scripts") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_script_test_driver_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "b");
  std::ofstream(dir / "a_pass.geo") << "s = 0;\nFor i In {1:4}\n  s += i;\nEndFor\nPrintf(\"%g\", s);  // expect: 10\n";
  std::ofstream(dir / "b" / "wrong_output.geo") << "Printf(\"%g\", 2);  // expect: 3\n";
  std::ofstream(dir / "b" / "fail_wrong_diag.geo") << "x = y;\n// expect error: 1:5: division-by-zero\n";
  std::ofstream(dir / "b" / "fail_right_diag.geo") << "x = 1;\nx = x / 0;\n// expect error: 2:9: division-by-zero\n";
  std::ofstream(dir / "b" / "unexpected_error.geo") << "x = y;\n";
  std::ofstream(dir / "b" / "not_a_script.inc") << "this is not run\n";
  std::ostringstream out;
  const int failed = run_script_tests({dir.string()}, RunSettings{}, out);
  const std::string text = out.str();
  CHECK(failed == 3);
  CHECK(text.find("2 passed, 3 failed\n") != std::string::npos);
  CHECK(text.find("FAIL " + (dir / "b" / "wrong_output.geo").string()) != std::string::npos);
  CHECK(text.find("expected '3', got '2'") != std::string::npos);
  CHECK(text.find("FAIL " + (dir / "b" / "fail_wrong_diag.geo").string()) != std::string::npos);
  CHECK(text.find("1:5: unknown-variable") != std::string::npos);
  CHECK(text.find("FAIL " + (dir / "b" / "unexpected_error.geo").string()) != std::string::npos);
  CHECK(text.find("fail_right_diag") == std::string::npos);
  std::ostringstream none;
  CHECK(run_script_tests({(dir / "missing").string()}, RunSettings{}, none) == -1);
  fs::remove_all(dir);
}
