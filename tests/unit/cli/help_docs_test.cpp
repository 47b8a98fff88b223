// --help comes from the flag table (cli/flags.h), which is every flag parse_args knows,
// and docs/interpreter.md's command-line section carries that help verbatim: this test
// fails when they drift apart, and rewrites the generated part when the environment
// variable SM_UPDATE_CLI_DOCS is set.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "cli/args.h"
#include "cli/flags.h"
#include "generated_docs.h"

TEST_CASE("cli flags: every flag of the table is parsed, every spelling is in --help") {
  const std::string help = sm::cli::usage_text();
  for (const sm::cli::CliFlag& f : sm::cli::cli_flags()) {
    CHECK_MESSAGE(help.find(std::string(f.shown)) != std::string::npos, f.shown);
    for (std::string_view name : f.names) {
      // Values a flag may take (two for -setnumber), then a script.
      const auto r = sm::cli::parse_args({std::string(name), "1", "1", "x.geo"});
      INFO(name, ": ", r.error);
      CHECK(r.error.find("unknown option") == std::string::npos);
      CHECK(r.error.find("not implemented") == std::string::npos);
    }
  }
  // A name outside the table is refused, whatever it looks like.
  const auto r = sm::cli::parse_args({"--diagnostic", "x.json", "x.geo"});
  CHECK_FALSE(r.ok);
  CHECK(r.error == "unknown option '--diagnostic'");
}

TEST_CASE("cli flags: --help lines stay within 100 columns") {
  std::istringstream in(sm::cli::usage_text());
  for (std::string line; std::getline(in, line);) CHECK_MESSAGE(line.size() <= 100, line);
}

TEST_CASE("docs/interpreter.md holds the generated --help") {
  sm::testing::check_generated_section(std::string(SM_SOURCE_DIR) + "/docs/interpreter.md",
                                       "<!-- BEGIN GENERATED: stereomesh --help (sm::cli::usage_text()) -->\n```text\n",
                                       "```\n<!-- END GENERATED -->", sm::cli::usage_text(), "SM_UPDATE_CLI_DOCS");
}
