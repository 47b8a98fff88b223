// Builtin functions called directly, without the parser.
#include <doctest/doctest.h>

#include <cmath>

#include "interp/builtins/builtins.h"

using namespace sm::interp;

namespace {

struct Env {
  Symbols symbols;
  Options options;
  std::map<std::string, double, std::less<>> nums;
  std::map<std::string, std::string, std::less<>> strs;
  std::uint64_t rand_state = 0;
  BuiltinEnv env{symbols, options, nums, strs, "/data/scripts/main.geo", rand_state};
};

Value call(Env& e, std::string_view name, std::vector<Value> args) {
  const BuiltinFn fn = find_builtin(name);
  REQUIRE((fn != nullptr));
  return fn(e.env, args);
}

double num(Env& e, std::string_view name, std::vector<Value> args) {
  return call(e, name, std::move(args)).nums().at(0);
}

Value n(double v) { return Value::number(v); }
Value s(std::string v) { return Value::string(std::move(v)); }

}  // namespace

TEST_CASE("builtins: every row of the table but the model ones has an implementation") {
  const auto all = sm::lang::builtin_functions();
  CHECK(all.size() >= 55);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto id = static_cast<sm::lang::BuiltinId>(i);
    CAPTURE(all[i].name);
    CHECK((builtin_impl(id) == nullptr) == (all[i].pass == sm::lang::BuiltinPass::Model));
  }
  for (const char* name : {"Sqrt", "ArcTan2", "Round", "Unique", "LinSpace", "StrCat", "Sprintf", "StrSub",
                           "GetNumber", "FileExists", "AbsolutePath", "Step", "Exists", "DefineNumber"})
    CHECK((find_builtin(name) != nullptr));
  CHECK((find_builtin("sqrt") == nullptr));
  CHECK((find_builtin("FieldValue") == nullptr));   // run by the evaluator's model dispatch
}

TEST_CASE("builtins: math matches Gmsh 4.8.4") {
  Env e;
  CHECK(num(e, "Round", {n(2.5)}) == 3);
  CHECK(num(e, "Round", {n(-2.5)}) == -2);
  CHECK(num(e, "Fmod", {n(-7), n(3)}) == -1);
  CHECK(num(e, "Modulo", {n(7.5), n(2)}) == 1.5);
  CHECK(num(e, "Hypot", {n(3), n(4)}) == 5);
  CHECK(num(e, "Atan2", {n(1), n(1)}) == doctest::Approx(M_PI / 4));
  CHECK(num(e, "Step", {n(-1)}) == 0);
  CHECK(num(e, "Step", {n(0)}) == 1);
  CHECK(num(e, "Min", {n(3), n(4)}) == 3);
  // A list used as a scalar gives its element 0.
  CHECK(num(e, "Sqrt", {Value::list({16, 9})}) == 4);
  CHECK(call(e, "Abs", {Value::list({-1, 2, -3})}).nums() == std::vector<double>{1, 2, 3});
}

TEST_CASE("builtins: domain errors instead of nan") {
  Env e;
  CHECK_THROWS_AS(call(e, "Sqrt", {n(-1)}), BuiltinError);
  CHECK_THROWS_AS(call(e, "Log", {n(0)}), BuiltinError);
  CHECK_THROWS_AS(call(e, "Asin", {n(2)}), BuiltinError);
  CHECK_THROWS_AS(call(e, "Fmod", {n(1), n(0)}), BuiltinError);
  CHECK_THROWS_AS(call(e, "Sqrt", {s("x")}), BuiltinError);
}

TEST_CASE("builtins: Rand is seeded and within [0, a]") {
  Env a, b;
  for (int i = 0; i < 100; ++i) {
    const double x = num(a, "Rand", {n(2)});
    CHECK(x == num(b, "Rand", {n(2)}));
    CHECK(x >= 0);
    CHECK(x <= 2);
  }
  CHECK(num(a, "Rand", {n(0)}) == 0);
}

TEST_CASE("builtins: lists") {
  Env e;
  CHECK(call(e, "Unique", {Value::list({3, 1, 2, 3, 1})}).nums() == std::vector<double>{1, 2, 3});
  CHECK(call(e, "LinSpace", {n(0), n(1), n(5)}).nums() == std::vector<double>{0, 0.25, 0.5, 0.75, 1});
  CHECK(call(e, "LinSpace", {n(2), n(3), n(1)}).nums() == std::vector<double>{2});
  CHECK(call(e, "LogSpace", {n(0), n(2), n(3)}).nums() == std::vector<double>{1, 10, 100});
  CHECK(num(e, "Find", {Value::list({1, 2, 3}), Value::list({2, 3, 4})}) == 2);
  CHECK_THROWS_AS(call(e, "LinSpace", {n(0), n(1), n(1e12)}), BuiltinError);
  CHECK_THROWS_AS(call(e, "ListFromFile", {s("/nonexistent/file.txt")}), BuiltinError);
}

