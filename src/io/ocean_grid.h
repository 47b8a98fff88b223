// Grid files of the unstructured ocean models (ocean-tools §4): ADCIRC
// fort.14 and SCHISM hgrid.gr3 / hgrid.ll. Nodes in lon/lat degrees, depth
// positive down, triangles (and hgrid.gr3's quadrangles), and the open / land / island boundary strings the
// models force and close.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

/// One boundary string of the model grid, as node indices of MeshModel::xyz
/// in order along the boundary.
struct BoundaryString {
  enum class Kind { Open, Mainland, Island };
  Kind kind = Kind::Mainland;
  std::vector<std::uint32_t> nodes;  // islands: the closed loop, first node not repeated;
                                     // a closed mainland loop: first node repeated at the end
};

struct OceanGridOptions {
  std::string title = "stereomesh";
  Vec3 centre{0, 0, 0};             // the mesh's sphere, for lon/lat
  double radius = 1;
  bool lonlat = true;               // node coordinates as lon/lat degrees; false: x y as they are
  std::vector<double> depth;        // per MeshModel node, positive down; empty: 0 everywhere
  std::vector<BoundaryString> boundaries;
};

/// The grid as ADCIRC reads it (fort.14): mainland strings have IBTYPE 20 (a closed one
/// repeats its first node at the end, as given),
/// islands IBTYPE 21 with the first node repeated at the end (closed).
std::string fort14_to_string(const MeshModel& mesh, const OceanGridOptions& opt);
/// SCHISM's hgrid.gr3 layout (land flag 0, island flag 1: island loops not repeated, a closed
/// mainland loop as given, its first node repeated).
std::string gr3_to_string(const MeshModel& mesh, const OceanGridOptions& opt);

/// Writes atomically; *error is the reason on failure, without the path (see msh_writer.h).
bool save_fort14(const MeshModel& mesh, const OceanGridOptions& opt, const std::string& path, std::string* error);
/// Writes `path` (hgrid.gr3) with the coordinates chosen in opt, and the
/// sibling hgrid.ll in lon/lat (whose failure says "hgrid.ll beside it: ...").
bool save_schism(const MeshModel& mesh, const OceanGridOptions& opt, const std::string& gr3_path, std::string* error);

/// A fort.14 / hgrid.gr3 read back (tests and round trips).
struct OceanGrid {
  std::vector<Vec2> xy;
  std::vector<double> depth;
  std::vector<std::uint32_t> triangles;  // 0-based, 3 per triangle
  std::vector<std::uint32_t> quads;      // 0-based, 4 per quadrangle (hgrid.gr3)
  struct String {
    int type = 0;                        // IBTYPE (ADCIRC) or land flag (SCHISM); -1 for open
    std::vector<std::uint32_t> nodes;    // 0-based
  };
  std::vector<String> open, land;
};

/// Parses either format; on malformed input returns false with *error
/// naming the line.
bool parse_ocean_grid(const std::string& text, OceanGrid* grid, std::string* error);

}  // namespace sm::io
