// Located diagnostics: kinds from diag_kinds.def, notes ("called from", "opened
// here"), an error limit, and clang-style rendering with the source line and a caret.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "lang/diag_format.h"
#include "lang/source.h"

namespace sm::lang {

enum class Severity : std::uint8_t { Error, Warning, Note };

struct DiagInfo {
  Severity severity;
  std::string_view kebab;   ///< "expected-semicolon"
  std::string_view format;  ///< fmt format string
};
const DiagInfo& diag_info(Diag kind);
/// The kind whose kebab name is `kebab`, or Diag::kCount.
Diag diag_from_kebab(std::string_view kebab);
std::string_view severity_name(Severity s);  // "error", "warning", "note"

struct DiagNote {
  SourceRange range;  ///< invalid: rendered without a location
  std::string message;
};

/// The parts of a diagnostic that is one of many of its statement (a coastline import
/// reports one per repaired place): a grouped listing shows the place and the figure and
/// counts the diagnostics by `what`; --diagnostics FILE writes them as fields.
struct DiagItem {
  std::string what;         ///< the sort of thing ("strait narrower than the accuracy kept open"), or ""
  std::string figure;       ///< the figure that matters ("width 1234 m"), or ""
  bool has_lonlat = false;  ///< lon/lat (degrees) are the place it is about
  double lon = 0, lat = 0;
  /// The figure as a number when the largest matter most (a closed passage's width, a
  /// dropped sea's area): a cut group lists the largest of its sort first; NaN: in order.
  double rank = std::numeric_limits<double>::quiet_NaN();
};

struct Diagnostic {
  Diag kind = Diag::kCount;
  Severity severity = Severity::Error;
  SourceRange range;
  std::string message;  ///< formatted, without the [kebab] suffix
  std::vector<DiagNote> notes;
  DiagItem item;
};

/// Collects diagnostics for one run. Errors are counted; after max_errors
/// errors one "too many errors" error is added and later reports are dropped
/// (the parser checks too_many_errors() and stops).
class Diagnostics {
 public:
  static constexpr std::size_t kDefaultMaxErrors = 50;

  /// Attaches notes to the diagnostic just reported; a no-op handle when that
  /// report was dropped by the error limit.
  class Handle {
   public:
    Handle& note(SourceRange range, std::string message);
    /// Sets the diagnostic's place and figure (see DiagItem).
    Handle& item(DiagItem item);
    bool dropped() const { return index_ == kDropped; }

   private:
    friend class Diagnostics;
    static constexpr std::size_t kDropped = ~std::size_t{0};
    Handle(Diagnostics* owner, std::size_t index) : owner_(owner), index_(index) {}
    Diagnostics* owner_;
    std::size_t index_;
  };

  explicit Diagnostics(const SourceManager& sources) : sources_(&sources) {}

  /// diags.report(tok.range, Diag::UnknownField, name): formats the kind's message with
  /// `args`, whose number and types are checked against the format at compile time.
  template <class... Args>
  Handle report(SourceRange range, std::type_identity_t<DiagFormat<Args...>> kind, const Args&... args) {
    return report_message(range, kind.kind(), format_diag<Args...>(kind, args...));
  }
  /// Reports with an already formatted message.
  Handle report_message(SourceRange range, Diag kind, std::string message);

  std::size_t error_count() const { return errors_; }
  std::size_t warning_count() const { return warnings_; }
  bool too_many_errors() const { return stopped_; }
  void set_max_errors(std::size_t n) { max_errors_ = n; }  ///< 0: no limit
  std::size_t max_errors() const { return max_errors_; }

  const std::vector<Diagnostic>& all() const { return diags_; }
  const SourceManager& sources() const { return *sources_; }

  /// clang-style text of one diagnostic and its notes (ends with '\n').
  std::string render(const Diagnostic& d) const;
  /// All diagnostics in report order.
  std::string render_all() const;
  /// Writes the diagnostics not written by an earlier flush (so a driver can
  /// stream them while a script runs) and returns how many were written.
  std::size_t flush(std::FILE* out);

  /// Where diagnostics go as a run reports them (the CLI prints them on stderr), while
  /// all() keeps collecting them for the --test driver and the unit tests. The sink gets
  /// them a statement at a time, so that it can group the many of one statement.
  using Sink = std::function<void(std::span<const Diagnostic>)>;
  void set_sink(Sink sink) { sink_ = std::move(sink); }
  /// Hands the diagnostics reported since the last flush/emit to the sink, in report
  /// order and in one call, and returns how many; nothing without a sink. The
  /// interpreter calls it after each statement, once the statement's notes are attached.
  std::size_t emit_pending();

 private:
  const SourceManager* sources_;
  std::vector<Diagnostic> diags_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t max_errors_ = kDefaultMaxErrors;
  std::size_t flushed_ = 0;
  bool stopped_ = false;
  Sink sink_;
};

/// "file:line:col" of a location (or "<unknown>"), as used in messages.
std::string format_location(const SourceManager& sources, SourceLoc loc);

}  // namespace sm::lang
