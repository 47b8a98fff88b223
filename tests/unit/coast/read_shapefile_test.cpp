// Shapefile reader on Natural Earth and the index-less GSHHS_l_L1.shp, plus broken files.
#include "coast/read_shapefile.h"

#include <unistd.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "coast/file_bytes.h"
#include "scratch_dir.h"

#include <shapefil.h>

using namespace sm;
using namespace sm::coast;

namespace {
const std::string kNe = std::string(SM_DATA_DIR) + "/naturalearth/";

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

// The first n bytes of b (all of them by default) as the file path.
void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& b,
                 std::size_t n = static_cast<std::size_t>(-1)) {
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(std::min(n, b.size())));
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
  auto c = read_shapefile(std::string(SM_DATA_DIR) + "/gshhs_shp/GSHHS_l_L1.shp", &info);
  REQUIRE_MESSAGE(c.ok(), (c.ok() ? "" : c.error().to_string()));
  CHECK(info.index_rebuilt);
  CHECK(info.records == 5706);
  const Counts n = count(*c);
  CHECK(n.records == 5706);
  CHECK(n.points == 56351);
  for (const Ring& r : c->rings) CHECK(r.level == 1);   // GSHHS level-1 shapes are all outer rings
}

TEST_CASE("shapefile: broken files are located errors") {
  const sm::testing::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path;
  auto bytes = read_file_bytes(kNe + "ne_110m_coastline.shp");
  auto shx = read_file_bytes(kNe + "ne_110m_coastline.shx");
  REQUIRE(bytes.ok());
  REQUIRE(shx.ok());
  auto write = [&](const std::string& name, const std::vector<unsigned char>& b, std::size_t n) {
    write_bytes(dir / name, b, n);
  };
  SUBCASE("truncated .shp with its full .shx") {
    write("t.shp", *bytes, bytes->size() / 2);
    write("t.shx", *shx, shx->size());
    auto r = read_shapefile((dir / "t.shp").string());
    REQUIRE_FALSE(r.ok());
    // Refused from the .shp header before any record is read.
    CHECK(r.error().message == "header claims 89652 bytes, the file holds 44826 bytes");
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
}

// Lengths a header claims beyond the bytes the file holds: shapelib would allocate or seek
// by them (a negative record length sent SHPRestoreSHX round in circles for ever), so the
// reader refuses them first, naming the file and the numbers.
TEST_CASE("shapefile: header lengths beyond the file are refused before shapelib reads them") {
  const sm::testing::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path;
  auto shp = read_file_bytes(kNe + "ne_110m_coastline.shp");
  auto shx = read_file_bytes(kNe + "ne_110m_coastline.shx");
  REQUIRE(shp.ok());
  REQUIRE(shx.ok());
  auto write = [&](const std::string& name, const std::vector<unsigned char>& b) { write_bytes(dir / name, b); };
  auto put_be32 = [](std::vector<unsigned char>& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b[at + static_cast<std::size_t>(k)] = static_cast<unsigned char>(v >> (24 - 8 * k));
  };
  auto message = [&](const std::string& name) {
    auto r = read_shapefile((dir / name).string());
    REQUIRE_FALSE(r.ok());
    return r.error().to_string();
  };
  SUBCASE("the .shp header claims more bytes than the file holds") {
    auto b = *shp;
    put_be32(b, 24, 0xFFFFFFFFu);
    write("a.shp", b);
    write("a.shx", *shx);
    CHECK(message("a.shp") == (dir / "a.shp").string() +
                                  ": header claims 8589934590 bytes, the file holds 89652 bytes");
  }
  SUBCASE("the .shx header claims more entries than the file holds") {
    auto x = *shx;
    put_be32(x, 24, 0x7FFFFFFFu);
    write("b.shp", *shp);
    write("b.shx", x);
    CHECK(message("b.shp") == (dir / "b.shx").string() +
                                  ": header claims 4294967294 bytes, the file holds 1172 bytes");
  }
  SUBCASE("an index entry points past the records") {
    auto x = *shx;
    put_be32(x, 100 + 8 * 5 + 4, 0x40000000u);   // entry 5: a 2 GiB record
    write("c.shp", *shp);
    write("c.shx", x);
    const std::string m = message("c.shp");
    CHECK(m.find((dir / "c.shx").string() + ": record 5: the index entry claims a record at bytes ") == 0);
    CHECK(m.find("outside the 89652 bytes of records the .shp header claims") != std::string::npos);
  }
  SUBCASE("an index offset of 2^30 words or more (a byte offset that does not fit in 32 bits)") {
    auto x = *shx;
    put_be32(x, 100 + 8 * 3, 0x40010000u);   // entry 3 at byte 2 * 1073807360
    write("i.shp", *shp);
    write("i.shx", x);
    const std::string m = message("i.shp");
    CHECK(m.find((dir / "i.shx").string() + ": record 3: the index entry claims a record at bytes 2147614720 to ") ==
          0);
  }
  SUBCASE("no .shx and a negative record length (the loop shapelib's index rebuild never left)") {
    auto b = *shp;
    const std::size_t second = 100 + 8 + 2 * ((std::size_t{b[104]} << 24 | std::size_t{b[105]} << 16 |
                                               std::size_t{b[106]} << 8 | b[107]));
    put_be32(b, second + 4, 0xFFFFFFF0u);   // -16 words: back into the first record
    write("d.shp", b);
    CHECK(message("d.shp") == (dir / "d.shp").string() +
                                  ": record 1: the record header claims a record of -32 bytes, less than its "
                                  "4-byte shape type");
  }
  SUBCASE("no .shx and a record running past the end") {
    auto b = *shp;
    put_be32(b, 104, 0x00100000u);
    write("e.shp", b);
    const std::string m = message("e.shp");
    CHECK(m.find((dir / "e.shp").string() + ": record 0: the record header claims a record at bytes 100 to ") == 0);
  }
  SUBCASE("a file shorter than its header") {
    std::vector<unsigned char> b(shp->begin(), shp->begin() + 60);
    write("f.shp", b);
    write("f.shx", *shx);
    CHECK(message("f.shp") == (dir / "f.shp").string() + ": the file holds 60 bytes, less than the 100-byte header");
  }
  SUBCASE("the files as they are still read") {
    write("g.shp", *shp);
    write("g.shx", *shx);
    CHECK(read_shapefile((dir / "g.shp").string()).ok());
    write("h.shp", *shp);
    ShapefileInfo info;
    CHECK(read_shapefile((dir / "h.shp").string(), &info).ok());
    CHECK(info.index_rebuilt);
  }
}

TEST_CASE("shapefile: PolygonZ and PolyLineZ written from real data read back the same") {
  namespace fs = std::filesystem;
  auto src = read_shapefile(kNe + "ne_110m_land.shp");
  REQUIRE(src.ok());
  const fs::path dir = fs::temp_directory_path() / ("sm_coast_shpz_test_" + std::to_string(::getpid()));
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
