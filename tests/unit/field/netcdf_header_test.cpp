// The classic netCDF header walk: counts that cannot fit in the file are refused, at
// every place a count sits, in CDF-1, CDF-2 and CDF-5; sound files pass.
#include "field/netcdf_header.h"

#include <unistd.h>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/lonlat_grid.h"

using namespace sm::field;
namespace fs = std::filesystem;

namespace {

// Which count of the header below gets a hostile value.
enum class Hostile { None, Dims, DimName, GlobalAtts, AttValues, Vars, VarDims, LastVarAtts, LastVarType };

// A classic header: dimensions lon = 3, lat = 2; a global text attribute; variables
// lon(lon) and lat(lat) with a units attribute, z(lat, lon) last. No data follows, and
// the begin offsets are 0: the walk reads counts only.
std::vector<unsigned char> header(int version, Hostile hostile, std::uint64_t huge) {
  const int w = version == 5 ? 8 : 4;
  std::vector<unsigned char> b = {'C', 'D', 'F', static_cast<unsigned char>(version)};
  auto u = [&](std::uint64_t v, int bytes) {
    for (int k = bytes - 1; k >= 0; --k) b.push_back(static_cast<unsigned char>(v >> (8 * k)));
  };
  auto count = [&](std::uint64_t v, Hostile at) { u(hostile == at ? huge : v, w); };
  auto text = [&](const std::string& s, Hostile at = Hostile::None) {
    count(s.size(), at);
    b.insert(b.end(), s.begin(), s.end());
    while (b.size() % 4) b.push_back(0);
  };
  auto units = [&](const std::string& s) {
    u(0x0C, 4), count(1, Hostile::None);
    text("units"), u(2, 4), text(s);   // NC_CHAR
  };
  u(0, w);   // numrecs
  u(0x0A, 4), count(2, Hostile::Dims);
  text("lon", Hostile::DimName), u(3, w);
  text("lat"), u(2, w);
  u(0x0C, 4), count(1, Hostile::GlobalAtts);
  text("title"), u(2, 4), count(2, Hostile::AttValues), b.insert(b.end(), {'a', 'b', 0, 0});
  u(0x0B, 4), count(3, Hostile::Vars);
  auto var_tail = [&](std::uint64_t type) { u(type, 4), u(8, w), u(0, version == 1 ? 4 : 8); };
  text("lon"), count(1, Hostile::VarDims), u(0, w), units("degrees_east"), var_tail(6);
  text("lat"), count(1, Hostile::None), u(1, w), units("degrees_north"), var_tail(6);
  text("z"), count(2, Hostile::None), u(1, w), u(0, w);
  u(0x0C, 4), count(0, Hostile::LastVarAtts);
  var_tail(hostile == Hostile::LastVarType ? huge : 5);
  return b;
}

std::optional<std::string> check(const std::vector<unsigned char>& bytes) {
  const fs::path p = fs::temp_directory_path() / ("sm_netcdf_header_test_" + std::to_string(::getpid()) + ".nc");
  {
    std::ofstream f(p, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  auto r = check_netcdf_header_counts(p);
  fs::remove(p);
  return r;
}

}  // namespace

TEST_CASE("netcdf header: counts beyond the file are refused wherever they are, in CDF-1, CDF-2 and CDF-5") {
  for (int version : {1, 2, 5}) {
    CAPTURE(version);
    const std::uint64_t huge = version == 5 ? (std::uint64_t{1} << 62) : 0xA8000001u;
    CHECK_FALSE(check(header(version, Hostile::None, 0)).has_value());
    struct Case { Hostile at; const char* what; };
    const Case cases[] = {{Hostile::Dims, " dimensions (at least "},
                          {Hostile::DimName, "a name of "},
                          {Hostile::GlobalAtts, " attributes of the file (at least "},
                          {Hostile::AttValues, " values in attribute 0 of the file (at least 1 byte each)"},
                          {Hostile::Vars, " variables (at least "},
                          {Hostile::VarDims, " dimension ids of variable 0 (at least "},
                          {Hostile::LastVarAtts, " attributes of variable 2 (at least "}};
    for (const Case& c : cases) {
      CAPTURE(std::string(c.what));
      const auto why = check(header(version, c.at, huge));
      REQUIRE(why.has_value());
      CHECK(why->find(std::to_string(huge)) != std::string::npos);
      CHECK_MESSAGE(why->find(c.what) != std::string::npos, *why);
      CHECK(why->find(" but the file holds ") != std::string::npos);
    }
  }
  // The minimum sizes are exact: a CDF-1 dimension takes 8 bytes, so a count of exactly
  // what is left / 8 passes the count check (and fails later, in libnetcdf, or not at all).
  const auto why = check(header(1, Hostile::Dims, 0xFFFFFFFFu));
  REQUIRE(why.has_value());
  CHECK(why->find("4294967295 dimensions (at least 8 bytes each)") != std::string::npos);
}

TEST_CASE("netcdf header: types outside the format are refused (NC_STRING in CDF-5 made libnetcdf divide by 0)") {
  // tests/fuzz/crashes_netcdf/cdf5_string_type_variable.nc is such a file from the fuzzer.
  const auto cdf5 = check(header(5, Hostile::LastVarType, 12));
  REQUIRE(cdf5.has_value());
  CHECK(*cdf5 == "variable 2 has type 12, not a type of this format (1 to 11)");
  const auto cdf1 = check(header(1, Hostile::LastVarType, 7));
  REQUIRE(cdf1.has_value());
  CHECK(*cdf1 == "variable 2 has type 7, not a type of this format (1 to 6)");
  CHECK_FALSE(check(header(5, Hostile::LastVarType, 11)).has_value());
}

TEST_CASE("netcdf header: an empty list with any tag is skipped, as libnetcdf reads it") {
  // tests/fuzz/crashes_netcdf/attribute_count_after_empty_list_with_odd_tag.nc: the global
  // attribute list has tag 0x00015B00 and count 0, then a variable declares 2818572289
  // attributes.
  std::string message;
  try {
    read_netcdf_grid(
        std::string(SM_TEST_DATA) + "/../fuzz/crashes_netcdf/attribute_count_after_empty_list_with_odd_tag.nc", {});
  } catch (const FieldError& e) {
    message = e.what();
  }
  CHECK(message.find("the header declares 2818572289 attributes of variable 0") != std::string::npos);
}

TEST_CASE("netcdf header: the fuzz finding's 2818572289 attributes are refused before nc_open") {
  // tests/fuzz/crashes_netcdf/attribute_count_beyond_file.nc: CDF-1, 446 bytes, whose
  // variable 'lon' declares 0xA8000001 attributes (libnetcdf allocated 2.5 GB for them).
  const std::string file = std::string(SM_TEST_DATA) + "/../fuzz/crashes_netcdf/attribute_count_beyond_file.nc";
  std::string message;
  try {
    read_netcdf_grid(file, {});
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::FileError);
    message = e.what();
  }
  CHECK(message == file + ": the header declares 2818572289 attributes of variable 0 (at least 12 bytes each) but "
                          "the file holds 366 more bytes");
}

TEST_CASE("netcdf header: the sound test grids and fuzz seeds pass the walk") {
  for (const char* f : {"/grids/small.nc", "/../fuzz/corpus_netcdf/small_classic.nc",
                        "/../fuzz/corpus_netcdf/small_64-bit-offset.nc", "/../fuzz/corpus_netcdf/small_cdf5.nc",
                        "/../fuzz/corpus_netcdf/small_nc4.nc", "/../fuzz/corpus_netcdf/global_1deg_8x6.nc"}) {
    CAPTURE(f);
    CHECK_FALSE(check_netcdf_header_counts(std::string(SM_TEST_DATA) + f).has_value());
  }
}

TEST_CASE("netcdf header: a header the file ends inside is refused (libnetcdf decodes past the end)") {
  // The fuzz finding: 158 bytes whose third list's first variable name runs to the end of
  // the file; nc_open then read a rank from beyond it and asked for 8 GB.
  const auto why = check_netcdf_header_counts(std::string(SM_TEST_DATA) +
                                              "/../fuzz/crashes_netcdf/header_cut_inside_variable_rank.nc");
  REQUIRE(why.has_value());
  CHECK(*why == "the header is cut short: the file ends inside variable 0");
}
