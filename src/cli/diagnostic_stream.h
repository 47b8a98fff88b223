// Diagnostics printed as a run reports them: on stderr, after the
// Printf output written so far and around the live progress line, as Gmsh does.
#pragma once

#include <cstdio>
#include <functional>
#include <ostream>
#include <span>

#include "cli/terminal_progress.h"
#include "lang/diagnostics.h"

namespace sm::cli {

/// The General.Verbosity from which a statement's many diagnostics are all listed
/// rather than counted with a few examples (one above Gmsh's default of 5).
inline constexpr double kVerbosityListAll = 6;

/// A Diagnostics::Sink that renders a statement's diagnostics to `err`, the many of one
/// location grouped (lang/diagnostic_groups.h). Before writing it flushes `out` and
/// `out_file` (Printf's stream and the FILE* beneath it) so that a terminal or `2>&1`
/// shows the real order, and it clears the live progress line while it writes.
class DiagnosticStream {
 public:
  DiagnosticStream(const lang::Diagnostics& diags, std::FILE* err, std::ostream& out, std::FILE* out_file,
                   TerminalProgress* progress = nullptr)
      : diags_(&diags), err_(err), out_(&out), out_file_(out_file), progress_(progress) {}

  /// Asked for each batch with warnings: false drops them (General.Verbosity < 2). Errors
  /// always print.
  void set_show_warnings(std::function<bool()> show) { show_warnings_ = std::move(show); }
  /// Asked for each batch: true lists every member of a group (General.Verbosity >=
  /// kVerbosityListAll); otherwise a group is cut and says how to see it whole.
  void set_list_all(std::function<bool()> list_all) { list_all_ = std::move(list_all); }

  void operator()(std::span<const lang::Diagnostic> batch) const;

 private:
  const lang::Diagnostics* diags_;
  std::FILE* err_;
  std::ostream* out_;
  std::FILE* out_file_;
  TerminalProgress* progress_;
  std::function<bool()> show_warnings_;
  std::function<bool()> list_all_;
};

}  // namespace sm::cli
