// Every command-line flag of stereomesh, declared once: parse_args (args.cpp) accepts
// only the names listed here, --help is written from this table, and docs/interpreter.md's
// command-line section carries that help verbatim (tests/unit/cli/help_docs_test.cpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sm::cli {

struct CliFlag {
  std::vector<std::string_view> names;  ///< every spelling: "--help", "-help", "-h"
  std::string_view shown;               ///< as --help shows it: "-o FILE", "-1, -2"
  std::string help;                     ///< what it does, one paragraph (wrapped by usage_text)
};

/// The table, in --help's order.
const std::vector<CliFlag>& cli_flags();

/// The entry with `name` among its names, or null (an unknown option).
const CliFlag* find_flag(std::string_view name);

}  // namespace sm::cli
