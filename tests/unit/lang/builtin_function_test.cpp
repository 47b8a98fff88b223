// The builtin-function table (lang/builtin_functions.def): lookup, what the
// parser decides from it, and docs/interpreter.md carrying its rendering
// verbatim (rewritten when the environment variable SM_UPDATE_BUILTIN_DOCS is set).
#include <doctest/doctest.h>

#include <sstream>

#include "lang/builtin_function.h"
#include "lang_test_util.h"
#include "generated_docs.h"

using namespace sm::lang;
using sm::lang::testing::ast_of;

TEST_CASE("builtin table: lookup by exact name") {
  const BuiltinId sqrt_id = find_builtin_function("Sqrt");
  REQUIRE(sqrt_id != BuiltinId::kNone);
  CHECK(builtin_function(sqrt_id).name == "Sqrt");
  CHECK(builtin_function(sqrt_id).result == BuiltinResult::Num);
  CHECK(builtin_function(BuiltinId::StrCat).result == BuiltinResult::Str);
  CHECK(builtin_function(BuiltinId::DefineNumber).pass == BuiltinPass::Onelab);
  CHECK(find_builtin_function("sqrt") == BuiltinId::kNone);
  CHECK(find_builtin_function("") == BuiltinId::kNone);
  CHECK(find_builtin_function("Zzz") == BuiltinId::kNone);
  for (std::size_t i = 0; i < builtin_functions().size(); ++i)
    CHECK(find_builtin_function(builtin_functions()[i].name) == static_cast<BuiltinId>(i));
}

TEST_CASE("builtin table: names Gmsh 4.8.4 does not have are no calls") {
  // They used to parse as calls that no implementation answered; `gmsh -0`
  // reads them as variables too ("Unknown variable 'Norm'").
  for (const char* name : {"Norm", "Hypot3", "Sign", "Total", "StrSplit"}) {
    CAPTURE(name);
    CHECK(find_builtin_function(name) == BuiltinId::kNone);
    CHECK(ast_of(std::string("x = ") + name + "(1);") == std::string("(assign = x (index ") + name + " 1))");
  }
}

TEST_CASE("builtin table: a string-valued call names a macro") {
  CHECK(ast_of("Call StrCat(\"a\", \"b\");").find("(call StrCat") != std::string::npos);
  CHECK(ast_of("x = DefineNumber[1, Name \"p\", Min 0];") == "(assign = x (call DefineNumber 1))");
}

TEST_CASE("docs/interpreter.md holds the generated builtin reference") {
  sm::testing::check_generated_section(std::string(SM_SOURCE_DIR) + "/docs/interpreter.md",
                                       "<!-- BEGIN GENERATED: sm::lang::builtin_functions_markdown() -->\n",
                                       "<!-- END GENERATED -->", builtin_functions_markdown(),
                                       "SM_UPDATE_BUILTIN_DOCS");
}
