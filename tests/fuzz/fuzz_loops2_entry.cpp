// Fuzz entry: the loops2 reader, coordinate kind and UTM zone from the first byte.
#include <string_view>

#include "coast/read_loops2.h"
#include "fuzz_reader_checks.h"
#include "fuzz_reader_entries.h"

namespace sm::fuzz {

void run_loops2_input(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  coast::Loops2Options opt;
  static constexpr coast::Loops2Coordinate kKinds[] = {
      coast::Loops2Coordinate::LonLatRadians, coast::Loops2Coordinate::LonLatDegrees,
      coast::Loops2Coordinate::Utm, coast::Loops2Coordinate::Cartesian};
  opt.coordinate = kKinds[data[0] % 4];
  opt.utm_zone = 1 + (data[0] / 4) % 60;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  check_coastline("loops2", coast::read_loops2_string(text, "fuzz.loops2", opt));
}

}  // namespace sm::fuzz
