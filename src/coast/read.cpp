// Format dispatch for the shoreline readers.
#include "coast/read.h"

#include <algorithm>
#include <cctype>

#include "coast/read_gshhs.h"
#include "coast/read_lonlat_text.h"
#include "coast/read_shapefile.h"

namespace sm::coast {

std::optional<CoastFormat> parse_coast_format(std::string_view name) {
  std::string s(name);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (s == "gshhs") return CoastFormat::Gshhs;
  if (s == "gshhg") return CoastFormat::Gshhg;
  if (s == "shapefile") return CoastFormat::Shapefile;
  if (s == "lonlattext") return CoastFormat::LonLatText;
  if (s == "loops2") return CoastFormat::Loops2;
  return std::nullopt;
}

const char* coast_format_name(CoastFormat f) {
  switch (f) {
    case CoastFormat::Gshhs: return "GSHHS";
    case CoastFormat::Shapefile: return "Shapefile";
    case CoastFormat::LonLatText: return "LonLatText";
    case CoastFormat::Loops2: return "Loops2";
    case CoastFormat::Gshhg: return "GSHHG";
  }
  return "?";
}

Result<Coastline> read_coastline(CoastFormat format, const std::string& path, const Loops2Options& loops2,
                                 const GshhgBinnedOptions& gshhg) {
  switch (format) {
    case CoastFormat::Gshhs: return read_gshhs(path);
    case CoastFormat::Shapefile: return read_shapefile(path);
    case CoastFormat::LonLatText: return read_lonlat_text(path);
    case CoastFormat::Loops2: return read_loops2(path, loops2);
    case CoastFormat::Gshhg: return read_gshhg_binned(path, gshhg);
  }
  return CoastError{path, -1, "unknown coastline format", {}};
}

}  // namespace sm::coast
