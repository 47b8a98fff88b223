// Diagnostics: the kind table from diag_kinds.def, the error limit, and the
// clang-style rendering (location, message [kind], source line, caret/tildes).
#include "lang/diagnostics.h"

#include <algorithm>
#include <array>

#include "base/utf8.h"

namespace sm::lang {

namespace {

constexpr std::array<DiagInfo, static_cast<std::size_t>(Diag::kCount)> kDiagInfo = {{
#define DIAG(name, severity, kebab, format) DiagInfo{Severity::severity, kebab, format},
#include "lang/diag_kinds.def"
#undef DIAG
}};

// Longest part of a source line shown under a message; longer lines are cut
// to a window around the caret so a 200 MB line costs nothing to print.
constexpr std::size_t kMaxShownLine = 160;
constexpr std::size_t kContextBeforeCaret = 60;

// Appends the printable form of s[b, e) to `shown`, and to `marks` one char per
// displayed column ('\t' for a tab so that the caret line stays aligned).
void append_display(std::string_view s, std::size_t b, std::size_t e, std::string& shown,
                    std::vector<std::size_t>& col_of_byte, std::size_t& col) {
  for (std::size_t i = b; i < e;) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t len = 1;
    if (c == '\t') {
      shown += '\t';
    } else if (c < 0x20 || c == 0x7F) {
      shown += '?';
    } else if (c < 0x80) {
      shown += static_cast<char>(c);
    } else if (std::size_t n = base::utf8_sequence_length(s, i); n > 0 && i + n <= e) {
      shown.append(s.substr(i, n));
      len = n;
    } else {
      shown += '?';
    }
    for (std::size_t k = 0; k < len; ++k) col_of_byte[i - b + k] = col;
    ++col;
    i += len;
  }
}

}  // namespace

const DiagInfo& diag_info(Diag kind) {
  const auto i = static_cast<std::size_t>(kind);
  return kDiagInfo[i < kDiagInfo.size() ? i : 0];
}

Diag diag_from_kebab(std::string_view kebab) {
  for (std::size_t i = 0; i < kDiagInfo.size(); ++i)
    if (kDiagInfo[i].kebab == kebab) return static_cast<Diag>(i);
  return Diag::kCount;
}

std::string_view severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

Diagnostics::Handle& Diagnostics::Handle::note(SourceRange range, std::string message) {
  if (index_ != kDropped) owner_->diags_[index_].notes.push_back({range, std::move(message)});
  return *this;
}

Diagnostics::Handle& Diagnostics::Handle::item(DiagItem item) {
  if (index_ != kDropped) owner_->diags_[index_].item = std::move(item);
  return *this;
}

Diagnostics::Handle Diagnostics::report_message(SourceRange range, Diag kind, std::string message) {
  if (stopped_) return Handle(this, Handle::kDropped);
  const Severity sev = diag_info(kind).severity;
  if (sev == Severity::Error && max_errors_ != 0 && errors_ >= max_errors_) {
    stopped_ = true;
    diags_.push_back({Diag::TooManyErrors, Severity::Error, range,
                      format_diag<std::size_t>(Diag::TooManyErrors, errors_), {}, {}});
    ++errors_;
    return Handle(this, Handle::kDropped);
  }
  if (sev == Severity::Error) ++errors_;
  if (sev == Severity::Warning) ++warnings_;
  diags_.push_back({kind, sev, range, std::move(message), {}, {}});
  return Handle(this, diags_.size() - 1);
}

std::string format_location(const SourceManager& sources, SourceLoc loc) {
  if (!loc.file.valid() || loc.file.value >= sources.file_count()) return "<unknown>";
  const LineCol lc = sources.line_col(loc);
  return fmt::format("{}:{}:{}", sources.path(loc.file), lc.line, lc.col);
}

