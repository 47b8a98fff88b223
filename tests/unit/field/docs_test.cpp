// docs/fields.md carries the registry's reference verbatim: this test fails
// when they drift apart, and rewrites the generated part when the
// environment variable SM_UPDATE_FIELD_DOCS is set.
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <doctest/doctest.h>

#include "field/registry.h"

TEST_CASE("docs/fields.md holds the generated field reference") {
  const std::string path = std::string(SM_SOURCE_DIR) + "/docs/fields.md";
  std::ifstream in(path);
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::string begin = "<!-- BEGIN GENERATED: sm::field::registry_markdown() -->\n";
  const std::string end = "<!-- END GENERATED -->";
  const auto b = text.find(begin), e = text.find(end);
  REQUIRE(b != std::string::npos);
  REQUIRE(e != std::string::npos);
  const std::string current = text.substr(b + begin.size(), e - b - begin.size());
  const std::string generated = sm::field::registry_markdown();
  if (std::getenv("SM_UPDATE_FIELD_DOCS") && current != generated) {
    std::ofstream out(path);
    out << text.substr(0, b + begin.size()) << generated << text.substr(e);
    return;
  }
  CHECK_MESSAGE(current == generated,
                "docs/fields.md is stale: run SM_UPDATE_FIELD_DOCS=1 build/tests/unit_field");
}
