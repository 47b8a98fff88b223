// Polygon regions: the polygon's checks, clipping synthetic rings with known answers, and
// real data closed along a polygon drawn from headland to headland.
#include "coast/region_polygon.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "coast/clean.h"
#include "coast/read_lonlat_text.h"
#include "exact/ring.h"

using namespace sm;
using namespace sm::coast;

namespace {

Ring land(std::vector<geo::LonLat> pts) {
  Ring r;
  r.pts = std::move(pts);
  return r;
}

std::string message(const Result<RegionPolygon>& p) { return p.ok() ? std::string() : p.error().message; }

// Each loop closes piece to piece and turns counter-clockwise in the polygon's plane (ocean
// on the left); open pieces run along the polygon's edges, coast pieces end on them.
void check_loops(const RegionResult& r, const RegionPolygon& poly) {
  for (const RegionLoop& loop : r.loops) {
    std::vector<Vec2> plane;
    for (std::size_t i = 0; i < loop.pieces.size(); ++i) {
      const RegionPiece& p = loop.pieces[i];
      const RegionPiece& q = loop.pieces[(i + 1) % loop.pieces.size()];
      if (loop.pieces.size() > 1) {
        CHECK(p.pts.back().lat == doctest::Approx(q.pts.front().lat).epsilon(1e-12));
        CHECK(std::fmod(p.pts.back().lon - q.pts.front().lon + 720.0, 360.0) == doctest::Approx(0).epsilon(1e-9));
      }
      if (p.open_boundary) CHECK_FALSE(poly.edges_along(p.pts).empty());
      for (std::size_t k = 0; k + (loop.pieces.size() > 1 ? 1 : 0) < p.pts.size(); ++k) {
        Vec2 xy;
        REQUIRE(poly.project(p.pts[k], xy));
        plane.push_back(xy);
      }
    }
    CHECK(ring_orientation(plane) == Sign::Positive);
  }
}

}  // namespace

TEST_CASE("region polygon: checks of the vertices") {
  CHECK(message(RegionPolygon::make({{0, 0}, {1, 1}})).find("at least 3") != std::string::npos);
  CHECK(message(RegionPolygon::make({{0, 0}, {10, 10}, {10, 0}, {0, 10}})).find("crosses itself") != std::string::npos);
  CHECK(message(RegionPolygon::make({{0, 0}, {0, 0}, {1, 1}})).find("same point") != std::string::npos);
  CHECK(message(RegionPolygon::make({{0, 0}, {1, 0}, {2, 0}})).find("crosses itself") !=
        std::string::npos);  // edges 3 and 1 overlap
  CHECK(message(RegionPolygon::make({{0, 80}, {120, 80}, {240, 80}})).find("North Pole") != std::string::npos);
  CHECK(message(RegionPolygon::make({{0, 0}, {170, 0}, {85, 10}})).find("degrees from") != std::string::npos);
  CHECK(message(RegionPolygon::make({{0, 0}, {1, 95}, {2, 0}})).find("latitude") != std::string::npos);
  auto cw = RegionPolygon::make({{0, 0}, {5, 8}, {10, 0}});   // clockwise: turned round, edges keep their numbers
  REQUIRE(cw.ok());
  CHECK(cw->contains({5, 3}));
  CHECK_FALSE(cw->contains({5, -1}));
  CHECK_FALSE(cw->contains({20, 3}));
  CHECK_FALSE(cw->contains({185, 3}));
  // The edge from (10, 0) to (0, 0) is the equator: given edge 2.
  CHECK(cw->edges_along({{9, 0}, {8, 0}}) == std::vector<std::size_t>{2});
  CHECK(cw->edges_along({{9, 0}, {8, 0.001}}).empty());
  // A great circle from (0, 60) to (40, 60) bulges north of 60: the box holds it.
  auto high = RegionPolygon::make({{0, 60}, {40, 60}, {20, 50}});
  REQUIRE(high.ok());
  CHECK(high->bounding_box().north > 61.5);   // atan(tan 60 / cos 20) = 61.53
  CHECK(high->bounding_box().south < 50);
}

