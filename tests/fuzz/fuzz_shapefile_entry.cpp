// Fuzz entry: the shapefile reader on a .shp/.shx/.dbf triple cut from one input
// (layout in fuzz_reader_entries.h), written to this process's scratch directory.
#include <algorithm>
#include <system_error>

#include "coast/read_shapefile.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"
#include "fuzz_temp_file.h"

namespace sm::fuzz {
namespace {

std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
}

}  // namespace

void run_shapefile_input(const std::uint8_t* data, std::size_t size) {
  if (size < 8) return;
  std::size_t rest = size - 8;
  const std::uint8_t* p = data + 8;
  const std::size_t shp_len = std::min<std::size_t>(le32(data), rest);
  const std::size_t shx_len = std::min<std::size_t>(le32(data + 4), rest - shp_len);
  const auto shp = scratch_path("fuzz.shp"), shx = scratch_path("fuzz.shx"), dbf = scratch_path("fuzz.dbf");
  write_file(shp, p, shp_len);
  std::error_code ec;
  std::filesystem::remove(shx, ec);
  if (shx_len > 0) write_file(shx, p + shp_len, shx_len);
  write_file(dbf, p + shp_len + shx_len, rest - shp_len - shx_len);
  check_coastline("shapefile", coast::read_shapefile(shp.string()));
}

}  // namespace sm::fuzz