namespace {

// "   14 | text\n      |    ^~~~\n" for the first line of `range`.
void render_snippet(const SourceManager& sources, SourceRange range, std::string& out) {
  if (!range.valid() || range.file.value >= sources.file_count()) return;
  const LineCol lc = sources.line_col(range.begin_loc());
  const std::string_view line = sources.line_text(range.file, lc.line);
  const std::size_t caret = std::min<std::size_t>(lc.col - 1, line.size());
  std::size_t underline = 1;
  if (range.end > range.begin)
    underline = std::max<std::size_t>(1, std::min<std::size_t>(range.end - range.begin, line.size() - caret));

  std::size_t b = 0, e = line.size();
  if (line.size() > kMaxShownLine) {
    b = caret > kContextBeforeCaret ? caret - kContextBeforeCaret : 0;
    while (b > 0 && (static_cast<unsigned char>(line[b]) & 0xC0) == 0x80) --b;
    e = std::min(line.size(), b + kMaxShownLine);
    while (e < line.size() && e > b && (static_cast<unsigned char>(line[e]) & 0xC0) == 0x80) --e;
  }
  std::string shown;
  std::vector<std::size_t> col_of_byte(e - b + 1, 0);
  std::size_t col = 0;
  if (b > 0) {
    shown += "...";
    col = 3;
  }
  append_display(line, b, e, shown, col_of_byte, col);
  col_of_byte[e - b] = col;  // one past the end (caret at end of line)
  if (e < line.size()) shown += "...";

  out += fmt::format("{:>5} | {}\n      | ", lc.line, shown);
  const std::size_t caret_col = col_of_byte[std::min(caret, e) - b];
  if (b > 0) out += "   ";
  for (std::size_t i = b; i < std::min(caret, e); ++i) {  // tabs copied so the caret aligns
    if (i > b && col_of_byte[i - b] == col_of_byte[i - b - 1]) continue;  // inside a UTF-8 char
    out += line[i] == '\t' ? '\t' : ' ';
  }
  out += '^';
  const std::size_t end_byte = std::min(caret + underline, e);
  const std::size_t end_col = end_byte > caret ? col_of_byte[end_byte - b] : caret_col + 1;
  for (std::size_t c = caret_col + 1; c < end_col; ++c) out += '~';
  out += '\n';
}

}  // namespace

std::string Diagnostics::render(const Diagnostic& d) const {
  std::string out;
  if (d.range.valid()) out += format_location(*sources_, d.range.begin_loc()) + ": ";
  out += fmt::format("{}: {}", severity_name(d.severity), d.message);
  if (d.kind != Diag::kCount && d.severity != Severity::Note) out += fmt::format(" [{}]", diag_info(d.kind).kebab);
  out += '\n';
  render_snippet(*sources_, d.range, out);
  for (const DiagNote& n : d.notes) {
    if (n.range.valid()) out += format_location(*sources_, n.range.begin_loc()) + ": ";
    out += "note: " + n.message + "\n";
  }
  return out;
}

std::string Diagnostics::render_all() const {
  std::string out;
  for (const Diagnostic& d : diags_) out += render(d);
  return out;
}

std::size_t Diagnostics::flush(std::FILE* out) {
  const std::size_t n = diags_.size() - flushed_;
  for (; flushed_ < diags_.size(); ++flushed_) {
    const std::string s = render(diags_[flushed_]);
    std::fwrite(s.data(), 1, s.size(), out);
  }
  std::fflush(out);
  return n;
}

std::size_t Diagnostics::emit_pending() {
  if (!sink_) return 0;
  // A copy (the sink may report more), and the cursor moved before the call, so that a
  // sink which reports (or throws) does not see the same diagnostic twice.
  const std::vector<Diagnostic> batch(diags_.begin() + static_cast<std::ptrdiff_t>(flushed_), diags_.end());
  flushed_ = diags_.size();
  if (!batch.empty()) sink_(batch);
  return batch.size();
}

}  // namespace sm::lang
