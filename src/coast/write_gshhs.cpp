// GSHHS 2.x writer: the inverse of read_gshhs for closed rings (layout in
// docs/coastlines.md section 2).
#include "coast/write_gshhs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "base/output_file.h"
#include "coast/coarsen.h"

namespace sm::coast {
namespace {

void put_be32(std::vector<unsigned char>& out, std::int64_t v) {
  const auto u = static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
  out.push_back(static_cast<unsigned char>(u >> 24));
  out.push_back(static_cast<unsigned char>(u >> 16));
  out.push_back(static_cast<unsigned char>(u >> 8));
  out.push_back(static_cast<unsigned char>(u));
}

// Micro-degrees, or nullopt outside the reader's accepted ranges.
std::optional<std::int64_t> micro(double deg, double lo, double hi) {
  const double m = std::round(deg * 1e6);
  if (!(m >= lo * 1e6 && m <= hi * 1e6)) return std::nullopt;
  return static_cast<std::int64_t>(m);
}

}  // namespace

Result<std::vector<unsigned char>> gshhs_bytes(const Coastline& c) {
  std::size_t total = 0;
  for (const Ring& r : c.rings) total += 44 + 8 * r.pts.size();
  std::vector<unsigned char> out;
  out.reserve(total);
  std::vector<std::int64_t> xy;
  for (std::size_t rec = 0; rec < c.rings.size(); ++rec) {
    const Ring& r = c.rings[rec];
    const auto record = static_cast<std::int64_t>(rec);
    if (!r.closed) return CoastError{c.file, record, "GSHHS holds closed rings only: this one is open", {}};
    if (r.pts.empty() || r.pts.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      return CoastError{c.file, record, fmt::format("{} points cannot be one GSHHS record", r.pts.size()), {}};
    if (r.level < 1 || r.level > 6)
      return CoastError{c.file, record, fmt::format("level {} is not 1..6", r.level), {}};
    xy.clear();
    std::int64_t west = std::numeric_limits<std::int64_t>::max(), east = std::numeric_limits<std::int64_t>::min();
    std::int64_t south = west, north = east;
    for (const geo::LonLat p : r.pts) {
      const auto x = micro(p.lon, -360, 540), y = micro(p.lat, -90, 90);
      if (!x || !y) return CoastError{c.file, record, "point off the globe for GSHHS", p};
      xy.push_back(*x);
      xy.push_back(*y);
      west = std::min(west, *x);
      east = std::max(east, *x);
      south = std::min(south, *y);
      north = std::max(north, *y);
    }
    // Area magnitude 1 (GSHHS >= 2.2: area / 10^1 km^2), version 12 in bits 8-15 as GSHHG 2.3.
    const double area = ring_area_km2(r.pts, geo::kEarthRadius * 1e-3);
    const auto tenths = static_cast<std::int64_t>(
        std::min(std::round(area * 10.0), static_cast<double>(std::numeric_limits<std::int32_t>::max())));
    const std::int64_t flag = r.level | (12 << 8) | (std::int64_t{1} << 26);
    put_be32(out, r.id >= 0 && r.id <= std::numeric_limits<std::int32_t>::max() ? r.id : record);
    put_be32(out, static_cast<std::int64_t>(r.pts.size()));
    put_be32(out, flag);
    put_be32(out, west);
    put_be32(out, east);
    put_be32(out, south);
    put_be32(out, north);
    put_be32(out, tenths);
    put_be32(out, tenths);
    put_be32(out, -1);   // container: not computed
    put_be32(out, -1);   // ancestor: none
    for (const std::int64_t v : xy) put_be32(out, v);
  }
  return out;
}

Result<bool> write_gshhs(const Coastline& c, const std::string& path) {
  auto bytes = gshhs_bytes(c);
  if (!bytes) return bytes.error();
  base::OutputFile f;
  if (!f.open(path) || !f.write(bytes->data(), bytes->size()) || !f.commit())
    return CoastError{path, -1, "cannot write: " + f.error(), {}};
  return true;
}

}  // namespace sm::coast
