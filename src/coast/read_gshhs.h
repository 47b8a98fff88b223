// Reader for the native GSHHS/GSHHG binary shoreline files, versions 1.x to 2.3
// (Wessel & Smith 1996; layout in docs/coastlines.md section 2).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "coast/coastline.h"

namespace sm::coast {

/// Record header layouts met in the wild; every integer is big-endian.
enum class GshhsLayout {
  Auto,      // pick the one layout that tiles the whole file exactly (see read_gshhs)
  V2,        // 2.0-2.3: 11 int32 (id n flag w e s n area area_full container ancestor), 44 bytes
  V1Flag,    // 1.6-1.10: 8 int32 (id n flag w e s n area), 32 bytes
  V1Plain,   // 1.2-1.5: 8 int32 (id n level w e s n area) + int16 greenwich + int16 source, 36 bytes
};

struct GshhsOptions {
  GshhsLayout layout = GshhsLayout::Auto;
};

/// Decoded header of one record (after byte swapping).
struct GshhsHeader {
  std::int32_t id = 0, n = 0, flag = 0, west = 0, east = 0, south = 0, north = 0;
  std::int32_t area = 0, area_full = 0, container = -1, ancestor = -1;
  int level() const { return flag & 255; }
  int version() const { return (flag >> 8) & 255; }
  int greenwich() const { return (flag >> 16) & 3; }
  int source() const { return (flag >> 24) & 1; }
  int river() const { return (flag >> 25) & 1; }
  int area_magnitude() const { return static_cast<int>(static_cast<std::uint32_t>(flag) >> 26); }
};

/// Reads every record (all levels; filtering is the caller's business). Points are
/// micro-degrees; longitudes (stored in [0,360), Antarctica in [-180,180]) are made
/// contiguous per ring. Areas: km2 * 10^p when p = flag>>26 > 0 (>= 2.2), else 1/10 km2.
Result<Coastline> read_gshhs(const std::string& path, const GshhsOptions& opt = {});
/// Same, from bytes already in memory (`name` is used in errors).
Result<Coastline> read_gshhs_bytes(std::span<const unsigned char> bytes, const std::string& name,
                                   const GshhsOptions& opt = {});

}  // namespace sm::coast
