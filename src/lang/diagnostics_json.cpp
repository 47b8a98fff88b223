// Diagnostics as JSON lines (see diagnostics_json.h).
#include "lang/diagnostics_json.h"

#include <cmath>

#include <fmt/format.h>

#include "base/json_text.h"

namespace sm::lang {

namespace {

using base::json_number;
using base::json_string;

// "\"file\": ..., \"line\": ..., \"col\": ..." of a location (nulls without one).
std::string location_fields(const SourceManager& sources, SourceRange range) {
  if (!range.valid() || range.file.value >= sources.file_count())
    return "\"file\": null, \"line\": null, \"col\": null";
  const LineCol lc = sources.line_col(range.begin_loc());
  return fmt::format("\"file\": {}, \"line\": {}, \"col\": {}", json_string(sources.path(range.file)), lc.line,
                     lc.col);
}

}  // namespace

std::string diagnostic_json_line(const SourceManager& sources, const Diagnostic& d) {
  std::string out = fmt::format("{{{}", location_fields(sources, d.range));
  out += fmt::format(", \"severity\": {}, \"kind\": {}, \"message\": {}", json_string(severity_name(d.severity)),
                     json_string(d.kind == Diag::kCount ? std::string_view() : diag_info(d.kind).kebab),
                     json_string(d.message));
  if (d.item.has_lonlat)
    out += fmt::format(", \"lon\": {}, \"lat\": {}", json_number(d.item.lon), json_number(d.item.lat));
  if (!d.item.what.empty()) out += fmt::format(", \"what\": {}", json_string(d.item.what));
  if (!d.item.figure.empty()) out += fmt::format(", \"figure\": {}", json_string(d.item.figure));
  if (std::isfinite(d.item.rank)) out += fmt::format(", \"value\": {}", json_number(d.item.rank));
  if (!d.notes.empty()) {
    out += ", \"notes\": [";
    for (std::size_t i = 0; i < d.notes.size(); ++i)
      out += fmt::format("{}{{{}, \"message\": {}}}", i ? ", " : "", location_fields(sources, d.notes[i].range),
                         json_string(d.notes[i].message));
    out += "]";
  }
  out += "}\n";
  return out;
}

}  // namespace sm::lang
