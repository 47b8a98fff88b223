// Fuzz entry: the netCDF grid reader on the input written to a scratch .nc file
// (libnetcdf opens paths; the reader's size checks read the file's length).
#include <cstdlib>

#include "field/error.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"
#include "fuzz_temp_file.h"

namespace sm::fuzz {

void run_netcdf_input(const std::uint8_t* data, std::size_t size) {
  const auto path = scratch_path("fuzz.nc");
  write_file(path, data, size);
  try {
    check_grid("netcdf", field::read_netcdf_grid(path, {}));
  } catch (const field::FieldError& e) {
    if (e.code() != field::FieldErrc::FileError) reader_violated("netcdf", "an error that is not a FileError");
  }
}

}  // namespace sm::fuzz
