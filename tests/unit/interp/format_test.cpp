// Printf/Sprintf formatting: expectations taken from gmsh 4.8.4 -0 runs.
#include <doctest/doctest.h>

#include "interp/format.h"

using sm::interp::format_gmsh;
using sm::interp::FormatArg;

namespace {
std::string fmt_ok(std::string_view f, std::vector<FormatArg> args) {
  auto r = format_gmsh(f, args);
  REQUIRE_MESSAGE(r.ok, r.error);
  return r.text;
}
}  // namespace

TEST_CASE("format: pieces with one number each (gmsh 4.8.4)") {
  CHECK(fmt_ok("a %g b", {5.0}) == "a 5 b");
  CHECK(fmt_ok("%5.2f|%e|%10g|%-6g|", {3.14159, 2.5, 7.0, 8.0}) == " 3.14|2.500000e+00|         7|8     |");
  CHECK(fmt_ok("x=%g y=%g", {1.5, 2.0}) == "x=1.5 y=2");
  CHECK(fmt_ok("%g", {1e20}) == "1e+20");
  CHECK(fmt_ok("%03.0f", {7.0}) == "007");
  CHECK(fmt_ok("%.3g|%G|%E|%5.1e", {3.14159, 1e-10, 12345.678, 0.000123}) ==
        "3.14|1E-10|1.234568E+04|1.2e-04");
  CHECK(fmt_ok("%g|%g", {-0.0, 1.0 / 3}) == "-0|0.333333");
  CHECK(fmt_ok("%+g % g", {3.0, 3.0}) == "+3  3");
  CHECK(fmt_ok("%lf", {2.5}) == "2.500000");
  CHECK(fmt_ok("a%gb%gc", {1.0, 2.0}) == "a1b2c");
}

TEST_CASE("format: no directive dumps the list") {
  CHECK(fmt_ok("L", {1.0, 2.0, 3.0}) == "L [0]1 [1]2 [2]3");
  CHECK(fmt_ok("nothing", {}) == "nothing");
  CHECK(fmt_ok("x", {3.0}) == "x [0]3");
}

TEST_CASE("format: argument count errors") {
  auto few = format_gmsh("%g %g", {1.0});
  CHECK_FALSE(few.ok);
  CHECK(few.error.find("too few") != std::string::npos);
  auto extra = format_gmsh("%g", {1.0, 2.0});
  CHECK_FALSE(extra.ok);
  CHECK(extra.error == "1 extra argument for the format");
  CHECK(extra.arg_index == 1);
  CHECK_FALSE(format_gmsh("%g", {}).ok);
}

TEST_CASE("format: C semantics where Gmsh prints garbage") {
  CHECK(fmt_ok("%d", {5.0}) == "5");
  CHECK(fmt_ok("%5.3d|", {42.9}) == "  042|");
  CHECK(fmt_ok("%d", {-3.7}) == "-3");
  CHECK(fmt_ok("%x %X %o", {255.0, 255.0, 8.0}) == "ff FF 10");
  CHECK(fmt_ok("%c", {65.0}) == "A");
  CHECK(fmt_ok("%s=%g", {std::string("v"), 2.0}) == "v=2");
  CHECK(fmt_ok("%-4s|", {std::string("ab")}) == "ab  |");
  CHECK(fmt_ok("%g %%", {5.0}) == "5 %");
  CHECK(fmt_ok("100%%", {}) == "100%");
}

TEST_CASE("format: hostile formats are refused, never passed to snprintf") {
  CHECK_FALSE(format_gmsh("%n", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%p", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%*g", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%99999999g", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%.99999g", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%s", {1.0}).ok);
  CHECK_FALSE(format_gmsh("%g", {std::string("a")}).ok);
  CHECK_FALSE(format_gmsh("%d", {1e300}).ok);
}

TEST_CASE("format: a failure names its typed kind, whose message it carries") {
  using sm::lang::Diag;
  const auto star = format_gmsh("%.*g", {1.0});
  CHECK(star.kind == Diag::FormatStarNotSupported);
  CHECK(star.error == "'*' precision is not supported in a format");
  const auto few = format_gmsh("%g %g", {1.0});
  CHECK(few.kind == Diag::FormatTooFewArguments);
  CHECK(few.error == "too few arguments for the format: 2 directives but 1 argument");
  const auto wide = format_gmsh("%99999g", {1.0});
  CHECK(wide.kind == Diag::FormatNumberTooLarge);
  CHECK(wide.error == "format width larger than 4096");
  const auto big = format_gmsh("%x", {1e300});
  CHECK(big.kind == Diag::FormatIntegerOverflow);
  CHECK(big.error == "value 1e+300 does not fit the integer conversion '%x'");
  CHECK(format_gmsh("%y", {1.0}).error == "invalid conversion '%y' in format");
  CHECK(format_gmsh("%d", {std::string("a")}).error == "'%d' expects a number, got a string");
  CHECK(format_gmsh("%g", {1.0}).kind == Diag::kCount);
}
