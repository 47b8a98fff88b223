// Cleaning: synthetic duplicates/spikes/seams, and the artefact counts of the real files
// (data/PROVENANCE.md; the rings with fewer than 3 distinct points).
#include "coast/clean.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "coast/read_lonlat_text.h"
#include "coast/read_shapefile.h"

using namespace sm;
using namespace sm::coast;

namespace {
Ring ring(std::vector<geo::LonLat> pts, bool closed = true) {
  Ring r;
  r.pts = std::move(pts);
  r.closed = closed;
  return r;
}
}  // namespace

TEST_CASE("clean: duplicates, spikes, seam spikes, degenerate rings") {
  Coastline c;
  c.rings.push_back(ring({{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2.5, 0.5}, {2, 0}, {2, 1}, {0, 1}}));
  c.rings.push_back(ring({{5, 5}, {6, 5}, {6, 6}, {5, 6}, {4, 6}, {5, 6}}));   // spike at the seam
  c.rings.push_back(ring({{9, 9}, {9.5, 9}, {9, 9}}));                          // 2 distinct vertices
  c.rings.push_back(ring({{-180, 10}, {180, 10}}, false));                      // one point on the sphere
  const CleanReport rep = clean(c);
  CHECK(rep.count(CleanAction::Duplicate) >= 1);
  CHECK(rep.count(CleanAction::Spike) == 3);
  CHECK(rep.count(CleanAction::DegenerateRing) == 2);
  REQUIRE(c.rings.size() == 2);
  CHECK(c.rings[0].pts.size() == 5);
  CHECK(c.rings[1].pts.size() == 4);
  bool found = false;
  for (const auto& e : rep.entries)
    if (e.action == CleanAction::Spike && e.where.lon == 2.5 && e.where.lat == 0.5) found = true;
  CHECK(found);   // the report says where
}

TEST_CASE("clean: the artefacts of the GSHHG text exports") {
  // README counts the vertices of every a->b->a pattern; a double spike a->b->a->b (world_c
  // ring 11) is one removal here, and world_l's 2-vertex ring is dropped as degenerate.
  struct F { const char* name; std::size_t spikes, degenerate; };
  const F files[] = {{"world_c.txt", 2, 0},      {"world_l.txt", 2, 1}, {"world_i_A100.txt", 4, 0},
                     {"arctic_i_A10.txt", 2, 0}, {"canadian_arctic_h.txt", 2, 0}, {"gb_ireland_f.txt", 0, 0},
                     {"northsea_scheldt_f.txt", 0, 0}, {"gbr_lizard_f.txt", 0, 0}};
  for (const F& f : files) {
    CAPTURE(f.name);
    auto c = read_lonlat_text(std::string(SM_DATA_DIR) + "/gshhg/" + f.name);
    REQUIRE(c.ok());
    const CleanReport rep = clean(*c);
    CHECK(rep.count(CleanAction::Spike) == f.spikes);
    CHECK(rep.count(CleanAction::DegenerateRing) == f.degenerate);
    CHECK(rep.count(CleanAction::Duplicate) == 0);   // "No file has consecutive duplicate vertices"
  }
}

TEST_CASE("clean: Natural Earth Antarctica closed along the South Pole") {
  auto c = read_shapefile(std::string(SM_DATA_DIR) + "/naturalearth/ne_110m_land.shp");
  REQUIRE(c.ok());
  const CleanReport rep = clean(*c);
  CHECK(rep.count(CleanAction::PoleVertex) >= 1);
  std::size_t wraps = 0;
  for (const Ring& r : c->rings) {
    wraps += r.wraps_pole;
    for (auto p : r.pts) CHECK(p.lat > -90);
  }
  CHECK(wraps == 1);
}

TEST_CASE("clean: rings sharing an edge are merged (polygons split at the dateline)") {
  Coastline sq;
  Ring a, b;
  a.pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  b.pts = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  b.record = 1;
  sq.rings = {a, b};
  CleanReport rep;
  merge_touching_rings(sq, rep);
  REQUIRE(sq.rings.size() == 1);
  CHECK(sq.rings[0].pts.size() == 6);
  CHECK(rep.count(CleanAction::MergedRings) == 1);
  // A run of two shared edges: the leftover becomes a spike and is removed.
  Coastline run;
  a.pts = {{0, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0, 1}};
  b.pts = {{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0.5}};
  run.rings = {a, b};
  CleanReport rep2;
  merge_touching_rings(run, rep2);
  REQUIRE(run.rings.size() == 1);
  CHECK(run.rings[0].pts.size() == 6);
  CHECK(rep2.count(CleanAction::Spike) == 1);
  struct F { const char* path; std::size_t merges; };
  for (const F& f : {F{"/gshhs_shp/GSHHS_l_L1.shp", 5}, F{"/naturalearth/ne_110m_land.shp", 3}}) {
    CAPTURE(f.path);
    auto c = read_shapefile(std::string(SM_DATA_DIR) + f.path);
    REQUIRE(c.ok());
    const std::size_t before = c->rings.size();
    const Coastline copy = *c;
    CleanReport r = clean(*c);
    merge_touching_rings(*c, r);
    CHECK(r.count(CleanAction::MergedRings) == f.merges);
    // On two and three threads (the vertex runs cut the largest rings; the rings go in
    // chunks to the cleaning, the dateline search and the spike pass after each merge):
    // the same rings, in order, and the same report, entry for entry.
    for (int threads : {2, 3}) {
      CAPTURE(threads);
      Coastline c2 = copy;
      CleanReport r2 = clean(c2, threads);
      merge_touching_rings(c2, r2, threads);
      REQUIRE(c2.rings.size() == c->rings.size());
      std::size_t differ = 0;
      for (std::size_t k = 0; k < c->rings.size(); ++k) {
        const auto& p1 = c->rings[k].pts;
        const auto& p2 = c2.rings[k].pts;
        differ += p1.size() != p2.size();
        for (std::size_t i = 0; i < std::min(p1.size(), p2.size()); ++i)
          differ += p1[i].lon != p2[i].lon || p1[i].lat != p2[i].lat;
      }
      CHECK(differ == 0);
      REQUIRE(r2.entries.size() == r.entries.size());
      std::size_t entries_differ = 0;
      for (std::size_t i = 0; i < r.entries.size(); ++i) {
        const auto& e1 = r.entries[i];
        const auto& e2 = r2.entries[i];
        entries_differ += e1.action != e2.action || e1.record != e2.record || e1.where.lon != e2.where.lon ||
                          e1.where.lat != e2.where.lat;
      }
      CHECK(entries_differ == 0);
    }
    CHECK(c->rings.size() + f.merges + r.count(CleanAction::DegenerateRing) == before);
    for (const auto& e : r.entries)
      if (e.action == CleanAction::MergedRings) CHECK(std::abs(std::abs(std::fmod(e.where.lon, 360.0)) - 180.0) < 1e-6);
  }
}