TEST_CASE("region polygon: an island across an edge, one inside, one outside") {
  auto poly = RegionPolygon::make({{0, 0}, {5, 8}, {10, 0}});
  REQUIRE(poly.ok());
  std::vector<Ring> rings{land({{4, -1}, {6, -1}, {6, 1}, {4, 1}}),          // across the equator edge
                          land({{4.5, 2.5}, {5.5, 2.5}, {5.5, 3.5}, {4.5, 3.5}}),   // inside
                          land({{20, 2}, {21, 2}, {21, 3}})};                 // outside
  auto r = clip_to_polygon(rings, *poly);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  CHECK(r->inside == std::vector<std::size_t>{1});
  REQUIRE(r->loops.size() == 1);
  REQUIRE(r->loops[0].pieces.size() == 2);
  const RegionPiece& coast = r->loops[0].pieces[0];
  const RegionPiece& open = r->loops[0].pieces[1];
  CHECK_FALSE(coast.open_boundary);
  CHECK(open.open_boundary);
  // The coast piece: from (4, 0) up the island's west side, along its top, down to (6, 0).
  REQUIRE(coast.pts.size() == 4);
  CHECK(coast.pts.front().lon == doctest::Approx(4));
  CHECK(std::abs(coast.pts.front().lat) < 1e-12);
  CHECK(coast.pts.back().lon == doctest::Approx(6));
  // The open piece turns round the three vertices, each listed as a corner.
  CHECK(open.corners.size() == 3);
  CHECK(poly->edges_along(open.pts) == std::vector<std::size_t>{0, 1, 2});
  check_loops(*r, *poly);
}

TEST_CASE("region polygon: all ocean, all land, an open end inside, across the dateline") {
  auto poly = RegionPolygon::make({{170, -5}, {-170, -5}, {-170, 5}, {170, 5}});
  REQUIRE(poly.ok());
  auto sea = clip_to_polygon({land({{100, 0}, {101, 0}, {101, 1}})}, *poly);
  REQUIRE(sea.ok());
  REQUIRE(sea->loops.size() == 1);
  REQUIRE(sea->loops[0].pieces.size() == 1);
  CHECK(sea->loops[0].pieces[0].open_boundary);
  CHECK(sea->loops[0].pieces[0].corners.size() == 4);
  auto island = clip_to_polygon({land({{179.5, 0}, {180.5, 0}, {180.5, 1}, {179.5, 1}})}, *poly);
  REQUIRE(island.ok());
  CHECK(island->inside.size() == 1);
  CHECK(poly->contains({-179.8, 0.5}));
  auto onland = clip_to_polygon({land({{160, -20}, {200, -20}, {200, 20}, {160, 20}})}, *poly);
  REQUIRE_FALSE(onland.ok());
  CHECK(onland.error().message.find("wholly on land") != std::string::npos);
  Ring open = land({{165, 0}, {178, 0}, {182, 0}, {195, 0}});   // in at 170, out at 190: land to the north
  open.closed = false;
  auto through = clip_to_polygon({open}, *poly);
  REQUIRE_MESSAGE(through.ok(), (through.ok() ? "" : through.error().to_string()));
  REQUIRE(through->loops.size() == 1);
  CHECK(through->loops[0].pieces.size() == 2);
  check_loops(*through, *poly);
  open.pts.erase(open.pts.begin());   // now it starts inside, at 178
  auto ends = clip_to_polygon({open}, *poly);
  REQUIRE_FALSE(ends.ok());
  CHECK(ends.error().message.find("ends inside") != std::string::npos);
}

TEST_CASE("region polygon: the Irish Sea between two headland lines, on GSHHG full") {
  auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/gb_ireland_f.txt");
  REQUIRE(c.ok());
  clean(*c);
  orient_rings(c->rings);
  // St George's Channel from Carnsore Point to St David's Head (edge 8, given order), round
  // over Wales, England and the Southern Uplands, the North Channel from the Rhins of
  // Galloway to Torr Head (edge 4), back over Ireland. Vertices a little inland.
  auto poly = RegionPolygon::make({{-5.27, 51.89}, {-2.2, 52.2}, {-2.2, 55.3}, {-4.5, 55.1}, {-5.0, 54.90},
                                   {-6.10, 55.17}, {-7.5, 54.5}, {-7.5, 52.5}, {-6.45, 52.22}});
  REQUIRE_MESSAGE(poly.ok(), message(poly));
  auto r = clip_to_polygon(c->rings, *poly);
  REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().to_string()));
  check_loops(*r, *poly);
  // The two channels, each one long open piece on its edge; the edges also graze the shore
  // at Loch Ryan's head and St David's Head (four pieces of under 500 m, which the import
  // joins into the coast: tests/scripts/coastline/region_polygon.geo).
  std::vector<std::size_t> long_on, short_on;
  for (const RegionLoop& loop : r->loops)
    for (const RegionPiece& p : loop.pieces)
      if (p.open_boundary) {
        const auto e = poly->edges_along(p.pts);
        REQUIRE(e.size() == 1);
        const double km = RegionPolygon::arc_deg(p.pts.front(), p.pts.back()) * 111.195;
        (km > 10 ? long_on : short_on).push_back(e[0]);
        if (km <= 10) CHECK(km < 0.5);
      }
  CHECK(long_on == std::vector<std::size_t>{4, 8});
  CHECK(short_on.size() == 4);
  CHECK(r->inside.size() > 50);   // Anglesey, the Isle of Man, ...
}
