// Transfinite patches of Gmsh's filling surfaces (Coons on 4 sides, Gmsh's 3-side form).
#include "geo/surface_filling.h"

#include "base/check.h"

namespace sm::geo {

Vec3 TransfinitePatch::point(Vec2 uv) const {
  SM_ASSERT(sides.size() == 3 || sides.size() == 4, "a filling patch has 3 or 4 sides");
  const double u = uv.x, v = uv.y;
  auto c = [&](std::size_t i, double t) { return sides[i].curve->eval(t, sides[i].reversed).p; };
  auto s = [&](std::size_t i) { return c(i, 0.0); };
  Vec3 f;
  if (sides.size() == 4) {
    f = (1 - u) * c(3, 1 - v) + u * c(1, v) + (1 - v) * c(0, u) + v * c(2, 1 - u) -
        ((1 - u) * (1 - v) * s(0) + u * (1 - v) * s(1) + u * v * s(2) + (1 - u) * v * s(3));
  } else if (old_style) {
    f = u * c(1, v) + (1 - v) * c(0, u) + v * c(2, 1 - u) - (u * (1 - v) * s(1) + u * v * s(2));
  } else {
    f = (1 - u) * (c(0, u - v) + c(2, 1 - v) - s(0)) + (u - v) * (c(1, v) + c(0, u) - s(1)) +
        v * (c(2, 1 - u) + c(1, 1 - u + v) - s(2));
  }
  if (sphere_centre) {
    const Vec3 o = *sphere_centre;
    const double r = norm(s(0) - o), d = norm(f - o);
    if (d > 0) f = o + (r / d) * (f - o);
  }
  return f;
}

}  // namespace sm::geo
