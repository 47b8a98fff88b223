// Reader for Gmsh 2.x's "loops2" coastline text (Plugin(GSHHS) Format="loops2",
// docs/coastlines.md): blocks of "nPoints closed" then nPoints lines "c1 c2".
#pragma once

#include <string>
#include <string_view>

#include "coast/coastline.h"

namespace sm::coast {

enum class Loops2Coordinate {
  LonLatRadians,  // Coordinate = "lonlat"
  LonLatDegrees,  // "lonlat_degrees"
  Utm,            // "utm": easting/northing in metres, northern hemisphere, zone utm_zone
  Cartesian,      // "cartesian": (x, y, 0), projected radially onto the sphere
};

struct Loops2Options {
  Loops2Coordinate coordinate = Loops2Coordinate::LonLatDegrees;
  int utm_zone = 0;
  double utm_equatorial_radius = 6378137.0;   // Gmsh's UTMEquatorialRadius
  double utm_polar_radius = 6356752.3142;     // Gmsh's UTMPolarRadius
};

/// Parses Gmsh's Coordinate option string; nullopt when unknown.
std::optional<Loops2Coordinate> parse_loops2_coordinate(std::string_view s);

Result<Coastline> read_loops2(const std::string& path, const Loops2Options& opt = {});
Result<Coastline> read_loops2_string(std::string_view text, const std::string& name,
                                     const Loops2Options& opt = {});

}  // namespace sm::coast
