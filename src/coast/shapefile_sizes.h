// Size checks of a shapefile's .shp and .shx headers against the bytes the files hold,
// made with plain reads before shapelib opens them (ESRI Shapefile Technical Description).
#pragma once

#include <filesystem>
#include <optional>

#include "coast/coastline.h"

namespace sm::coast {

/// shapelib trusts the lengths a header claims: it allocates the index a .shx header
/// announces, and SHPRestoreSHX follows the .shp record lengths without bounds (a
/// negative one sends it back to an earlier record, for ever). This checks, reading
/// only headers:
///  - the .shp header's file length is no more than the .shp holds;
///  - with a .shx (`shx` not empty): its header's file length is no more than it holds,
///    and every index entry names a record of at least 4 bytes (its shape type) lying
///    inside the .shp's claimed length;
///  - without one: the chain of record headers from byte 100 tiles the claimed length
///    the same way (what SHPRestoreSHX walks).
/// Returns the first violation, naming the file and the numbers; nullopt when all hold.
std::optional<CoastError> check_shapefile_sizes(const std::filesystem::path& shp, const std::filesystem::path& shx);

}  // namespace sm::coast
