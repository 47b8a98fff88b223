// The splice of a local shoreline into a base one inside a box (coast/patch.h), on a
// synthetic case with a known answer.
#include "coast/patch.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/region.h"

using namespace sm;
using namespace sm::coast;

namespace {

Ring patch_square(double w, double e, double s, double n) {
  Ring r;
  r.pts = {{w, s}, {e, s}, {e, n}, {w, n}};
  return r;
}

double patch_signed_area(const Ring& r) {
  double a = 0;
  for (std::size_t i = 0; i < r.pts.size(); ++i) {
    const geo::LonLat p = r.pts[i], q = r.pts[(i + 1) % r.pts.size()];
    a += p.lon * q.lat - q.lon * p.lat;
  }
  return 0.5 * a;
}

bool patch_has_point(const std::vector<Ring>& rings, geo::LonLat p) {
  for (const Ring& r : rings)
    for (auto q : r.pts)
      if (q.lon == p.lon && q.lat == p.lat) return true;
  return false;
}

// The channel case's splice over `base`: the box is the strip x in [4,6], y in [-1,11];
// the local source, two blocks leaving the channel y in (4.5, 5.5) open and reaching past
// [0,10]^2 at the top and bottom.
auto splice_channel(std::vector<Ring> base, PatchReport& rep) {
  std::vector<Ring> local{patch_square(3, 7, -2, 4.5), patch_square(3, 7, 5.5, 12)};
  orient_rings(base);
  orient_rings(local);
  return splice_patch(base, local, LonLatBox{4, 6, -1, 11}, 6371e3, &rep);
}

}  // namespace

TEST_CASE("patch: a channel cut through the base land inside the box") {
  // Base: the land square [0,10]^2. Box: the strip x in [4,6], y in [-1,11]. Local: two
  // blocks leaving the channel y in (4.5, 5.5) open and reaching past the base at the
  // top and bottom. Land = base outside the strip U local inside it: an outer ring of
  // 100 + 2 + 2 (the two bumps of the strip past the square) and the channel, a hole of 2.
  PatchReport rep;
  auto out = splice_channel({patch_square(0, 10, 0, 10)}, rep);
  REQUIRE(out.ok());
  REQUIRE(out->size() == 2);
  double total = 0, outer = 0, hole = 0;
  for (const Ring& r : *out) {
    CHECK(r.closed);
    const double a = patch_signed_area(r);
    total += a;
    (a > 0 ? outer : hole) = a;
  }
  CHECK(outer == doctest::Approx(104));
  CHECK(hole == doctest::Approx(-2));
  CHECK(total == doctest::Approx(102));
  // Outside the box the base is unchanged: its corners are still there.
  for (geo::LonLat c : {geo::LonLat{0, 0}, geo::LonLat{10, 0}, geo::LonLat{10, 10}, geo::LonLat{0, 10}})
    CHECK(patch_has_point(*out, c));
  // Four stretches of box edge close the gaps: round each bump (1 + 2 + 1 degrees: up the
  // side, along the box's end, down the other side) and across each end of the channel
  // (1 degree).
  CHECK(rep.steps == 4);
  CHECK(rep.max_step_m == doctest::Approx(4 * 6371e3 * M_PI / 180).epsilon(1e-3));
  CHECK(rep.base_chains == 2);
  CHECK(rep.local_chains == 2);
}

TEST_CASE("patch: errors") {
  std::vector<Ring> base{patch_square(0, 10, 0, 10)};
  orient_rings(base);
  SUBCASE("no shoreline of the patch inside the box") {
    std::vector<Ring> local{patch_square(20, 21, 20, 21)};
    auto out = splice_patch(base, local, LonLatBox{4, 6, -1, 11}, 6371e3);
    REQUIRE_FALSE(out.ok());
    CHECK(out.error().option == "Patch");
    CHECK(out.error().message.find("no shoreline inside its box") != std::string::npos);
  }
  SUBCASE("a box without west < east") {
    std::vector<Ring> local{patch_square(3, 7, 3, 7)};
    auto out = splice_patch(base, local, LonLatBox{6, 4, -1, 11}, 6371e3);
    REQUIRE_FALSE(out.ok());
    CHECK(out.error().option == "PatchBox");
  }
  SUBCASE("an island of the patch wholly inside the box is kept, the base inside dropped") {
    std::vector<Ring> local{patch_square(4.5, 5.5, 20, 21), patch_square(4.5, 5.5, 1, 2)};
    orient_rings(local);
    auto out = splice_patch(base, local, LonLatBox{4, 6, -1, 11}, 6371e3);
    REQUIRE(out.ok());
    double total = 0;
    for (const Ring& r : *out) total += patch_signed_area(r);
    CHECK(total == doctest::Approx(80 + 1));   // the square less the strip, and the island
  }
}

TEST_CASE("patch: a base ring leaving the box through a vertex on its edge") {
  // Base: land [0,10]^2 with vertices exactly on the box's west edge x = 4 (the data's
  // round coordinates: GSHHG holds vertices on whole degrees). The ring comes out of the
  // box through (4, 10) and back in through (4, 0): the outside chain must start and end
  // on the perimeter there, or the linking sees two chains leave in a row.
  // The same splice as the channel case, its box's west edge through the base's vertices.
  Ring base_ring;
  base_ring.pts = {{0, 0}, {4, 0}, {10, 0}, {10, 10}, {4, 10}, {0, 10}};
  PatchReport rep;
  auto out = splice_channel({base_ring}, rep);
  REQUIRE(out.ok());
  REQUIRE(out->size() == 2);
  double outer = 0, hole = 0;
  for (const Ring& r : *out) (patch_signed_area(r) > 0 ? outer : hole) = patch_signed_area(r);
  CHECK(outer == doctest::Approx(104));
  CHECK(hole == doctest::Approx(-2));
}
