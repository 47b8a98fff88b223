// Hostile inputs: deep nesting, garbage bytes, huge lines and files must give
// clean errors (no crash, no stack overflow). No wall-clock checks here (they fail on a
// loaded machine): a quadratic pass on these 50 MB inputs runs into the test timeout
// that tests/CMakeLists.txt sets.
#include <doctest/doctest.h>

#include "lang_test_util.h"

using namespace sm::lang;
using sm::lang::testing::parse_text;

TEST_CASE("hostile: 100,000 nested parentheses give one nesting error") {
  const std::string text = "x = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";\ny = 2;\n";
  const auto r = parse_text(text);
  CHECK(r.errors == 1);
  CHECK(r.diags.find("t.geo:1:1005: error: nesting deeper than 1000 levels") == 0);
}

TEST_CASE("hostile: other deep nestings (lists, unary, ^, ~{}, blocks, transforms)") {
  const std::vector<std::string> cases = {
      "z = " + std::string(100000, '{') + "1" + std::string(100000, '}') + ";",
      "x = " + std::string(100000, '!') + "1;",
      [] {
        std::string s = "y = ";
        for (int i = 0; i < 100000; ++i) s += "2^";
        return s + "1;";
      }(),
      [] {
        std::string s = "x = a";
        for (int i = 0; i < 50000; ++i) s += "~{a";
        return s + std::string(50000, '}') + ";";
      }(),
      [] {
        std::string s;
        for (int i = 0; i < 5000; ++i) s += "For i In {1:2} ";
        for (int i = 0; i < 5000; ++i) s += "EndFor ";
        return s;
      }(),
      [] {
        std::string s;
        for (int i = 0; i < 5000; ++i) s += "If(1) ";
        for (int i = 0; i < 5000; ++i) s += "EndIf ";
        return s;
      }(),
      [] {
        std::string s = "Delete { ";
        for (int i = 0; i < 20000; ++i) s += "Translate{1,0,0}{";
        return s + std::string(20001, '}');
      }(),
  };
  for (const std::string& text : cases) {
    const auto r = parse_text(text);
    INFO(text.substr(0, 40));
    CHECK(r.errors == 1);
    CHECK(r.diags.find("[nesting-too-deep]") != std::string::npos);
  }
}

TEST_CASE("hostile: binary garbage is reported, never crashes, stops at the error limit") {
  std::string text;
  std::uint32_t seed = 12345;
  for (int i = 0; i < 2000000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    text += static_cast<char>(seed >> 24);
  }
  const auto r = parse_text(text);
  CHECK_FALSE(r.ok);
  CHECK(r.errors <= Diagnostics::kDefaultMaxErrors + 1);
  CHECK(r.diags.find("too many errors (50), stopping") != std::string::npos);
}

TEST_CASE("hostile: a 50 MB line lexes, parses and renders in linear time") {
  {
    // a 50 MB string literal, then a 50 MB comment, on one line
    std::string text = "s = \"";
    text.reserve(101u << 20);
    text.append(50u << 20, 'a');
    text += "\"; // ";
    text.append(50u << 20, 'b');
    text += "\nx = ;\n";
    const auto r = parse_text(text);
    CHECK(r.errors == 1);
    CHECK(r.diags.find("t.geo:2:5: error: expected an expression") == 0);
  }
  {
    // an error at the end of a 50 MB line renders a short window
    std::string text(50u << 20, ' ');
    text += "@";
    const auto r = parse_text(text);
    CHECK(r.errors == 1);
    CHECK(r.diags.size() < 600);
    CHECK(r.diags.find("t.geo:1:52428801: error: unexpected character '@'") == 0);
  }
}

TEST_CASE("hostile: a list of a million items on one line") {
  std::string text = "L[] = {0";
  for (int i = 0; i < 1000000; ++i) text += ",12345";
  text += "};\nx = ;\n";
  const auto r = parse_text(text);
  CHECK(r.errors == 1);
  CHECK(r.diags.find("t.geo:2:5: error: expected an expression") == 0);
}

TEST_CASE("hostile: unterminated constructs at the end of the file") {
  for (const char* text : {"x = \"abc", "/* open", "x = (1 +", "L[] = {1,", "For i In {1:", "If (", "Macro",
                           "Field[1", "Point(1) = {", "Delete {", "DefineConstant[ a = {1, Name", "x~{", "#"}) {
    const auto r = parse_text(text);
    INFO(text);
    CHECK(r.errors >= 1);
    CHECK(r.errors <= 2);
  }
}

TEST_CASE("hostile: files over the size limit are rejected with a message") {
  SourceManager sm;
  const auto r = sm.add_buffer("big.geo", std::string(SourceManager::kMaxFileBytes + 1, ' '));
  CHECK_FALSE(r.file.valid());
  CHECK(r.failure == SourceManager::LoadFailure::TooLarge);
  CHECK(format_diag<std::string, std::size_t>(Diag::ScriptTooLarge, "big.geo", SourceManager::kMaxFileMiB) ==
        "cannot load 'big.geo': larger than the 256 MiB limit for a script");
}

TEST_CASE("hostile: huge tokens are clipped in messages") {
  auto r = parse_text(std::string(10u << 20, 'x') + " \"a\";\n");
  CHECK(r.errors == 1);
  CHECK(r.diags.size() < 800);
  CHECK(r.diags.find("unknown command 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'") != std::string::npos);
  r = parse_text("x = 1" + std::string(1u << 20, '0') + ";\n");
  CHECK(r.errors == 1);
  CHECK(r.diags.find("[number-out-of-range]") != std::string::npos);
  CHECK(r.diags.size() < 800);
}
