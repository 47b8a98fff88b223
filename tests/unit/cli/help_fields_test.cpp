// --help-fields: parsed without an input file; what it prints is
// registry_markdown(), the text docs/fields.md's reference is checked against.
#include <doctest/doctest.h>

#include "cli/args.h"

using sm::cli::parse_args;

TEST_CASE("args: --help-fields needs no input file") {
  const auto r = parse_args({"--help-fields"});
  CHECK(r.ok);
  CHECK(r.args.help_fields);
  CHECK_FALSE(r.args.help);
  CHECK(sm::cli::usage_text().find("--help-fields") != std::string::npos);
}
