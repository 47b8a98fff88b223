// What every successful read must give, checked by the reader fuzz targets: finite
// points on the globe in the Ring convention, and well-formed grids.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "coast/coastline.h"
#include "field/lonlat_grid.h"

namespace sm::fuzz {

[[noreturn]] inline void reader_violated(const char* reader, const char* what) {
  std::fprintf(stderr, "fuzz_%s: reader invariant violated: %s\n", reader, what);
  std::abort();
}

inline void check_coastline(const char* reader, const coast::Result<coast::Coastline>& r) {
  if (!r.ok()) {
    if (r.error().message.empty()) reader_violated(reader, "an error without a message");
    (void)r.error().to_string();
    return;
  }
  for (const coast::Ring& ring : r.value().rings) {
    for (std::size_t i = 0; i < ring.pts.size(); ++i) {
      const geo::LonLat p = ring.pts[i];
      if (!std::isfinite(p.lon) || !std::isfinite(p.lat)) reader_violated(reader, "a point that is not finite");
      if (std::fabs(p.lat) > 90) reader_violated(reader, "a latitude off the globe");
      // Contiguous longitudes (coastline.h): consecutive points never jump by more
      // than 180 degrees.
      if (i > 0 && std::fabs(p.lon - ring.pts[i - 1].lon) > 180 + 1e-9)
        reader_violated(reader, "a longitude jump of more than 180 degrees");
    }
  }
}

inline void check_grid(const char* reader, const field::LonLatGrid& g) {
  if (g.nlon < 2 || g.nlat < 2) reader_violated(reader, "a grid side under 2 nodes");
  if (g.v.size() != static_cast<std::size_t>(g.nlon) * static_cast<std::size_t>(g.nlat))
    reader_violated(reader, "a value count that is not nlon x nlat");
  if (!(g.dlon > 0 && g.dlat > 0) || !std::isfinite(g.dlon) || !std::isfinite(g.dlat) ||
      !std::isfinite(g.lon0) || !std::isfinite(g.lat0))
    reader_violated(reader, "a grid geometry that is not finite and positive");
  for (const double v : g.v)
    if (std::isinf(v)) reader_violated(reader, "an infinite grid value");
  // Interpolation anywhere must stay inside the data (NaN only from missing nodes).
  (void)g.interp(g.lon0 + 0.5 * g.dlon, g.lat0 + 0.5 * g.dlat);
  (void)g.interp(-720, 95);
}

}  // namespace sm::fuzz
