// Diagnostics printed as a run reports them: on stderr, after the
// Printf output written so far and around the live progress line, as Gmsh does.
#pragma once

#include <cstdio>
#include <functional>
#include <ostream>

#include "cli/terminal_progress.h"
#include "lang/diagnostics.h"

namespace sm::cli {

/// A Diagnostics::Sink that renders each diagnostic to `err`. Before writing it flushes
/// `out` and `out_file` (Printf's stream and the FILE* beneath it) so that a terminal or
/// `2>&1` shows the real order, and it clears the live progress line while it writes.
class DiagnosticStream {
 public:
  DiagnosticStream(const lang::Diagnostics& diags, std::FILE* err, std::ostream& out, std::FILE* out_file,
                   TerminalProgress* progress = nullptr)
      : diags_(&diags), err_(err), out_(&out), out_file_(out_file), progress_(progress) {}

  /// Asked for each warning: false drops it (General.Verbosity < 2). Errors always print.
  void set_show_warnings(std::function<bool()> show) { show_warnings_ = std::move(show); }

  void operator()(const lang::Diagnostic& d) const;

 private:
  const lang::Diagnostics* diags_;
  std::FILE* err_;
  std::ostream* out_;
  std::FILE* out_file_;
  TerminalProgress* progress_;
  std::function<bool()> show_warnings_;
};

}  // namespace sm::cli
