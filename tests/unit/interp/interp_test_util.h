// Runs a script held in a string through a fresh interpreter and returns its
// Printf output and diagnostic kinds, for the evaluator tests.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.h"

namespace sm::interp::testing {

struct RunOutput {
  std::string out;                  ///< Printf lines
  std::vector<std::string> kinds;   ///< "line:col kind" of every error/warning
  std::string rendered;             ///< the diagnostics as the CLI prints them
  bool ok = false;                  ///< no error reported
  int exit_request = -1;
};

inline RunOutput run_script(const std::string& text, const std::string& name = "test.geo",
                            RunSettings settings = {}) {
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream out;
  // The binary finds its stdlib beside itself; a test binary takes the source tree's.
  if (settings.stdlib_dir.empty()) settings.stdlib_dir = SM_SOURCE_DIR "/stdlib";
  Interpreter in(sources, diags, out, settings);
  in.run_buffer(name, text);
  RunOutput r;
  r.out = out.str();
  for (const auto& d : diags.all()) {
    if (d.severity == lang::Severity::Note) continue;
    const lang::LineCol lc = d.range.valid() ? sources.line_col(d.range.begin_loc()) : lang::LineCol{};
    r.kinds.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.col) + " " +
                      std::string(lang::diag_info(d.kind).kebab));
  }
  r.rendered = diags.render_all();
  r.ok = diags.error_count() == 0;
  r.exit_request = in.exit_request();
  return r;
}

}  // namespace sm::interp::testing
