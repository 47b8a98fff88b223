// GMT multi-segment lon/lat text reader (format in shared/data/README.md).
#include "coast/read_lonlat_text.h"

#include <fmt/format.h>

#include "coast/file_bytes.h"
#include "coast/text_scan.h"

namespace sm::coast {
namespace {

using detail::next_line;

// Value of "key=" among the words of a header/comment line, empty when absent.
std::string_view word_value(std::string_view line, std::string_view key) {
  std::size_t pos = 0;
  while ((pos = line.find(key, pos)) != std::string_view::npos) {
    const bool starts_word = pos == 0 || line[pos - 1] == ' ' || line[pos - 1] == '\t' || line[pos - 1] == '>';
    if (starts_word && pos + key.size() < line.size() && line[pos + key.size()] == '=') {
      std::string_view v = line.substr(pos + key.size() + 1);
      const std::size_t e = v.find_first_of(" \t");
      return v.substr(0, e);
    }
    pos += key.size();
  }
  return {};
}

bool parse_count(std::string_view v, long long& out) {
  return !v.empty() && detail::take_long(v, out) && detail::only_space_left(v) && out >= 0;
}

// "-Rw/e/s/n" anywhere in the line.
std::optional<LonLatBox> parse_region(std::string_view line) {
  const std::size_t p = line.find("-R");
  if (p == std::string_view::npos) return std::nullopt;
  std::string_view s = line.substr(p + 2);
  double v[4];
  for (int i = 0; i < 4; ++i) {
    if (i > 0) {
      if (s.empty() || s.front() != '/') return std::nullopt;
      s.remove_prefix(1);
    }
    if (!detail::take_double(s, v[i])) return std::nullopt;
  }
  if (!(v[0] < v[1] && v[2] < v[3])) return std::nullopt;
  return LonLatBox{v[0], v[1], v[2], v[3]};
}

struct Pending {
  Ring ring;
  long long npts = -1;     // announced, -1 when the header has none
  int closed_word = -1;    // 0/1 from the header, -1 when absent
  std::size_t line = 0;
};

}  // namespace

Result<Coastline> read_lonlat_text_string(std::string_view text, const std::string& name) {
  Coastline out;
  out.file = name;
  long long want_segments = -1, want_points = -1, want_closed = -1, want_open = -1;
  std::optional<Pending> cur;
  std::size_t lineno = 0, comment_lines = 0;
  long long total_points = 0;

  auto finish = [&](std::size_t at_line) -> std::optional<CoastError> {
    if (!cur) return std::nullopt;
    Pending& s = *cur;
    const auto rec = static_cast<std::int64_t>(s.ring.record);
    if (s.npts >= 0 && static_cast<long long>(s.ring.pts.size()) != s.npts)
      return CoastError{name, rec,
                        fmt::format("segment header (line {}) announces npts={} but {} points follow "
                                    "before line {}",
                                    s.line, s.npts, s.ring.pts.size(), at_line),
                        {}};
    if (s.closed_word >= 0) {
      s.ring.closed = s.closed_word == 1;
    } else {
      s.ring.closed = s.ring.pts.size() >= 3 && same_point(s.ring.pts.front(), s.ring.pts.back());
    }
    total_points += static_cast<long long>(s.ring.pts.size());
    normalise_ring(s.ring);
    out.rings.push_back(std::move(s.ring));
    cur.reset();
    return std::nullopt;
  };

  // A file cut inside its last number would otherwise read as a slightly different
  // point: an unterminated last data line is an error.
  if (!text.empty() && text.back() != '\n') {
    const std::size_t nl = text.rfind('\n');
    std::string_view last = text.substr(nl == std::string_view::npos ? 0 : nl + 1);
    detail::skip_space(last);
    if (!last.empty() && last.front() != '#')
      return CoastError{name, -1, "the last line has no end of line: the file looks truncated", {}};
  }
  std::string_view line;
  while (next_line(text, line)) {
    ++lineno;
    std::string_view t = line;
    detail::skip_space(t);
    if (t.empty()) continue;
    if (t.front() == '#') {
      ++comment_lines;
      if (comment_lines == 1 && !out.region) out.region = parse_region(t);
      long long v;
      if (parse_count(word_value(t, "segments"), v)) want_segments = v;
      if (parse_count(word_value(t, "points"), v)) want_points = v;
      if (parse_count(word_value(t, "closed"), v)) want_closed = v;
      if (parse_count(word_value(t, "open"), v)) want_open = v;
      continue;
    }
    if (t.front() == '>') {
      if (auto e = finish(lineno)) return *e;
      cur.emplace();
      cur->line = lineno;
      cur->ring.record = out.rings.size();
      cur->ring.id = static_cast<std::int64_t>(out.rings.size()) + 1;
      long long v;
      const std::string_view seg = word_value(t, "seg");
      if (!seg.empty() && parse_count(seg, v)) cur->ring.id = v;
      const std::string_view lv = word_value(t, "level");
      if (!lv.empty()) {
        if (!parse_count(lv, v) || v < 1 || v > 6)
          return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                            fmt::format("line {}: bad level '{}'", lineno, lv), {}};
        cur->ring.level = static_cast<int>(v);
      }
      const std::string_view np = word_value(t, "npts");
      if (!np.empty()) {
        if (!parse_count(np, v))
          return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                            fmt::format("line {}: bad npts '{}'", lineno, np), {}};
        // An absurd count is caught by the bound below before anything is reserved.
        if (v > static_cast<long long>(text.size() / 4 + 1))
          return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                            fmt::format("line {}: npts={} cannot fit in the rest of the file", lineno, v), {}};
        cur->npts = v;
        cur->ring.pts.reserve(static_cast<std::size_t>(v));
      }
      const std::string_view cl = word_value(t, "closed");
      if (!cl.empty()) {
        if (cl != "0" && cl != "1")
          return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                            fmt::format("line {}: closed must be 0 or 1, not '{}'", lineno, cl), {}};
        cur->closed_word = cl == "1" ? 1 : 0;
      }
      continue;
    }
    if (!cur) {  // points before any header: one implicit segment (plain GMT xy files)
      cur.emplace();
      cur->line = lineno;
      cur->ring.record = out.rings.size();
      cur->ring.id = static_cast<std::int64_t>(out.rings.size()) + 1;
    }
    double lon, lat;
    if (!detail::take_double(t, lon) || !detail::take_double(t, lat) || !detail::only_space_left(t))
      return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                        fmt::format("line {}: expected two finite numbers 'lon lat', got '{}'", lineno,
                                    line.substr(0, 60)),
                        {}};
    if (lat < -90 || lat > 90 || lon < -540 || lon > 540)
      return CoastError{name, static_cast<std::int64_t>(cur->ring.record),
                        fmt::format("line {}: point off the globe", lineno), geo::LonLat{lon, lat}};
    cur->ring.pts.push_back({lon, lat});
  }
  if (auto e = finish(lineno + 1)) return *e;

  long long closed = 0;
  for (const Ring& r : out.rings) closed += r.closed ? 1 : 0;
  const long long nseg = static_cast<long long>(out.rings.size());
  auto mismatch = [&](const char* what, long long want, long long got) {
    return CoastError{name, -1,
                      fmt::format("the header announces {}={} but the file holds {} (truncated or edited file)",
                                  what, want, got),
                      {}};
  };
  if (want_segments >= 0 && want_segments != nseg) return mismatch("segments", want_segments, nseg);
  if (want_points >= 0 && want_points != total_points) return mismatch("points", want_points, total_points);
  if (want_closed >= 0 && want_closed != closed) return mismatch("closed", want_closed, closed);
  if (want_open >= 0 && want_open != nseg - closed) return mismatch("open", want_open, nseg - closed);
  if (out.rings.empty()) return CoastError{name, -1, "no segment in file", {}};
  return out;
}

Result<Coastline> read_lonlat_text(const std::string& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return read_lonlat_text_string(text, path);
}

}  // namespace sm::coast
