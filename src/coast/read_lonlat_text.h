// Reader for GMT multi-segment lon/lat text (data/gshhg/*.txt, `gmt coast -M`):
// '#' comments, '>' segment headers with key=value words, one "lon lat" pair per line.
#pragma once

#include <string>
#include <string_view>

#include "coast/coastline.h"

namespace sm::coast {

/// Totals announced in a file's comment line "# segments=.. closed=.. open=.. points=..";
/// when present they are checked, so a truncated file is an error, not a partial import.
/// Header words used: level, npts (checked against the points that follow), closed
/// (else closed iff the last point repeats the first), seg (the id). A "-R w/e/s/n" in the
/// first comment line sets Coastline::region.
Result<Coastline> read_lonlat_text(const std::string& path);
Result<Coastline> read_lonlat_text_string(std::string_view text, const std::string& name);

}  // namespace sm::coast
