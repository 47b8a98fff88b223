// Region clipping and closing along the box on real data.
#include "coast/region.h"

#include <doctest/doctest.h>

#include <cmath>

#include "coast/clean.h"
#include "exact/ring.h"
#include "coast/read_lonlat_text.h"

using namespace sm;
using namespace sm::coast;

namespace {
std::vector<Ring> load(const char* name) {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/" + name);
  REQUIRE(c.ok());
  clean(*c);
  orient_rings(c->rings);
  return std::move(c->rings);
}

bool on_box(geo::LonLat p, const LonLatBox& b) {
  const double e = 1e-9;
  return std::abs(p.lon - b.west) < e || std::abs(p.lon - b.east) < e || std::abs(p.lat - b.south) < e ||
         std::abs(p.lat - b.north) < e;
}

// Every loop closes piece to piece, box pieces run on the box, coast pieces end on it,
// and the loop turns counter-clockwise (ocean on the left).
void check_loops(const RegionResult& r, const LonLatBox& box) {
  for (const RegionLoop& loop : r.loops) {
    std::vector<Vec2> poly;
    for (std::size_t i = 0; i < loop.pieces.size(); ++i) {
      const RegionPiece& p = loop.pieces[i];
      const RegionPiece& q = loop.pieces[(i + 1) % loop.pieces.size()];
      if (loop.pieces.size() > 1) {
        CHECK(p.pts.back().lat == q.pts.front().lat);
        CHECK(std::fmod(p.pts.back().lon - q.pts.front().lon + 720.0, 360.0) == doctest::Approx(0));
      }
      if (p.open_boundary)
        for (auto x : p.pts) CHECK(on_box(x, box));
      else
        CHECK((on_box(p.pts.front(), box) && on_box(p.pts.back(), box)));
      for (std::size_t k = 0; k + (loop.pieces.size() > 1 ? 1 : 0) < p.pts.size(); ++k)
        poly.push_back({p.pts[k].lon, p.pts[k].lat});
    }
    CHECK(ring_orientation(poly) == Sign::Positive);
  }
}
}  // namespace

TEST_CASE("region: GB and Ireland closed along the file's own box") {
  const auto rings = load("gb_ireland_f.txt");
  const LonLatBox box{-11, 2, 49, 61};
  auto r = clip_to_region(rings, box);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  CHECK(r->inside.size() == 2892);           // every closed ring lies inside
  REQUIRE(r->loops.size() == 1);             // one sea: both French pieces are capes poking into the box
  std::size_t coast = 0, open = 0;
  for (const auto& l : r->loops)
    for (const auto& p : l.pieces) (p.open_boundary ? open : coast)++;
  CHECK(coast == 2);
  CHECK(open == 2);
  check_loops(*r, box);
}

TEST_CASE("region: world_c cut to the North Sea box, and Wrangel Island across the dateline") {
  const auto rings = load("world_c.txt");
  const LonLatBox ns{-12, 10, 47, 62};
  auto r = clip_to_region(rings, ns);
  REQUIRE(r.ok());
  CHECK(r->loops.size() >= 1);
  check_loops(*r, ns);
  const LonLatBox bering{170, 200, 60, 75};   // east of the dateline written past 180
  auto b = clip_to_region(rings, bering);
  REQUIRE_MESSAGE(b.ok(), (b.ok() ? "" : b.error().to_string()));
  check_loops(*b, bering);
  bool wrangel = false;
  for (std::size_t i : b->inside) wrangel |= rings[i].id == 78;
  CHECK(wrangel);
}

TEST_CASE("region: all ocean, all land, bad boxes, open ends inside") {
  const auto rings = load("world_c.txt");
  auto sea = clip_to_region(rings, {-40, -30, 30, 40});
  REQUIRE(sea.ok());
  REQUIRE(sea->loops.size() == 1);
  CHECK(sea->loops[0].pieces.size() == 1);
  CHECK(sea->loops[0].pieces[0].open_boundary);
  auto land = clip_to_region(rings, {80, 90, 40, 45});
  REQUIRE_FALSE(land.ok());
  CHECK(land.error().message.find("land") != std::string::npos);
  CHECK_FALSE(clip_to_region(rings, {10, 5, 0, 1}).ok());
  CHECK_FALSE(clip_to_region(rings, {-180, 180, -90, 0}).ok());
  const auto gb = load("gb_ireland_f.txt");
  auto inner = clip_to_region(gb, {-10, 1, 50, 60});   // the French pieces end outside this box: fine
  CHECK(inner.ok());
  auto bigger = clip_to_region(gb, {-12, 3, 48, 62});   // they now end inside it: cannot be closed
  REQUIRE_FALSE(bigger.ok());
  REQUIRE(bigger.error().where.has_value());
}

TEST_CASE("region: the Arctic cap closes along the parallel 50N") {
  const auto rings = load("arctic_i_A10.txt");
  const LonLatBox cap{-180, 180, 50, 90};
  auto r = clip_to_region(rings, cap);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  std::size_t open = 0;
  for (const auto& l : r->loops)
    for (const auto& p : l.pieces)
      if (p.open_boundary) {
        ++open;
        for (auto x : p.pts) CHECK(x.lat == 50);
      }
  CHECK(open == 16);   // one box piece after each of the 16 cut coastlines
}

// Box corners listed by the pieces that turn round them, with samples halving in
// distance towards them (the B-splines must not cut the corners).
void check_corners(const RegionResult& r, const LonLatBox& box, std::size_t want_corners) {
  std::size_t corners = 0;
  for (const RegionLoop& loop : r.loops)
    for (const RegionPiece& p : loop.pieces) {
      if (!p.open_boundary) CHECK(p.corners.empty());
      for (std::size_t c : p.corners) {
        REQUIRE(c < p.pts.size());
        const geo::LonLat x = p.pts[c];
        CHECK(((x.lon == box.west || x.lon == box.east) && (x.lat == box.south || x.lat == box.north)));
        // The nearest samples on either side are ~1e-5 degrees from it, the next twice as far.
        const std::size_t n = p.pts.size();
        for (std::size_t nb : {(c + 1) % n, (c + n - 1) % n}) {
          const double d = std::abs(p.pts[nb].lon - x.lon) + std::abs(p.pts[nb].lat - x.lat);
          CHECK(d < 2e-5);
          CHECK(d >= 1e-5 * 0.999);
        }
        ++corners;
      }
    }
  CHECK(corners == want_corners);
}

TEST_CASE("region: box pieces list their corners, sampled densely next to them") {
  const auto rings = load("gb_ireland_f.txt");
  // The Irish Sea tutorial's box: one box piece, turning round the western corners (both at sea).
  const LonLatBox irish{-7, -2.5, 51.5, 55.5};
  auto r = clip_to_region(rings, irish);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  check_loops(*r, irish);
  check_corners(*r, irish, 2);
  // A box in the open Atlantic: the box alone, a closed piece with its four corners.
  const LonLatBox atlantic{-20, -15, 50, 52};
  auto a = clip_to_region(rings, atlantic);
  REQUIRE_MESSAGE(a.ok(), (a.ok() ? "" : a.error().to_string()));
  REQUIRE(a->loops.size() == 1);
  REQUIRE(a->loops[0].pieces.size() == 1);
  CHECK(a->loops[0].pieces[0].corners.front() == 0);
  check_corners(*a, atlantic, 4);
}
