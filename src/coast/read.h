// One entry point for the shoreline formats, named as in the import statement
// `Coastline[n] = GSHHS | GSHHG | Shapefile | LonLatText | Loops2;`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "coast/coastline.h"
#include "coast/read_gshhg_binned.h"
#include "coast/read_loops2.h"

namespace sm::coast {

/// Gshhs: the native GSHHS binary; Gshhg: GMT's binned netCDF files (read_gshhg_binned.h).
enum class CoastFormat { Gshhs, Shapefile, LonLatText, Loops2, Gshhg };

/// "GSHHS", "GSHHG", "Shapefile", "LonLatText", "Loops2" (case-insensitive); nullopt otherwise.
std::optional<CoastFormat> parse_coast_format(std::string_view name);
const char* coast_format_name(CoastFormat f);

/// Reads `path` in the given format (`loops2` options apply to Loops2 only, `gshhg` to
/// GSHHG only: that reader selects levels, area and region itself).
Result<Coastline> read_coastline(CoastFormat format, const std::string& path, const Loops2Options& loops2 = {},
                                 const GshhgBinnedOptions& gshhg = {});

}  // namespace sm::coast
