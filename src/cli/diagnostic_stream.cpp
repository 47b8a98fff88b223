// Printing diagnostics while a run goes on (see diagnostic_stream.h).
#include "cli/diagnostic_stream.h"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "lang/diagnostic_groups.h"

namespace sm::cli {

void DiagnosticStream::operator()(std::span<const lang::Diagnostic> batch) const {
  const bool hide_warnings = show_warnings_ && !show_warnings_();
  std::vector<lang::Diagnostic> shown;
  for (const lang::Diagnostic& d : batch)
    if (!(hide_warnings && d.severity == lang::Severity::Warning)) shown.push_back(d);
  if (shown.empty()) return;
  out_->flush();
  if (out_file_) std::fflush(out_file_);
  if (progress_) progress_->suspend();
  lang::GroupRenderOptions options;
  options.list_all = list_all_ && list_all_();
  const std::string see_all = fmt::format("-v {:g} lists every one, --diagnostics FILE writes them as JSON lines",
                                          kVerbosityListAll);
  options.how_to_see_all = see_all;
  // Diagnostics of the command line itself (no script location) say who speaks.
  options.unlocated_prefix = "stereomesh: ";
  const std::string text = lang::render_grouped(*diags_, shown, options);
  std::fwrite(text.data(), 1, text.size(), err_);
  std::fflush(err_);
  if (progress_) progress_->resume();
}

}  // namespace sm::cli
