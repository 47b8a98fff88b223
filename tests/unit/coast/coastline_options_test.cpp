// The coastline option table (coast/coastline_options.def): docs/interpreter.md carries its
// generated reference verbatim, every option is set by some test, and each row's setter
// writes the member its row names.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "coast/coastline_options.h"
#include "generated_docs.h"

using namespace sm::coast;

namespace {

// Every option a test sets in script form (`Coastline[1].Name = ...`): in a script test of
// tests/scripts or in a script a unit test runs.
std::set<std::string> options_set_by_tests() {
  std::set<std::string> found;
  // Coastline[...] only: Field[1].FileName or Field[1].Resolution set a field's option.
  const std::regex set_re(R"(Coastline\[[^\]]*\]\.([A-Za-z]+)\s*=[^=])");
  for (const char* dir : {"/tests/scripts", "/tests/unit"}) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(SM_SOURCE_DIR) + dir)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".geo" && ext != ".cpp")) continue;
      if (e.path().filename() == "coastline_options_test.cpp") continue;   // this file names them all
      std::ifstream in(e.path());
      std::stringstream ss;
      ss << in.rdbuf();
      const std::string text = ss.str();
      for (std::sregex_iterator it(text.begin(), text.end(), set_re), end; it != end; ++it)
        if (find_coast_option((*it)[1].str())) found.insert((*it)[1].str());
    }
  }
  return found;
}

CoastOptionValue numbers(const std::vector<double>& x) {
  CoastOptionValue v;
  v.nums = x;
  return v;
}

CoastOptionValue text(std::string_view s) {
  CoastOptionValue v;
  v.is_string = true;
  v.strings = 1;
  v.str = s;
  return v;
}

}  // namespace

TEST_CASE("docs/interpreter.md holds the generated coastline option table") {
  sm::testing::check_generated_section(std::string(SM_SOURCE_DIR) + "/docs/interpreter.md",
                                       "<!-- BEGIN GENERATED: sm::coast::coast_options_markdown() -->\n",
                                       "<!-- END GENERATED -->", coast_options_markdown(),
                                       "SM_UPDATE_COAST_OPTION_DOCS");
}

TEST_CASE("coastline options: every option is set by a script test") {
  // Options no test sets yet: to be emptied, not grown (a listed option that a test
  // comes to set must leave the list).
  const std::set<std::string> without_test = {};
  const std::set<std::string> found = options_set_by_tests();
  for (const CoastOptionSpec& o : coast_options()) {
    const std::string name(o.name);
    INFO(name);
    CHECK((found.count(name) == 1) != (without_test.count(name) == 1));
  }
}

TEST_CASE("coastline options: names unique, the enum in the table's order, each row complete") {
  std::set<std::string_view> names;
  std::size_t i = 0;
  for (const CoastOptionSpec& o : coast_options()) {
    INFO(o.name);
    CHECK(names.insert(o.name).second);
    CHECK(&coast_option(static_cast<CoastOpt>(i++)) == &o);
    CHECK(find_coast_option(o.name) == &o);
    CHECK(!o.help.empty());
    CHECK(!o.values.empty());
    CHECK(!o.target.empty());
    CHECK(static_cast<bool>(o.apply));
    CHECK(static_cast<bool>(o.default_of));
  }
  CHECK(coast_option_name(CoastOpt::MinChannelWidth) == "MinChannelWidth");
  CHECK(find_coast_option("minchannelwidth") == nullptr);   // exact, as the script spells it
}

