// Error recovery: every independent error in one run, unclosed openers, quiet ends.
#include <doctest/doctest.h>

#include "lang_test_util.h"

using namespace sm::lang;
using sm::lang::testing::parse_text;

namespace {
// The "file:line:col: severity: message [kind]" lines and notes, without snippets.
std::string headlines(const std::string& rendered) {
  std::string out;
  std::size_t pos = 0;
  while (pos < rendered.size()) {
    std::size_t nl = rendered.find('\n', pos);
    if (nl == std::string::npos) nl = rendered.size();
    const std::string line = rendered.substr(pos, nl - pos);
    if (line.rfind("t.geo:", 0) == 0) out += line + "\n";
    pos = nl + 1;
  }
  return out;
}
}  // namespace

TEST_CASE("recovery: one run reports every independent syntax error") {
  const auto r = parse_text(
      "x = 1 +;\n"
      "Point(1) = {0, 0, 0}\n"
      "Point(2) = {1, 0, 0};\n"
      "y = (2 * 3;\n"
      "For i In {1:3}\n"
      "  z = i *;\n"
      "EndFor\n"
      "L[] = {1, 2;\n"
      "Line(3) = {1, 2}};\n"
      "EndFor\n"
      "a = 1;\n");
  CHECK_FALSE(r.ok);
  CHECK(headlines(r.diags) ==
        "t.geo:1:8: error: expected an expression, found ';' [expected-expression]\n"
        "t.geo:2:21: error: expected ';' after statement [expected-semicolon]\n"
        "t.geo:4:11: error: expected ')' to close '(' from line 4, found ';' [unclosed-delimiter]\n"
        "t.geo:4:5: note: '(' opened here\n"
        "t.geo:6:10: error: expected an expression, found ';' [expected-expression]\n"
        "t.geo:8:12: error: expected '}' to close '{' from line 8, found ';' [unclosed-delimiter]\n"
        "t.geo:8:7: note: '{' opened here\n"
        "t.geo:9:17: error: expected ';' after the statement, found '}' [expected-token]\n"
        "t.geo:10:1: error: 'EndFor' without an open 'For' [unmatched-end]\n");
  CHECK(r.errors == 7);
  // the statements between the errors were parsed
  CHECK(r.ast.find("(point 2 ") != std::string::npos);
  CHECK(r.ast.find("(assign = a 1)") != std::string::npos);
}

TEST_CASE("recovery: unclosed blocks point back at their opener") {
  auto r = parse_text("x = 1;\nFor i In {1:2}\n  y = i;\n");
  CHECK(headlines(r.diags) ==
        "t.geo:4:1: error: 'For' without matching 'EndFor' [unterminated-block]\n"
        "t.geo:2:1: note: 'For' opened here\n");
  r = parse_text("For (1:2)\n If (1)\n  x = 1;\nEndFor\n");
  CHECK(headlines(r.diags) ==
        "t.geo:4:1: error: expected 'EndIf' to close 'If', found 'EndFor' [expected-token]\n"
        "t.geo:2:2: note: 'If' opened here\n");
  r = parse_text("Macro Foo\n x = 1;\n");
  CHECK(headlines(r.diags) ==
        "t.geo:3:1: error: 'Macro' without matching 'Return' [unterminated-block]\n"
        "t.geo:1:1: note: 'Macro' opened here\n");
  r = parse_text("If (x > 1\n  w = 2;\nEndIf\nv = 1;\n");
  CHECK(headlines(r.diags) ==
        "t.geo:2:3: error: expected ')' to close '(' from line 1, found identifier 'w' [unclosed-delimiter]\n"
        "t.geo:1:4: note: '(' opened here\n");
  CHECK(r.ast.find("(assign = w 2)") != std::string::npos);
  r = parse_text("Macro A\nMacro B\nReturn\nReturn\n");
  CHECK(headlines(r.diags).find(
            "t.geo:2:1: error: a 'Macro' cannot be defined inside another 'Macro' [nested-macro]") == 0);
  r = parse_text("If (1) Else x = 1; Else y = 2; EndIf");
  CHECK(headlines(r.diags) == "t.geo:1:20: error: 'Else' after 'Else' in the same 'If' [else-after-else]\n");
}

TEST_CASE("recovery: unterminated string and comment give one error at the opener") {
  auto r = parse_text("For (1:2)\n  Printf(\"abc);\nEndFor\n");
  CHECK(headlines(r.diags) == "t.geo:2:10: error: unterminated string: missing closing '\"' [unterminated-string]\n");
  r = parse_text("If (1)\n  x = 1; /* comment\nEndIf\n");
  CHECK(headlines(r.diags) == "t.geo:2:10: error: unterminated '/*' comment [unterminated-comment]\n");
}

TEST_CASE("recovery: syntax errors in dead branches and macro bodies are reported") {
  // Gmsh skips such text unparsed; we parse it (docs/language.md).
  const auto r = parse_text("If (0)\n  x = = 1;\nEndIf\nMacro M\n  y = );\nReturn\n");
  CHECK(r.errors == 2);
  CHECK(headlines(r.diags).find("t.geo:2:7:") == 0);
  CHECK(headlines(r.diags).find("t.geo:5:7:") != std::string::npos);
}

TEST_CASE("recovery: unknown commands and keywords as names") {
  auto r = parse_text("Frobnicate \"bar\";\nx = 1;\n");
  CHECK(headlines(r.diags) == "t.geo:1:1: error: unknown command 'Frobnicate' [unknown-command]\n");
  r = parse_text("For i In {1:2}\n  x = i;\nEndFo\ny = 2;\n");
  CHECK(headlines(r.diags) ==
        "t.geo:3:1: error: unknown command 'EndFo' [unknown-command]\n"
        "t.geo:3:1: note: did you mean 'EndFor'?\n"
        "t.geo:5:1: error: 'For' without matching 'EndFor' [unterminated-block]\n"
        "t.geo:1:1: note: 'For' opened here\n");
  r = parse_text("Sav \"a.msh\";\n");
  CHECK(headlines(r.diags) ==
        "t.geo:1:1: error: unknown command 'Sav' [unknown-command]\n"
        "t.geo:1:1: note: did you mean 'Save'?\n");
  r = parse_text("Pi = 3;\n");
  CHECK(headlines(r.diags) ==
        "t.geo:1:1: error: 'Pi' is a keyword and cannot be used as a name here [keyword-as-name]\n");
  r = parse_text("Call Foo; x = 1;\n");
  CHECK(r.ok);
  CHECK(headlines(r.diags).find("warning: statements after 'Call' on the same line run after it here, but before it in "
                                "Gmsh [statement-after-call]") != std::string::npos);
}
