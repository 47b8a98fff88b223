// GMT multi-segment lon/lat text reader (format in data/PROVENANCE.md and docs/coastlines.md).
#include "coast/read_lonlat_text.h"

#include <fmt/format.h>

#include "coast/file_blocks.h"
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

// The reader's state from line to line, so that one set of rules reads a text in memory
// and a file read block by block (the whole GSHHG is 225 MB of text: it is never held).
class Parser {
 public:
  Parser(const std::string& name, std::size_t total_bytes) : name_(name), total_bytes_(total_bytes) {
    out_.file = name;
  }

  std::optional<CoastError> line(std::string_view line) {
    ++lineno_;
    std::string_view t = line;
    detail::skip_space(t);
    if (t.empty()) return std::nullopt;
    if (t.front() == '#') {
      ++comment_lines_;
      if (comment_lines_ == 1 && !out_.region) out_.region = parse_region(t);
      long long v;
      if (parse_count(word_value(t, "segments"), v)) want_segments_ = v;
      if (parse_count(word_value(t, "points"), v)) want_points_ = v;
      if (parse_count(word_value(t, "closed"), v)) want_closed_ = v;
      if (parse_count(word_value(t, "open"), v)) want_open_ = v;
      return std::nullopt;
    }
    if (t.front() == '>') return header(t);
    if (!cur_) start_segment();   // points before any header: one implicit segment (plain GMT xy files)
    double lon, lat;
    if (!detail::take_double(t, lon) || !detail::take_double(t, lat) || !detail::only_space_left(t))
      return error(fmt::format("line {}: expected two finite numbers 'lon lat', got '{}'", lineno_,
                               line.substr(0, 60)));
    if (lat < -90 || lat > 90 || lon < -540 || lon > 540)
      return CoastError{name_, static_cast<std::int64_t>(cur_->ring.record),
                        fmt::format("line {}: point off the globe", lineno_), geo::LonLat{lon, lat}};
    cur_->ring.pts.push_back({lon, lat});
    return std::nullopt;
  }

  Result<Coastline> finish() {
    if (auto e = end_segment(lineno_ + 1)) return *e;
    long long closed = 0;
    for (const Ring& r : out_.rings) closed += r.closed ? 1 : 0;
    const long long nseg = static_cast<long long>(out_.rings.size());
    auto mismatch = [&](const char* what, long long want, long long got) {
      return CoastError{name_, -1,
                        fmt::format("the header announces {}={} but the file holds {} (truncated or edited file)",
                                    what, want, got),
                        {}};
    };
    if (want_segments_ >= 0 && want_segments_ != nseg) return mismatch("segments", want_segments_, nseg);
    if (want_points_ >= 0 && want_points_ != total_points_) return mismatch("points", want_points_, total_points_);
    if (want_closed_ >= 0 && want_closed_ != closed) return mismatch("closed", want_closed_, closed);
    if (want_open_ >= 0 && want_open_ != nseg - closed) return mismatch("open", want_open_, nseg - closed);
    if (out_.rings.empty()) return CoastError{name_, -1, "no segment in file", {}};
    return std::move(out_);
  }

 private:
  CoastError error(std::string message) const {
    return CoastError{name_, static_cast<std::int64_t>(cur_->ring.record), std::move(message), {}};
  }

  void start_segment() {
    cur_.emplace();
    cur_->line = lineno_;
    cur_->ring.record = out_.rings.size();
    cur_->ring.id = static_cast<std::int64_t>(out_.rings.size()) + 1;
  }

  std::optional<CoastError> end_segment(std::size_t at_line) {
    if (!cur_) return std::nullopt;
    Pending& s = *cur_;
    if (s.npts >= 0 && static_cast<long long>(s.ring.pts.size()) != s.npts)
      return error(fmt::format("segment header (line {}) announces npts={} but {} points follow before line {}",
                               s.line, s.npts, s.ring.pts.size(), at_line));
    if (s.closed_word >= 0) {
      s.ring.closed = s.closed_word == 1;
    } else {
      s.ring.closed = s.ring.pts.size() >= 3 && same_point(s.ring.pts.front(), s.ring.pts.back());
    }
    total_points_ += static_cast<long long>(s.ring.pts.size());
    normalise_ring(s.ring);
    out_.rings.push_back(std::move(s.ring));
    cur_.reset();
    return std::nullopt;
  }

