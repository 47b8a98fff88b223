// Shapefile reader on Natural Earth and the index-less GSHHS_l_L1.shp, plus broken files.
#include "coast/read_shapefile.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "coast/file_bytes.h"

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
