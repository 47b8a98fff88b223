// The land ring holding a point (land_ring.h).
#include "coast/land_ring.h"

#include "exact/ring.h"

namespace sm::coast {

const Ring* land_ring_holding(const std::vector<Ring>& rings, geo::LonLat p) {
  std::vector<Vec2> xy;
  for (const Ring& r : rings) {
    if (!r.closed || r.wraps_pole || r.level != 1) continue;
    for (int k = -1; k <= 1; ++k) {
      xy.clear();
      for (auto q : r.pts) xy.push_back({q.lon + 360.0 * k, q.lat});
      if (point_in_ring(xy, {p.lon, p.lat})) return &r;
    }
  }
  return nullptr;
}

}  // namespace sm::coast
