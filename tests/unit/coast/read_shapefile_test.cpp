// Shapefile reader on Natural Earth and the index-less GSHHS_l_L1.shp, plus broken files.
#include "coast/read_shapefile.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "coast/file_bytes.h"

#include <shapefil.h>

using namespace sm;
using namespace sm::coast;

namespace {
const std::string kNe = std::string(SM_SHARED_DATA) + "/naturalearth/";

struct Counts { std::size_t records = 0, parts = 0, points = 0; };
Counts count(const Coastline& c) {
  Counts n;
  std::size_t last = static_cast<std::size_t>(-1);
  for (const Ring& r : c.rings) {
    if (r.record != last) ++n.records, last = r.record;
    ++n.parts;
    n.points += r.pts.size() + (r.closed && !r.wraps_pole ? 1 : 0);
  }
  return n;
}
}  // namespace

TEST_CASE("shapefile: Natural Earth polygons and polylines") {
  struct F { const char* name; int type; std::size_t records, parts; };
  const F files[] = {{"ne_110m_land.shp", 5, 127, 128},
                     {"ne_110m_coastline.shp", 3, 134, 134},
                     {"ne_50m_coastline.shp", 3, 1428, 1429},
                     {"ne_50m_land_no_antarctica.shp", 5, 1313, 1315}};
  for (const F& f : files) {
    CAPTURE(f.name);
    ShapefileInfo info;
    auto c = read_shapefile(kNe + f.name, &info);
    REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
    CHECK(info.shape_type == f.type);
    CHECK_FALSE(info.index_rebuilt);
    const Counts n = count(*c);
    CHECK(n.records == f.records);
    CHECK(n.parts == f.parts);
  }
  auto cl = read_shapefile(kNe + "ne_110m_coastline.shp");
  REQUIRE(cl.ok());
  std::size_t closed = 0, wraps = 0, pts = 0;
  for (const Ring& r : cl->rings) {
    closed += r.closed;
    wraps += r.wraps_pole;
    pts += r.pts.size() + (r.closed ? 1 : 0);
  }
  // 120 parts repeat their first point; Antarctica's line runs from 180 to -180: closed
  // on the sphere only.
  CHECK(closed == 121);
  CHECK(wraps == 1);
  CHECK(pts == 5128);
  auto land = read_shapefile(kNe + "ne_110m_land.shp");
  REQUIRE(land.ok());
  std::size_t land_wraps = 0;
  for (const Ring& r : land->rings) land_wraps += r.wraps_pole;
  CHECK(land_wraps == 1);   // Antarctica, closed along lat -90
  CHECK(count(*land).points + land_wraps == 5143);
}

TEST_CASE("shapefile: GSHHS_l_L1.shp without .shx (index rebuilt)") {
  ShapefileInfo info;
  auto c = read_shapefile(std::string(SM_SHARED_DATA) + "/gshhs_shp/GSHHS_l_L1.shp", &info);
  REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
  CHECK(info.index_rebuilt);
  CHECK(info.records == 5706);
  const Counts n = count(*c);
  CHECK(n.records == 5706);
  CHECK(n.points == 56351);
  for (const Ring& r : c->rings) CHECK(r.level == 1);   // GSHHS level-1 shapes are all outer rings
}

TEST_CASE("shapefile: broken files are located errors") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "sm_coast_shp_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto bytes = read_file_bytes(kNe + "ne_110m_coastline.shp");
  auto shx = read_file_bytes(kNe + "ne_110m_coastline.shx");
  REQUIRE(bytes.ok());
  REQUIRE(shx.ok());
  auto write = [&](const std::string& name, const std::vector<unsigned char>& b, std::size_t n) {
    std::ofstream f(dir / name, std::ios::binary);
    f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(n));
  };
  SUBCASE("truncated .shp with its full .shx") {
    write("t.shp", *bytes, bytes->size() / 2);
    write("t.shx", *shx, shx->size());
    auto r = read_shapefile((dir / "t.shp").string());
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().record >= 0);
  }
  SUBCASE("truncated .shp without .shx") {
    write("u.shp", *bytes, bytes->size() - 100);
    auto r = read_shapefile((dir / "u.shp").string());
    if (r.ok()) {
      // shapelib's index rebuild stops at the last complete record: never more records
      CHECK(r->rings.size() < 134);
    }
  }
  SUBCASE("garbage header and empty file") {
    std::vector<unsigned char> junk(200, 0x5A);
    write("g.shp", junk, junk.size());
    write("g.shx", junk, junk.size());
    CHECK_FALSE(read_shapefile((dir / "g.shp").string()).ok());
    write("e.shp", junk, 0);
    CHECK_FALSE(read_shapefile((dir / "e.shp").string()).ok());
    CHECK_FALSE(read_shapefile((dir / "missing.shp").string()).ok());
  }
  fs::remove_all(dir);
}

TEST_CASE("shapefile: PolygonZ and PolyLineZ written from real data read back the same") {
  namespace fs = std::filesystem;
  auto src = read_shapefile(kNe + "ne_110m_land.shp");
  REQUIRE(src.ok());
  const fs::path dir = fs::temp_directory_path() / "sm_coast_shpz_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (int type : {SHPT_POLYGONZ, SHPT_ARCZ}) {
    const std::string base = (dir / (type == SHPT_POLYGONZ ? "landz" : "linez")).string();
    SHPHandle h = SHPCreate(base.c_str(), type);
    REQUIRE(h != nullptr);
    // One multi-part record of the first 3 rings (closed, first point repeated), z = 7.
    std::vector<double> x, y, z;
    std::vector<int> starts;
    for (int r = 0; r < 3; ++r) {
      starts.push_back(static_cast<int>(x.size()));
      const auto& pts = src->rings[static_cast<std::size_t>(r)].pts;
      for (std::size_t k = 0; k <= pts.size(); ++k) {
        const auto p = pts[k % pts.size()];
        x.push_back(p.lon), y.push_back(p.lat), z.push_back(7.0);
      }
    }
    SHPObject* o = SHPCreateObject(type, -1, 3, starts.data(), nullptr, static_cast<int>(x.size()), x.data(), y.data(),
                                   z.data(), nullptr);
    SHPWriteObject(h, -1, o);
    SHPDestroyObject(o);
    SHPClose(h);
    ShapefileInfo info;
    auto back = read_shapefile(base + ".shp", &info);
    REQUIRE_MESSAGE(back.ok(), (back.ok() ? "" : back.error().to_string()));
    CHECK(info.shape_type == type);
    REQUIRE(back->rings.size() == 3);
    for (std::size_t r = 0; r < 3; ++r) {
      CHECK(back->rings[r].record == 0);
      CHECK(back->rings[r].part == static_cast<int>(r));
      CHECK(back->rings[r].closed);
      REQUIRE(back->rings[r].pts.size() == src->rings[r].pts.size());
      CHECK(back->rings[r].pts[1].lon == src->rings[r].pts[1].lon);
    }
  }
  fs::remove_all(dir);
}
