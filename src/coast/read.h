// One entry point for the four shoreline formats, named as in the import statement
// `Coastline[n] = GSHHS | Shapefile | LonLatText | Loops2;`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "coast/coastline.h"
#include "coast/read_loops2.h"

namespace sm::coast {

enum class CoastFormat { Gshhs, Shapefile, LonLatText, Loops2 };

/// "GSHHS", "Shapefile", "LonLatText", "Loops2" (case-insensitive); nullopt otherwise.
std::optional<CoastFormat> parse_coast_format(std::string_view name);
const char* coast_format_name(CoastFormat f);

/// Reads `path` in the given format (`loops2` options apply to Loops2 only).
Result<Coastline> read_coastline(CoastFormat format, const std::string& path, const Loops2Options& loops2 = {});

}  // namespace sm::coast
