// Fuzz entry: the binned GSHHG reader on the input written to a scratch .nc file
// (libnetcdf opens paths); once with every level and Antarctica, once with a Region so
// that the bin selection and the whole-polygon pass run too.
//
// Inputs in HDF5's container (netCDF-4, as the system's files are) are skipped: a mutated
// HDF5 file crashes libhdf5 itself inside nc_open (a double free in H5MM_xfree, found by
// this target), which no check of ours before or after the call can prevent. The reader's
// own checks (counts, offsets, tiling, chains) are the same for every container, so the
// classic container exercises all of them; the system's files come from Debian's package.
#include <cstring>

#include "coast/read_gshhg_binned.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"
#include "fuzz_temp_file.h"

namespace sm::fuzz {

void run_gshhg_binned_input(const std::uint8_t* data, std::size_t size) {
  static constexpr char kHdf5Signature[] = "\x89HDF\r\n\x1a\n";
  if (size >= 8 && std::memcmp(data, kHdf5Signature, 8) == 0) return;
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