  std::optional<CoastError> header(std::string_view t) {
    if (auto e = end_segment(lineno_)) return e;
    start_segment();
    long long v;
    const std::string_view seg = word_value(t, "seg");
    if (!seg.empty() && parse_count(seg, v)) cur_->ring.id = v;
    const std::string_view lv = word_value(t, "level");
    if (!lv.empty()) {
      if (!parse_count(lv, v) || v < 1 || v > 6) return error(fmt::format("line {}: bad level '{}'", lineno_, lv));
      cur_->ring.level = static_cast<int>(v);
    }
    const std::string_view np = word_value(t, "npts");
    if (!np.empty()) {
      if (!parse_count(np, v)) return error(fmt::format("line {}: bad npts '{}'", lineno_, np));
      // An absurd count is caught by the bound below before anything is reserved.
      if (v > static_cast<long long>(total_bytes_ / 4 + 1))
        return error(fmt::format("line {}: npts={} cannot fit in the rest of the file", lineno_, v));
      cur_->npts = v;
      cur_->ring.pts.reserve(static_cast<std::size_t>(v));
    }
    const std::string_view cl = word_value(t, "closed");
    if (!cl.empty()) {
      if (cl != "0" && cl != "1") return error(fmt::format("line {}: closed must be 0 or 1, not '{}'", lineno_, cl));
      cur_->closed_word = cl == "1" ? 1 : 0;
    }
    return std::nullopt;
  }

  const std::string& name_;
  std::size_t total_bytes_;
  Coastline out_;
  long long want_segments_ = -1, want_points_ = -1, want_closed_ = -1, want_open_ = -1;
  std::optional<Pending> cur_;
  std::size_t lineno_ = 0, comment_lines_ = 0;
  long long total_points_ = 0;
};

// A file cut inside its last number would otherwise read as a slightly different
// point: an unterminated last data line is an error. `last` is what follows the last '\n'.
std::optional<CoastError> unterminated(std::string_view last, const std::string& name) {
  detail::skip_space(last);
  if (!last.empty() && last.front() != '#')
    return CoastError{name, -1, "the last line has no end of line: the file looks truncated", {}};
  return std::nullopt;
}

}  // namespace

Result<Coastline> read_lonlat_text_string(std::string_view text, const std::string& name) {
  if (!text.empty() && text.back() != '\n') {
    const std::size_t nl = text.rfind('\n');
    if (auto e = unterminated(text.substr(nl == std::string_view::npos ? 0 : nl + 1), name)) return *e;
  }
  Parser parser(name, text.size());
  std::string_view line;
  while (detail::next_line(text, line))
    if (auto e = parser.line(line)) return *e;
  return parser.finish();
}

Result<Coastline> read_lonlat_text(const std::string& path) {
  FileBlocks file;
  if (auto e = file.open(path)) return *e;
  if (!file.regular()) {   // a pipe: its size is known only at its end
    std::string text;
    for (;;) {
      auto block = file.next();
      if (!block) return block.error();
      if (block->empty()) break;
      text.append(*block);
    }
    return read_lonlat_text_string(text, path);
  }
  // The unterminated-last-line test comes first, as for a text in memory.
  if (auto tail = file.last_line()) {
    if (!*tail) return tail->error();
    if (auto e = unterminated(**tail, path)) return *e;
  }
  Parser parser(path, file.size());
  std::string carry;   // a line cut by the end of a block
  for (;;) {
    auto block = file.next();
    if (!block) return block.error();
    std::string_view text = *block;
    if (text.empty()) break;
    if (!carry.empty()) {
      const std::size_t nl = text.find('\n');
      carry.append(text.substr(0, nl));
      if (nl == std::string_view::npos) continue;
      text.remove_prefix(nl + 1);
      std::string_view whole = carry;
      if (!whole.empty() && whole.back() == '\r') whole.remove_suffix(1);
      if (auto e = parser.line(whole)) return *e;
      carry.clear();
    }
    // Whole lines of this block; the rest waits for the next one.
    const std::size_t last_nl = text.rfind('\n');
    std::string_view lines = last_nl == std::string_view::npos ? std::string_view{} : text.substr(0, last_nl + 1);
    carry.assign(last_nl == std::string_view::npos ? text : text.substr(last_nl + 1));
    std::string_view line;
    while (detail::next_line(lines, line))
      if (auto e = parser.line(line)) return *e;
  }
  if (!carry.empty()) {
    std::string_view whole = carry;
    if (whole.back() == '\r') whole.remove_suffix(1);
    if (auto e = parser.line(whole)) return *e;
  }
  return parser.finish();
}

}  // namespace sm::coast
