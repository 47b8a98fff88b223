// The grid readers check what they read: hostile files of tests/data/grids (made by
// its make_grids.sh) are errors naming the file, the variable or line, and the value.
#include "field/lonlat_grid.h"

#include <string>

#include <doctest/doctest.h>

#include "field/error.h"

using namespace sm::field;

namespace {

const std::string kDir = std::string(SM_TEST_DATA) + "/grids/";

// The message of the FieldError reading `file` throws ("" when it reads).
std::string read_error(const std::string& file) {
  try {
    const std::string path = kDir + file;
    if (file.size() > 4 && file.substr(file.size() - 4) == ".asc")
      read_esri_ascii_grid(path);
    else
      read_netcdf_grid(path, {});
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    CHECK(e.file == kDir + file);
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("lonlat grid: the small sound grids read") {
  const LonLatGrid nc = read_netcdf_grid(kDir + "small.nc", {});
  CHECK(nc.nlon == 9);
  CHECK(nc.nlat == 7);
  CHECK(nc.at(8, 6) == -960);
  const LonLatGrid nc4 = read_netcdf_grid(kDir + "small_nc4.nc", {});
  CHECK(nc4.v == nc.v);
  const LonLatGrid asc = read_esri_ascii_grid(kDir + "small.asc");
  CHECK(asc.nlon == 3);
  CHECK(asc.at(2, 0) == -6);
}

TEST_CASE("lonlat grid: a netCDF file cut to half its bytes is an error naming the variable") {
  // Cut inside the values of z (the header and the coordinates are whole).
  const std::string classic = read_error("truncated_z.nc");
  CHECK(classic.find("variable 'z'") != std::string::npos);
  CHECK(classic.find("truncated") != std::string::npos);
  // Cut inside the header: refused before nc_open (field/netcdf_header.h), which would
  // decode past the end; netCDF-4 (HDF5): libnetcdf refuses the file itself.
  CHECK(read_error("truncated_half.nc").find("the header is cut short") != std::string::npos);
  CHECK(read_error("truncated_half_nc4.nc").find("truncated_half_nc4.nc") != std::string::npos);
}

TEST_CASE("lonlat grid: packing attributes must be finite, and scale_factor non-zero") {
  CHECK(read_error("offset_nan.nc").find("add_offset nan must be finite") != std::string::npos);
  CHECK(read_error("scale_zero.nc").find("scale_factor 0 must be finite and non-zero") != std::string::npos);
  // 1e300 is a finite scale: the values it gives (-1e302 .. -9.6e302) are caught by the
  // Bathymetry field's relief bound (bathymetry_test.cpp).
  CHECK(read_error("scale_1e300.nc").empty());
}

TEST_CASE("lonlat grid: nodes past the pole are an error") {
  CHECK(read_error("lat_past_pole.nc").find("latitudes 87 .. 93 are not in [-90, 90]") != std::string::npos);
}

TEST_CASE("lonlat grid: ESRI headers are checked before anything is allocated") {
  CHECK(read_error("huge_ncols.asc").find("line 1: ncols 4e9 must be a whole number from 2 to 2147483647") !=
        std::string::npos);
  CHECK(read_error("ncols_fraction.asc").find("line 1: ncols 3.5 must be a whole number") != std::string::npos);
  CHECK(read_error("cellsize_nan.asc").find("line 5: header 'cellsize' needs a finite number, not 'nan'") !=
        std::string::npos);
  CHECK(read_error("xll_nan.asc").find("line 3: header 'xllcorner'") != std::string::npos);
  CHECK(read_error("rows_missing.asc").find("2 x 3")  == std::string::npos);
  CHECK(read_error("rows_missing.asc").find("20 x 3 values") != std::string::npos);
}

TEST_CASE("lonlat grid: ESRI text from memory, bad data words named by line") {
  const std::string head = "ncols 2\nnrows 2\nxllcenter 0\nyllcenter 0\ncellsize 1\n";
  const LonLatGrid g = parse_esri_ascii_grid(head + "1 2\n3 4\n", "mem.asc");
  // Sizes an int holds, but 1.6e9 values cannot fit in 9 bytes of data.
  try {
    parse_esri_ascii_grid("ncols 40000\nnrows 40000\nxllcorner 0\nyllcorner 0\ncellsize 1e-3\n1 2\n3 4\n", "big.asc");
    FAIL("read");
  } catch (const FieldError& e) {
    CHECK(std::string(e.what()).find("big.asc: the header announces 40000 x 40000 values but only 9 bytes") !=
          std::string::npos);
  }
  CHECK(g.at(0, 1) == 1);
  CHECK(g.at(1, 0) == 4);
  auto error_of = [&](const std::string& text) -> std::string {
    try {
      parse_esri_ascii_grid(text, "mem.asc");
    } catch (const FieldError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error_of(head + "1 2\n3 inf\n").find("line 7: row 2 column 2: 'inf' is not a finite number") !=
        std::string::npos);
  CHECK(error_of(head + "1 2\n3 4 5\n").find("line 7: more values") != std::string::npos);
  CHECK(error_of(head + "ncols 2\n1 2\n3 4\n").find("line 6: header 'ncols' given twice") != std::string::npos);
  CHECK(error_of("ncols 2\nnrows 2\nxllcenter 0\nyllcenter 89.6\ncellsize 1\n1 2\n3 4\n")
            .find("latitudes") != std::string::npos);
  CHECK(error_of("ncols 2\nnrows 2\nxllcenter 0\nyllcenter 0\ncellsize -1\n1 2\n3 4\n")
            .find("line 5: cellsize -1 must be positive") != std::string::npos);
}
