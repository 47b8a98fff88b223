// Lexer: Gmsh number/keyword/operator rules, raw strings, bad bytes.
#include <doctest/doctest.h>

#include "lang_test_util.h"

using namespace sm::lang;
using sm::lang::testing::lex_all;

TEST_CASE("lexer: numbers follow Gmsh (no sign, 1. .5 1.5e-3 2E4)") {
  const auto r = lex_all("123 1. .5 1.5e-3 2E4 -3 2e 1.e1");
  const std::vector<std::string> want = {"123", "1.", ".5", "1.5e-3", "2E4", "-", "3", "2", "e", "1.e1"};
  CHECK(r.texts == want);
  CHECK(r.errors == 0);
  double v = 0;
  CHECK(number_value("1.", v));
  CHECK(v == 1.0);
  CHECK(number_value(".5", v));
  CHECK(v == 0.5);
  CHECK(number_value("1.5e-3", v));
  CHECK(v == doctest::Approx(1.5e-3));
  CHECK_FALSE(number_value("1e999", v));
  CHECK(number_value("1e-999", v));
  CHECK(v == 0.0);
}

TEST_CASE("lexer: keywords, synonyms, constants and identifiers") {
  const auto r = lex_all("Line Curve CatmullRom Pointer Point Pi newp Include x_1 Function");
  const std::vector<Tok> want = {Tok::Curve, Tok::Curve, Tok::Spline, Tok::Ident, Tok::Point,
                                 Tok::Constant, Tok::Constant, Tok::Ident, Tok::Ident, Tok::Macro};
  CHECK(r.kinds == want);
  CHECK(r.texts[0] == "Line");  // the spelling is kept for messages
}

TEST_CASE("lexer: operators use maximal munch") {
  const auto r = lex_all("a+=1; b++ -- :: || && == != <= >= << >> ? ~ # . : | & ^ %");
  const std::vector<Tok> want = {Tok::Ident, Tok::PlusAssign, Tok::Number, Tok::Semicolon, Tok::Ident,
                                 Tok::PlusPlus, Tok::MinusMinus, Tok::ColonColon, Tok::PipePipe, Tok::AmpAmp,
                                 Tok::EqEq, Tok::NotEq, Tok::LessEq, Tok::GreaterEq, Tok::ShiftLeft,
                                 Tok::ShiftRight, Tok::Question, Tok::Tilde, Tok::Hash, Tok::Dot, Tok::Colon,
                                 Tok::Pipe, Tok::Amp, Tok::Caret, Tok::Percent};
  CHECK(r.kinds == want);
}

TEST_CASE("lexer: comments and raw strings") {
  const auto r = lex_all("a // c\n/* x\n y */ \"s\\n'\" 'q\"' \"multi\nline\"");
  REQUIRE(r.kinds.size() == 4);
  CHECK(r.texts[1] == "\"s\\n'\"");
  CHECK(r.texts[2] == "'q\"'");
  CHECK(r.kinds[3] == Tok::String);
  CHECK(r.errors == 0);
}

TEST_CASE("lexer: unterminated string and comment point at the opener") {
  auto r = lex_all("x = 1;\ny = \"abc;\n");
  CHECK(r.errors == 1);
  CHECK(r.diags.find("t.geo:2:5: error: unterminated string: missing closing '\"' [unterminated-string]") == 0);
  r = lex_all("a\n  /* open\n\n");
  CHECK(r.errors == 1);
  CHECK(r.diags.find("t.geo:2:3: error: unterminated '/*' comment [unterminated-comment]") == 0);
}

TEST_CASE("lexer: bad characters become one Error token per run") {
  auto r = lex_all("a @@ b $ c");
  CHECK(r.kinds == std::vector<Tok>{Tok::Ident, Tok::Error, Tok::Ident, Tok::Error, Tok::Ident});
  CHECK(r.errors == 2);
  CHECK(r.diags.find("unexpected character '@'") != std::string::npos);
  std::string garbage = "x";
  garbage += std::string("\x00\xff\xfe\x01", 4);
  garbage += "y \xc3\xa9";  // é is valid UTF-8 but not a token
  r = lex_all(garbage);
  CHECK(r.kinds == std::vector<Tok>{Tok::Ident, Tok::Error, Tok::Ident, Tok::Error});
  CHECK(r.diags.find("invalid byte 0x00") != std::string::npos);
  CHECK(r.diags.find("unexpected character '\xc3\xa9'") != std::string::npos);
}