TEST_CASE("builtins: strings") {
  Env e;
  CHECK(call(e, "StrCat", {s("a"), s("b"), s("c")}).strs().at(0) == "abc");
  CHECK(call(e, "Str", {s("a"), s("b")}).strs() == std::vector<std::string>{"a", "b"});
  CHECK(call(e, "StrSub", {s("hello"), n(1), n(3)}).strs().at(0) == "ell");
  CHECK(call(e, "StrSub", {s("hello"), n(2)}).strs().at(0) == "llo");
  CHECK_THROWS_AS(call(e, "StrSub", {s("hello"), n(9)}), BuiltinError);
  CHECK(call(e, "StrPrefix", {s("dir.d/file.geo")}).strs().at(0) == "dir.d/file");
  CHECK(call(e, "StrPrefix", {s("dir.d/file")}).strs().at(0) == "dir.d/file");
  CHECK(call(e, "StrRelative", {s("dir/file.geo")}).strs().at(0) == "file.geo");
  CHECK(call(e, "DirName", {s("/a/b/c.geo")}).strs().at(0) == "/a/b/");
  CHECK(call(e, "StrReplace", {s("aXbXc"), s("X"), s("--")}).strs().at(0) == "a--b--c");
  CHECK_THROWS_AS(call(e, "StrReplace", {s("a"), s(""), s("b")}), BuiltinError);
  CHECK(call(e, "UpperCase", {s("abc")}).strs().at(0) == "ABC");
  CHECK(num(e, "StrCmp", {s("a"), s("b")}) == -1);
  CHECK(num(e, "StrFind", {s("hello"), s("ll")}) == 1);
  CHECK(num(e, "StrLen", {s("hello")}) == 5);
  CHECK(call(e, "Sprintf", {s("%g-%g"), Value::list({1, 2})}).strs().at(0) == "1-2");
  CHECK_THROWS_AS(call(e, "Sprintf", {s("%g %g"), n(1)}), BuiltinError);
  CHECK(call(e, "AbsolutePath", {s("x/y.geo")}).strs().at(0) == "/data/scripts/x/y.geo");
}

TEST_CASE("builtins: ONELAB-style parameters") {
  Env e;
  CHECK(num(e, "GetNumber", {s("p"), n(3)}) == 3);
  CHECK_THROWS_AS(call(e, "GetNumber", {s("p")}), BuiltinError);
  call(e, "SetNumber", {s("p"), n(9)});
  CHECK(num(e, "GetNumber", {s("p")}) == 9);
  call(e, "SetString", {s("q"), s("v")});
  CHECK(call(e, "GetString", {s("q")}).strs().at(0) == "v");
  CHECK(num(e, "GetValue", {s("prompt"), n(42)}) == 42);
}

TEST_CASE("builtins: constants") {
  double v = 0;
  CHECK(builtin_number_constant("Pi", v));
  CHECK(v == doctest::Approx(M_PI));
  CHECK(builtin_number_constant("GMSH_MAJOR_VERSION", v));
  CHECK(v == 4);
  CHECK_FALSE(builtin_number_constant("Nope", v));
  Env e;
  std::string str;
  CHECK(builtin_string_constant("CurrentDirectory", e.env, str));
  CHECK(str == "/data/scripts/");
  CHECK(builtin_string_constant("CurrentFileName", e.env, str));
  CHECK(str == "main.geo");
}

TEST_CASE("builtins: Today is laid out as Gmsh prints it (ctime: the day padded with a space)") {
  std::tm t{};
  t.tm_year = 2026 - 1900;
  t.tm_mon = 11;
  t.tm_mday = 2;
  t.tm_wday = 3;
  t.tm_hour = 9;
  t.tm_min = 5;
  t.tm_sec = 3;
  CHECK(gmsh_today(t) == "Wed Dec  2 09:05:03 2026");
  t.tm_mday = 12;
  t.tm_wday = 6;
  CHECK(gmsh_today(t) == "Sat Dec 12 09:05:03 2026");
}
