// The check behind every generated part of the docs (docs/fields.md's field reference,
// docs/interpreter.md's builtins and --help): the text between a begin marker and the
// first end marker after it must be what the program generates now.
#pragma once

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <doctest/doctest.h>

namespace sm::testing {

/// Checks that the part of the file `path` between `begin` and the first `end` after it
/// equals `generated`. With the environment variable `update_env` set, a stale part is
/// rewritten instead (the way to refresh the doc), and the check passes.
inline void check_generated_section(const std::string& path, const std::string& begin, const std::string& end,
                                    const std::string& generated, const char* update_env) {
  std::ifstream in(path);
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto b = text.find(begin);
  REQUIRE(b != std::string::npos);
  const auto e = text.find(end, b);
  REQUIRE(e != std::string::npos);
  const std::string current = text.substr(b + begin.size(), e - b - begin.size());
  if (std::getenv(update_env) && current != generated) {
    std::ofstream out(path);
    out << text.substr(0, b + begin.size()) << generated << text.substr(e);
    return;
  }
  const std::string stale = path + " is stale: run " + update_env + "=1 and the unit test again";
  CHECK_MESSAGE(current == generated, stale);
}

}  // namespace sm::testing
