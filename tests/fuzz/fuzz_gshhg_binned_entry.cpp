// Fuzz entry: the binned GSHHG reader on the input written to a scratch .nc file
// (libnetcdf opens paths); once with every level and Antarctica, once with a Region so
// that the bin selection and the whole-polygon pass run too.
#include "coast/read_gshhg_binned.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"
#include "fuzz_temp_file.h"

namespace sm::fuzz {

void run_gshhg_binned_input(const std::uint8_t* data, std::size_t size) {
  const auto path = scratch_path("fuzz_binned.nc");
  write_file(path, data, size);
  coast::GshhgBinnedOptions all;
  all.levels = {1, 2, 3, 4};
  check_coastline("gshhg_binned", coast::read_gshhg_binned(path.string(), all));
  coast::GshhgBinnedOptions box;
  box.antarctica_level = 6;
  box.region = coast::LonLatBox{170, 200, -20, 40};
  check_coastline("gshhg_binned", coast::read_gshhg_binned(path.string(), box));
}

}  // namespace sm::fuzz
