#include <unistd.h>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/lonlat_grid.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;
using sm::field::testing::repo_data;

namespace {

FieldSet structured(const std::string& file, bool text) {
  FieldSet fs;
  fs.define(1, "Structured");
  fs.set(1, "FileName", file);
  fs.set(1, "TextFormat", text ? 1.0 : 0.0);
  return fs;
}

}  // namespace

TEST_CASE("structured: Gmsh text grid of the GBR relief equals the netCDF grid") {
  const std::string txt = repo_data("bathymetry/etopo5_gbr_5min.gmsh_structured.txt");
  FieldSet fs = structured(txt, true);
  const LonLatGrid nc = read_netcdf_grid(repo_data("bathymetry/etopo5_gbr_5min.nc"), {});
  // Nodes (ncdump: z(100,150) = -1511 at lon 152.5, lat -17.6667) and midpoints.
  CHECK(eval1(fs, 1, {152.5, -26 + 100.0 / 12, 0}) == doctest::Approx(-1511));
  CHECK(eval1(fs, 1, {152.5 + 1.0 / 24, -26 + 100.5 / 12, 0}) ==
        doctest::Approx((-1511 - 1581 - 1491 - 1496) / 4.0));
  for (double lon = 140.3; lon < 156; lon += 1.37)
    for (double lat = -25.8; lat < -9; lat += 0.91)
      CHECK(eval1(fs, 1, {lon, lat, 0}) == doctest::Approx(nc.interp(lon, lat)).epsilon(1e-9));
  // Outside: edges extend, or OutsideValue.
  CHECK(eval1(fs, 1, {130, -17.6666666666667, 0}) == doctest::Approx(nc.interp(140, -17.6666666666667)));
  fs.set(1, "SetOutsideValue", 1.0);
  fs.set(1, "OutsideValue", 77.0);
  CHECK(eval1(fs, 1, {130, -17, 0}) == 77);
  CHECK(eval1(fs, 1, {156, -17, 0}) == 77);  // the last node counts as outside (Gmsh)
  CHECK(eval1(fs, 1, {155.9, -17, 0}) != 77);
}

TEST_CASE("structured: binary format, and bad files") {
  const auto dir = std::filesystem::temp_directory_path() / ("sm_field_structured_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto bin = dir / "grid.bin";
  {
    // 2 x 3 x 2 grid, v = i + 10 j + 100 k, z fastest.
    std::ofstream out(bin, std::ios::binary);
    const double o[3] = {1, 2, 3}, d[3] = {0.5, 1, 2};
    const std::int32_t n[3] = {2, 3, 2};
    out.write(reinterpret_cast<const char*>(o), sizeof o);
    out.write(reinterpret_cast<const char*>(d), sizeof d);
    out.write(reinterpret_cast<const char*>(n), sizeof n);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 2; ++k) {
          const double v = i + 10 * j + 100 * k;
          out.write(reinterpret_cast<const char*>(&v), sizeof v);
        }
  }
  FieldSet fs = structured(bin.string(), false);
  CHECK(eval1(fs, 1, {1.25, 3.5, 4}) == doctest::Approx(0.5 + 15 + 50));
  CHECK(eval1(fs, 1, {1.5, 4, 5}) == doctest::Approx(1 + 20 + 100));
  // Relative names resolve against the context's directory.
  BuildContext ctx;
  ctx.base_dir = dir;
  FieldSet rel = structured("grid.bin", false);
  CHECK(eval1(rel, 1, {1, 2, 3}, ctx) == 0);
  // A NaN value is rejected with its node.
  {
    std::ofstream out(dir / "nan.txt");
    out << "0 0 0\n1 1 1\n2 2 1\n1 2 nan 4\n";
  }
  FieldSet nan = structured((dir / "nan.txt").string(), true);
  try {
    nan.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(std::string(e.what()).find("(1, 0, 0)") != std::string::npos);
  }
  // Truncated file, missing file, text read as binary.
  std::filesystem::resize_file(bin, 80);
  CHECK_THROWS_AS(fs.build(1, {}), FieldError);
  FieldSet missing = structured((dir / "nope.txt").string(), true);
  try {
    missing.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(e.field_id == 1);
  }
  FieldSet wrong = structured(repo_data("bathymetry/etopo5_gbr_5min.gmsh_structured.txt"), false);
  CHECK_THROWS_AS(wrong.build(1, {}), FieldError);
  std::filesystem::remove_all(dir);
}
