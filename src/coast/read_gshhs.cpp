// GSHHS/GSHHG native binary reader. The flag word is byte-swapped BEFORE the level is
// taken from it (Gmsh 2.6's plugin tested the unswapped word: see docs/coastlines.md).
#include "coast/read_gshhs.h"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "coast/big_endian.h"
#include "coast/file_bytes.h"

namespace sm::coast {
namespace {


std::size_t header_size(GshhsLayout l) {
  switch (l) {
    case GshhsLayout::V1Flag: return 32;
    case GshhsLayout::V1Plain: return 36;
    default: return 44;
  }
}

const char* layout_name(GshhsLayout l) {
  switch (l) {
    case GshhsLayout::V1Flag: return "GSHHS 1.6-1.10 (32-byte header)";
    case GshhsLayout::V1Plain: return "GSHHS 1.2-1.5 (36-byte header)";
    default: return "GSHHS 2.x (44-byte header)";
  }
}

GshhsHeader decode(const unsigned char* p, GshhsLayout l) {
  GshhsHeader h;
  h.id = be32(p);
  h.n = be32(p + 4);
  h.flag = be32(p + 8);
  h.west = be32(p + 12);
  h.east = be32(p + 16);
  h.south = be32(p + 20);
  h.north = be32(p + 24);
  h.area = be32(p + 28);
  if (l == GshhsLayout::V2) {
    h.area_full = be32(p + 32);
    h.container = be32(p + 36);
    h.ancestor = be32(p + 40);
  } else if (l == GshhsLayout::V1Plain) {
    // The third word is the bare level; greenwich and source are 16-bit: fold them into
    // the flag layout of later versions so callers see one header.
    const int level = h.flag & 255;
    const int greenwich = be16(p + 32) & 1;
    const int source = be16(p + 34) & 1;
    h.flag = level | (greenwich << 16) | (source << 24);
    h.area_full = h.area;
  } else {
    h.area_full = h.area;
  }
  return h;
}

// Why a header cannot be a GSHHS record header; empty when it is plausible.
std::string implausible(const GshhsHeader& h, std::size_t remaining_after_header) {
  if (h.n < 0) return fmt::format("negative point count {}", h.n);
  if (static_cast<std::uint64_t>(h.n) * 8u > remaining_after_header)
    return fmt::format("point count {} needs {} bytes but only {} remain (truncated or corrupt file)",
                       h.n, static_cast<std::uint64_t>(h.n) * 8u, remaining_after_header);
  if (h.level() < 1 || h.level() > 6) return fmt::format("level {} is not 1..6", h.level());
  if (h.south < -90000000 || h.north > 90000000 || h.south > h.north)
    return fmt::format("latitude extent {}..{} micro-degrees is invalid", h.south, h.north);
  if (h.west < -360000000 || h.east > 540000000 || h.west > h.east)
    return fmt::format("longitude extent {}..{} micro-degrees is invalid", h.west, h.east);
  return {};
}

// Walks the headers only; returns an error message naming the first bad record, or empty
// when the layout tiles the file exactly.
std::string check_tiling(std::span<const unsigned char> b, GshhsLayout l, std::int64_t* bad_record) {
  const std::size_t hs = header_size(l);
  std::size_t off = 0;
  std::int64_t rec = 0;
  while (off < b.size()) {
    *bad_record = rec;
    if (b.size() - off < hs)
      return fmt::format("truncated header: {} bytes left, a {}-byte header expected", b.size() - off, hs);
    const GshhsHeader h = decode(b.data() + off, l);
    const std::string why = implausible(h, b.size() - off - hs);
    if (!why.empty()) return why;
    off += hs + static_cast<std::size_t>(h.n) * 8u;
    ++rec;
  }
  return {};
}

}  // namespace

Result<Coastline> read_gshhs_bytes(std::span<const unsigned char> b, const std::string& name,
                                   const GshhsOptions& opt) {
  if (b.empty()) return CoastError{name, -1, "empty file: no GSHHS record", {}};
  GshhsLayout layout = opt.layout;
  if (layout == GshhsLayout::Auto) {
    // Exactly one layout normally tiles the file with plausible headers; the newest wins
    // a tie. If none does, report the 2.x diagnosis (the format in use since 2008).
    std::int64_t bad_v2 = -1, bad = -1;
    const std::string why_v2 = check_tiling(b, GshhsLayout::V2, &bad_v2);
    if (why_v2.empty()) {
      layout = GshhsLayout::V2;
    } else if (check_tiling(b, GshhsLayout::V1Flag, &bad).empty()) {
      layout = GshhsLayout::V1Flag;
    } else if (check_tiling(b, GshhsLayout::V1Plain, &bad).empty()) {
      layout = GshhsLayout::V1Plain;
    } else {
      return CoastError{name, bad_v2, "not a GSHHS file in any known layout: " + why_v2, {}};
    }
  } else {
    std::int64_t bad = -1;
    const std::string why = check_tiling(b, layout, &bad);
    if (!why.empty()) return CoastError{name, bad, std::string(layout_name(layout)) + ": " + why, {}};
  }

  Coastline out;
  out.file = name;
  const std::size_t hs = header_size(layout);
  std::size_t off = 0;
  std::size_t rec = 0;
  while (off < b.size()) {
    const GshhsHeader h = decode(b.data() + off, layout);
    off += hs;
    Ring r;
    r.id = h.id;
    r.level = h.level();
    r.record = rec;
    r.closed = true;
    r.pts.reserve(static_cast<std::size_t>(h.n));
    for (std::int32_t i = 0; i < h.n; ++i, off += 8) {
      const std::int32_t x = be32(b.data() + off), y = be32(b.data() + off + 4);
      if (y < -90000000 || y > 90000000 || x < -360000000 || x > 540000000)
        return CoastError{name, static_cast<std::int64_t>(rec),
                          fmt::format("point {} ({} {}) micro-degrees is off the globe", i, x, y),
                          geo::LonLat{x * 1e-6, y * 1e-6}};
      r.pts.push_back({x * 1e-6, y * 1e-6});
    }
    const int p = h.area_magnitude();
    if (layout == GshhsLayout::V2 && p > 0)
      r.area_km2 = h.area / std::pow(10.0, p);
    else
      r.area_km2 = h.area / 10.0;
    normalise_ring(r);
    out.rings.push_back(std::move(r));
    ++rec;
  }
  return out;
}

Result<Coastline> read_gshhs(const std::string& path, const GshhsOptions& opt) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return read_gshhs_bytes(*bytes, path, opt);
}

}  // namespace sm::coast