TEST_CASE("coastline options: each setter writes the member its row names") {
  const CoastlineSettings defaults;
  CoastlineSettings s;
  const double w = 2000, factor = 0.25;
  coast_option(CoastOpt::MinChannelWidth).apply(s, numbers({w}));
  CHECK(s.import.passages.min_width == w);
  CHECK(coast_option(CoastOpt::MinChannelWidth).target == "import.passages.min_width");
  CHECK(coast_option(CoastOpt::MinChannelWidth).default_of(defaults) == "0");
  CHECK(coast_option(CoastOpt::MinChannelWidth).default_of(s) == "2000");
  coast_option(CoastOpt::DeviationFactor).apply(s, numbers({factor}));
  CHECK(s.import.deviation.factor == factor);
  CHECK(coast_option(CoastOpt::DeviationFactor).default_of(defaults) == "0.5");
  coast_option(CoastOpt::CloseStraits).apply(s, numbers({1}));
  CHECK(s.import.repair.close_straits);
  coast_option(CoastOpt::MinArea).apply(s, numbers({10}));
  CHECK(s.import.coarsen.min_area_km2 == 10);
  coast_option(CoastOpt::Levels).apply(s, numbers({1, 2}));
  CHECK(s.import.levels == std::vector<int>{1, 2});
  coast_option(CoastOpt::Dams).apply(s, numbers({1, 2, 3, 4}));
  REQUIRE(s.import.passages.dams.size() == 1);
  CHECK(s.import.passages.dams[0].second.lat == 4);
  coast_option(CoastOpt::SeaAt).apply(s, numbers({5, 6, 7, 8}));
  REQUIRE(s.import.sea_at.size() == 2);
  CHECK(s.import.sea_at[1].lon == 7);
  coast_option(CoastOpt::CurveType).apply(s, text("Line"));
  CHECK_FALSE(s.import.deviation.bspline);
  CHECK(coast_option(CoastOpt::CurveType).default_of(defaults) == "`\"BSpline\"`");
  coast_option(CoastOpt::Coordinate).apply(s, text("utm"));
  CHECK(s.loops2.coordinate == Loops2Coordinate::Utm);
  coast_option(CoastOpt::UTMZone).apply(s, numbers({31}));
  CHECK(s.loops2.utm_zone == 31);
  // A box, then a polygon, whose bounding box the readers clip to.
  coast_option(CoastOpt::Region).apply(s, numbers({-10, 5, 45, 60}));
  REQUIRE(s.import.region);
  CHECK(s.import.region->west == -10);
  CHECK(s.import.region_polygon.empty());
  coast_option(CoastOpt::Region).apply(s, numbers({0, 50, 4, 50, 2, 53}));
  CHECK(s.import.region_polygon.size() == 3);
  REQUIRE(s.import.region);
  CHECK(s.import.region->north >= 53);
  CHECK(s.import.region->south <= 50);
}

TEST_CASE("coastline options: values checked by type, then by the row's check") {
  const CoastOptionSpec& width = coast_option(CoastOpt::MinChannelWidth);
  CHECK(check_coast_option(width, numbers({100})) == std::nullopt);
  CHECK(check_coast_option(width, numbers({-1})) == "must not be negative (0 is off), not -1");
  CHECK(check_coast_option(width, numbers({1, 2})) == "takes one number, not a list of 2");
  CHECK(check_coast_option(width, numbers({std::nan("")})) == "is not finite");
  CHECK(check_coast_option(width, text("x")) == "takes a number");
  const CoastOptionSpec& flag = coast_option(CoastOpt::KeepPassages);
  CHECK(check_coast_option(flag, numbers({2})) == "must be 0 or 1, not 2");
  CHECK(check_coast_option(flag, numbers({1})) == std::nullopt);
  const CoastOptionSpec& file = coast_option(CoastOpt::FileName);
  CHECK(check_coast_option(file, text("")) == "is empty");
  CHECK(check_coast_option(file, numbers({1})) == "takes one string");
  CHECK(check_coast_option(coast_option(CoastOpt::Region), numbers({0, 1, 2})).has_value());
  CHECK(check_coast_option(coast_option(CoastOpt::KeepOpen), numbers({0, 91})) ==
        "has latitude 91 (value 2): latitudes lie in [-90, 90]");
  CHECK(check_coast_option(coast_option(CoastOpt::Levels), numbers({})) == "is empty: no shoreline would be kept");
  CHECK(check_coast_option(coast_option(CoastOpt::CurveType), text("Spline")) ==
        "must be \"BSpline\" or \"Line\", not \"Spline\"");
}
