// The script-test driver behind `stereomesh --test`: runs .geo scripts whose
// expected output is written in them (`// expect: 10`) and, for fail_*.geo,
// whose expected diagnostics are (`// expect error: 2:21: expected-semicolon`).
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "interp/interpreter.h"

namespace sm::interp {

struct ScriptExpectations {
  std::vector<std::string> stdout_lines;   ///< in order
  std::vector<std::string> diagnostics;    ///< "L:C: kind" / "warning L:C: kind", sorted
};

/// Reads the `// expect: TEXT`, `// expect error: L:C: kind` and
/// `// expect warning: L:C: kind` comments of a script.
ScriptExpectations parse_expectations(std::string_view text);

struct ScriptTestResult {
  bool passed = false;
  std::string details;   ///< why it failed (empty when passed)
};

/// Runs one script in a fresh interpreter. A script whose file name starts with
/// `fail_` must produce exactly the listed diagnostics; any other script must
/// run without errors. Both must print exactly the expected lines.
ScriptTestResult run_script_test(const std::string& path, const RunSettings& settings);

/// Every *.geo under each path (recursively, sorted; a file path is taken as
/// is), one line per failure with its details, then exactly "N passed, N
/// failed". Returns the number of failures (-1 when a path does not exist).
int run_script_tests(const std::vector<std::string>& paths, const RunSettings& settings,
                     std::ostream& out);

}  // namespace sm::interp
