// The lon/lat box geometry of region.cpp, shared with patch.cpp: perimeter parameter
// t in [0,4) counter-clockwise from the south-west corner (region.cpp's drawing),
// Liang-Barsky clipping of a segment, and paths along the box.
#pragma once

#include <cstddef>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast::region_box {

bool strictly_outside(geo::LonLat p, const LonLatBox& b);
bool on_boundary(geo::LonLat p, const LonLatBox& b);
double box_param(geo::LonLat p, const LonLatBox& b);
geo::LonLat box_point(double t, const LonLatBox& b);
std::vector<geo::LonLat> box_path(geo::LonLat a, double ta, geo::LonLat b, double tb, const LonLatBox& box,
                                  double step, double corner_step = 0, std::vector<std::size_t>* corners = nullptr,
                                  bool closed = false);
bool clip_segment(geo::LonLat p, geo::LonLat q, const LonLatBox& b, double& t0, double& t1);
geo::LonLat lerp(geo::LonLat p, geo::LonLat q, double t);

}  // namespace sm::coast::region_box
