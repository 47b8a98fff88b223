// loops2 text reader. UTM goes through GeographicLib's transverse Mercator on Gmsh's
// (a, b) ellipsoid with k0 = 0.9996 and a 500 km false easting, as the plugin did.
#include "coast/read_loops2.h"

#include <cmath>

#include <GeographicLib/TransverseMercator.hpp>
#include <fmt/format.h>

#include "coast/file_bytes.h"
#include "coast/text_scan.h"

namespace sm::coast {

std::optional<Loops2Coordinate> parse_loops2_coordinate(std::string_view s) {
  if (s == "lonlat") return Loops2Coordinate::LonLatRadians;
  if (s == "lonlat_degrees") return Loops2Coordinate::LonLatDegrees;
  if (s == "utm" || s == "UTM") return Loops2Coordinate::Utm;
  if (s == "cartesian") return Loops2Coordinate::Cartesian;
  return std::nullopt;
}

Result<Coastline> read_loops2_string(std::string_view text, const std::string& name,
                                     const Loops2Options& opt) {
  std::optional<GeographicLib::TransverseMercator> tm;
  if (opt.coordinate == Loops2Coordinate::Utm) {
    const double a = opt.utm_equatorial_radius, b = opt.utm_polar_radius;
    if (!(a > 0 && b > 0 && b <= a) || opt.utm_zone < 1 || opt.utm_zone > 60)
      return CoastError{
          name, -1, fmt::format("UTM needs a zone 1..60 (got {}) and radii a >= b > 0", opt.utm_zone), {}};
    tm.emplace(a, (a - b) / a, 0.9996);
  }
  if (!text.empty() && text.back() != '\n' &&
      text.find_first_not_of(" \t\r", text.rfind('\n') + 1) != std::string_view::npos)
    return CoastError{name, -1, "the last line has no end of line: the file looks truncated", {}};
  Coastline out;
  out.file = name;
  std::string_view line;
  std::size_t lineno = 0;
  auto next_data_line = [&](std::string_view& l) {
    while (detail::next_line(text, l)) {
      ++lineno;
      std::string_view t = l;
      detail::skip_space(t);
      if (!t.empty()) return true;
    }
    return false;
  };
  while (next_data_line(line)) {
    const auto rec = static_cast<std::int64_t>(out.rings.size());
    std::string_view t = line;
    long long n = 0, closed = 0;
    if (!detail::take_long(t, n) || !detail::take_long(t, closed) || !detail::only_space_left(t) || n < 0 ||
        (closed != 0 && closed != 1))
      return CoastError{name, rec, fmt::format("line {}: expected a block header 'nPoints closed(0|1)'", lineno), {}};
    if (static_cast<unsigned long long>(n) > text.size() / 4 + 1)
      return CoastError{name, rec, fmt::format("line {}: {} points cannot fit in the rest of the file", lineno, n), {}};
    Ring r;
    r.id = rec;
    r.record = out.rings.size();
    r.closed = closed == 1;
    r.pts.reserve(static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i) {
      if (!next_data_line(line))
        return CoastError{name, rec, fmt::format("file ends after {} of the {} points of the block", i, n), {}};
      std::string_view p = line;
      double c1, c2;
      if (!detail::take_double(p, c1) || !detail::take_double(p, c2))
        return CoastError{name, rec, fmt::format("line {}: expected two finite numbers", lineno), {}};
      geo::LonLat ll;
      switch (opt.coordinate) {
        case Loops2Coordinate::LonLatRadians: ll = {c1 * geo::kRadToDeg, c2 * geo::kRadToDeg}; break;
        case Loops2Coordinate::LonLatDegrees: ll = {c1, c2}; break;
        case Loops2Coordinate::Utm: {
          const double lon0 = 6.0 * opt.utm_zone - 183.0;
          tm->Reverse(lon0, c1 - 500000.0, c2, ll.lat, ll.lon);
          break;
        }
        case Loops2Coordinate::Cartesian:
          if (c1 == 0 && c2 == 0)
            return CoastError{name, rec, fmt::format("line {}: cartesian point at the centre", lineno), {}};
          ll = {std::atan2(c2, c1) * geo::kRadToDeg, 0.0};
          break;
      }
      if (!(std::abs(ll.lat) <= 90) || !(std::abs(ll.lon) <= 540))
        return CoastError{name, rec, fmt::format("line {}: point off the globe", lineno), ll};
      r.pts.push_back(ll);
    }
    normalise_ring(r);
    out.rings.push_back(std::move(r));
  }
  if (out.rings.empty()) return CoastError{name, -1, "no block in file", {}};
  return out;
}

Result<Coastline> read_loops2(const std::string& path, const Loops2Options& opt) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return read_loops2_string(text, path, opt);
}

}  // namespace sm::coast
