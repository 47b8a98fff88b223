// docs/fields.md carries the registry's reference verbatim: this test fails
// when they drift apart, and rewrites the generated part when the
// environment variable SM_UPDATE_FIELD_DOCS is set.
#include <string>

#include <doctest/doctest.h>

#include "field/registry.h"
#include "generated_docs.h"

TEST_CASE("docs/fields.md holds the generated field reference") {
  sm::testing::check_generated_section(
      std::string(SM_SOURCE_DIR) + "/docs/fields.md", "<!-- BEGIN GENERATED: sm::field::registry_markdown() -->\n",
      "<!-- END GENERATED -->", sm::field::registry_markdown(), "SM_UPDATE_FIELD_DOCS");
}
