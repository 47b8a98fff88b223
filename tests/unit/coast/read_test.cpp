// Format dispatch: names of the import statement, each format on a real file.
#include "coast/read.h"

#include <doctest/doctest.h>

using namespace sm;
using namespace sm::coast;

TEST_CASE("read: format names and dispatch") {
  CHECK(parse_coast_format("GSHHS") == CoastFormat::Gshhs);
  CHECK(parse_coast_format("shapefile") == CoastFormat::Shapefile);
  CHECK(parse_coast_format("LonLatText") == CoastFormat::LonLatText);
  CHECK(parse_coast_format("Loops2") == CoastFormat::Loops2);
  CHECK(parse_coast_format("gshhg") == CoastFormat::Gshhg);
  CHECK(std::string(coast_format_name(CoastFormat::Gshhg)) == "GSHHG");
  CHECK_FALSE(parse_coast_format("GeoJSON").has_value());
  CHECK(std::string(coast_format_name(CoastFormat::LonLatText)) == "LonLatText");
  const std::string d = SM_DATA_DIR;
  auto g = read_coastline(CoastFormat::Gshhs, d + "/gshhs/gshhs_c.b");
  auto s = read_coastline(CoastFormat::Shapefile, d + "/naturalearth/ne_110m_land.shp");
  auto t = read_coastline(CoastFormat::LonLatText, d + "/gshhg/world_c.txt");
  auto l = read_coastline(CoastFormat::Loops2, std::string(SM_TEST_DATA) + "/coast/gb_islands_loops2.txt");
  REQUIRE(g.ok());
  REQUIRE(s.ok());
  REQUIRE(t.ok());
  REQUIRE(l.ok());
  CHECK(g->rings.size() == 1781);
  CHECK(s->rings.size() == 128);
  CHECK(t->rings.size() == 743);
  CHECK(l->rings.size() == 4);
  // The wrong reader on a file is an error, not garbage.
  CHECK_FALSE(read_coastline(CoastFormat::Gshhs, d + "/gshhg/world_c.txt").ok());
  CHECK_FALSE(read_coastline(CoastFormat::LonLatText, d + "/gshhs/gshhs_c.b").ok());
  CHECK_FALSE(read_coastline(CoastFormat::Shapefile, d + "/gshhg/world_c.txt").ok());
}
