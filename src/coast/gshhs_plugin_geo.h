// Gmsh 2.6's Plugin(GSHHS), rebuilt on the coast kernel (docs/coastlines.md): reads a
// GSHHS binary or loops2 file, coarsens it with the iField accuracy, and writes the .geo
// text the plugin wrote, with its bugs fixed (see write_gshhs_plugin_geo).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "coast/coarsen.h"
#include "coast/import.h"

namespace sm::coast {

/// The plugin's options, with Gmsh's names and defaults.
struct GshhsPluginOptions {
  std::string in_file_name = "gshhs_c.b";   // InFileName
  std::string out_file_name = "earth.geo";  // OutFileName
  AccuracyFn field;                         // iField (-1 = none: every distinct point is kept)
  std::string format = "gshhs";             // Format: "gshhs" or "loops2"
  std::string coordinate = "cartesian";     // Coordinate (loops2): lonlat, lonlat_degrees, utm, cartesian
  int utm_zone = 0;                         // UTMZone
  double utm_equatorial_radius = 6378137;   // UTMEquatorialRadius
  double utm_polar_radius = 6356752.3142;   // UTMPolarRadius
  double radius = 6371009;                  // radius (metres)
  int write_polar_sphere = 1;  // WritePolarSphere: 1 sphere + (u,v); 0 (u,v) only; -2 plane (xi,eta) in metres
  double min_straits_factor = 1;            // MinStraitsFactor (> 0: straits narrower than factor*gamma are closed)
};

struct GshhsPluginResult {
  CoastModel model;
  std::vector<CoastCurve> cut;   // open polylines left by negative field values (cropping)
  std::string geo;               // the text written to out_file_name
};

/// The .geo text for a model. Tags are relative (IP = newp; ...) so the file can be
/// included into a model. Differences from Gmsh 2.6, all fixes:
/// - the Plane Surface (outer loop first, then the holes) is written for each surface;
/// - the coastline size field is `Distance` with `PointsList` (Gmsh 4.8.4 has no Attractor);
/// - GSHHG >= 2.2 levels are read after byte swapping (lakes no longer leak in);
/// - cut coastlines are closed along the region box and grouped as Physical Curve("open").
/// `cut`: open polylines written after the loops as curves of their own (no loop), as the
/// plugin did for loops cut by negative field values.
std::string write_gshhs_plugin_geo(const CoastModel& m, const GshhsPluginOptions& opt,
                                   std::span<const CoastCurve> cut = {});

/// Runs the plugin: read, import (levels {1} + Antarctica), write the file. As in Gmsh 2.6,
/// a negative iField value cuts a loop at that point (the way to crop to a region): the cut
/// loops become open polylines, coarsened but not part of any loop or surface; a zero value
/// keeps every point.
Result<GshhsPluginResult> run_gshhs_plugin(const GshhsPluginOptions& opt);

}  // namespace sm::coast
