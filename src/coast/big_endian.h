// Signed big-endian integers from raw file bytes: GSHHS and the shapefile headers
// store their counts and coordinates this way, whatever the machine's byte order.
#pragma once

#include <cstdint>

namespace sm::coast {

inline std::int32_t be32(const unsigned char* p) {
  return static_cast<std::int32_t>((std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                                   (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]});
}

inline std::int16_t be16(const unsigned char* p) {
  return static_cast<std::int16_t>((std::uint16_t{p[0]} << 8) | std::uint16_t{p[1]});
}

}  // namespace sm::coast
