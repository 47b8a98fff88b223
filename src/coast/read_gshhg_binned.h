// Reader for GMT's binned GSHHG shorelines (binned_GSHHS_{c,l,i,h,f}.nc, netCDF-4), the
// files Debian's gmt-gshhg-low/-high/-full install: each polygon is stored as one piece
// per square bin it crosses, quantised to 1/65535 of the bin's side; the reader joins the
// pieces head to tail into the rings every other reader returns (coastline.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

/// Where Debian's gmt-gshhg packages put the files.
inline constexpr std::string_view kGshhgSystemDir = "/usr/share/gmt-gshhg";

struct GshhgBinnedOptions {
  /// GSHHS levels kept among 1 land, 2 lake, 3 island in lake, 4 pond (5 and 6 listed
  /// here keep Antarctica's ice front or grounding line as antarctica_level does).
  std::vector<int> levels{1};
  /// Antarctica: 5 the ice front (GMT's default, -A+ai), 6 the grounding line (-A+ag),
  /// 0 none. Its rings come out with that level (see read_gshhg_binned).
  int antarctica_level = 5;
  /// Polygons whose area (GSHHG's full-resolution area, km^2) is below this are dropped,
  /// as GMT's -A<min_area>.
  double min_area_km2 = 0;
  /// Only the polygons with a piece in a bin overlapping this box are read (whole: their
  /// pieces in the other bins too); longitudes compared modulo 360.
  std::optional<LonLatBox> region;
  /// Threads joining the polygons' pieces into rings (<= 0: the hardware concurrency): the
  /// same rings for every count.
  int threads = 1;
};

/// True for the resolution letters c, l, i, h, f.
bool is_gshhg_resolution(std::string_view r);
/// The file of a resolution in `dir`: dir/binned_GSHHS_<r>.nc.
std::string gshhg_binned_file(char resolution, std::string_view dir = kGshhgSystemDir);
/// The Debian package holding a resolution's file: gmt-gshhg-low (c, l), gmt-gshhg-high
/// (i, h), gmt-gshhg-full (f); nullptr for another letter.
const char* gshhg_package(char resolution);

/// Reads one binned file. Every count is checked against the sizes the file declares
/// (and those against the file's length) before anything is allocated or indexed, and a
/// piece chain that does not close is an error: a corrupt file is a CoastError naming
/// the file, never a crash. A missing file named binned_GSHHS_<r>.nc names the package.
///
/// Rings: one per polygon (GSHHG id in Ring::id, first segment in Ring::record), in
/// polygon order (largest first), closed, contiguous longitudes; Antarctica's continent
/// is one wraps_pole ring from lon 180 to -180. Levels 1-4 as stored; the segments GMT
/// flags as Antarctica's ice front get level 5, its grounding line 6; with
/// antarctica_level 6 the ice-front islands that have no grounding-line twin (every
/// ice-flagged polygon but the continent, which GMT keeps with -A+ag) get level 6 too,
/// so the one level names the whole chosen Antarctic coast. area_km2: |area| (GSHHG
/// stores river-lakes with a negative area).
Result<Coastline> read_gshhg_binned(const std::string& path, const GshhgBinnedOptions& opt = {});

}  // namespace sm::coast
