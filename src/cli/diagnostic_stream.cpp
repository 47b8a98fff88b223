// Printing diagnostics while a run goes on (see diagnostic_stream.h).
#include "cli/diagnostic_stream.h"

#include <string>

namespace sm::cli {

void DiagnosticStream::operator()(const lang::Diagnostic& d) const {
  if (d.severity == lang::Severity::Warning && show_warnings_ && !show_warnings_()) return;
  out_->flush();
  if (out_file_) std::fflush(out_file_);
  if (progress_) progress_->suspend();
  // Diagnostics of the command line itself (no script location) say who speaks.
  std::string text = d.range.valid() ? std::string() : std::string("stereomesh: ");
  text += diags_->render(d);
  std::fwrite(text.data(), 1, text.size(), err_);
  std::fflush(err_);
  if (progress_) progress_->resume();
}

}  // namespace sm::cli
