// What a picture of a mesh shows, independent of the file format: the view (plane, lon/lat,
// stereographic), the frame (a lon/lat box or the whole mesh), filled triangles, the
// boundary curves coloured by physical group, a labelled graticule, the worst triangles
// circled, and below the map a colour bar with units and a legend. svg_writer and
// png_writer are two back ends of one Scene.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

enum class PictureView {
  Plane,          // x, y as they are (planar meshes)
  LonLat,         // equirectangular lon/lat of points on the sphere
  Stereographic,  // Gmsh's PolarSphere (u, v) plane: the paper's Figure 4 view
};

/// Triangle fills: plain; quality in three classes (see QualityClass); a node field over
/// the range of the triangles drawn; size, the triangle's mean edge length in 3D on a log
/// scale from the smallest (blue) to the largest (red) triangle drawn, which shows a
/// multiscale mesh's grading; or a category per node (the size criterion), one colour per
/// value.
enum class PictureColour { None, Quality, NodeValue, Size, Category };

/// A zoom in degrees: west to east (east > west; east may pass 180 for a box across the
/// dateline, 170 to 190), south to north. In the plane view the same numbers bound x, y.
struct PictureBox {
  double west = 0, east = 0, south = 0, north = 0;
};

/// What keeps a box from framing a picture (the interpreter words it with the bounds):
/// a bound not finite, a longitude outside [-360, 360], a latitude outside [-90, 90],
/// south not below north, west = east, more than 360 degrees from west to east.
enum class PictureBoxProblem { None, NotFinite, Longitudes, Latitudes, SouthNotBelowNorth, NoWidth, TooWide };

/// None when `b` is a box a picture can frame, else what is wrong with it. W > E is read
/// as a box across the dateline (E + 360); the result is in `*out`.
PictureBoxProblem normalise_picture_box(double west, double east, double south, double north, PictureBox* out);

struct PictureOptions {
  PictureView view = PictureView::LonLat;
  Vec3 centre{0, 0, 0};  // sphere of the mesh (for LonLat and Stereographic)
  double radius = 1;
  PictureColour colour = PictureColour::None;
  std::vector<double> node_values;  // NodeValue, Category: one per node
  std::string node_values_title;    // NodeValue: the colour bar's title with units, "depth (m)"
  /// Category: the legend's text per value ("12 ShoreField (Threshold)"); values not
  /// listed are named by their number.
  std::vector<std::pair<double, std::string>> category_names;
  /// Size (km) and NodeValue: the values at the colour bar's ends, for pictures compared
  /// side by side; values beyond are drawn in the end colours. 0, 0: the drawn range.
  double colour_min = 0, colour_max = 0;
  /// Quality: triangles with rho below this are drawn in the alarm colour (the mesher's
  /// Mesh.QualityFloor; a picture of a mesh made without a floor still flags them).
  double quality_floor = 0.3;
  std::optional<PictureBox> box;    // the zoom; none: the whole mesh
  int worst = 0;                    // this many lowest-rho triangles drawn are circled
  double width_px = 1600;
  bool draw_triangles = true;       // false: only the boundary curves
  bool draw_points = false;         // the model points (point entities on the sphere) as dots:
                                    // a coastline's B-spline control points, Figure 5
  bool save_all = false;
  bool decorations = true;          // graticule, colour bar and legend (false: the map alone)
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb a, Rgb b) = default;
};

/// The drawing, in pixels with y down: the map (clipped to `map`) then the legend strip
/// below it. Both back ends draw the lists in the order declared here.
struct Scene {
  struct Triangle {
    std::array<Vec2, 3> p;
    Rgb fill;
  };
  struct Curve {
    std::vector<Vec2> p;
    std::uint32_t style = 0;            // index into curve_styles
  };
  struct CurveStyle {
    Rgb colour;
    std::string name;                   // the physical group's name (legend text)
  };
  struct Line {
    std::vector<Vec2> p;
    Rgb colour;
    double width = 1;
  };
  struct Circle {
    Vec2 centre;
    double radius = 1;
    Rgb colour;
    double width = 1;
  };
  struct Box {                          // a filled rectangle (colour bar cells, swatches)
    Vec2 lo, hi;
    Rgb fill;
  };
  enum class Anchor { Start, Middle, End };
  struct Text {
    Vec2 at;                            // the baseline's anchor point
    std::string text;                   // UTF-8
    double size = 12;                   // font size in pixels
    Anchor anchor = Anchor::Start;
    Rgb colour;
    bool halo = false;                  // outlined in the background colour (on the map)
  };
  struct GridLine {                     // a meridian or parallel, with its label
    std::vector<Vec2> p;
    bool meridian = false;
    double value = 0;                   // degrees
  };

  double width = 0, height = 0;         // pixels (not rounded)
  Box map{{0, 0}, {0, 0}, {}};          // the frame of the mesh: everything of the map is clipped to it
  Rgb background{0xf4, 0xf1, 0xea};
  bool draw_triangles = true;
  Rgb edge{0x3a, 0x5a, 0x78};           // triangle edges
  double edge_width = 0.2;              // 0: edges not drawn (triangles too small to see them)
  std::vector<Triangle> triangles;      // a triangle across the dateline appears twice
  Rgb graticule_colour{0x30, 0x30, 0x30};
  double graticule_width = 0.5;
  std::vector<GridLine> graticule;
  std::vector<CurveStyle> curve_styles; // [0]: curves in no physical group
  double curve_width = 1;
  std::vector<Curve> polylines;
  std::vector<Circle> marks;            // the worst triangles
  std::vector<Circle> points;           // the model points (filled dots)
  std::vector<Text> map_labels;         // graticule labels, on the map
  // The legend strip below the map.
  std::vector<Box> boxes;
  std::vector<Line> lines;
  std::vector<Circle> circles;
  std::vector<Text> texts;
  // What the legend shows, for tests and readers: the colour bar's title and range, and
  // the legend's entries in order.
  std::string bar_title;
  double bar_min = 0, bar_max = 0;      // the values at the bar's ends (km, node value)
  std::vector<std::string> legend;
};

/// Quality colours in three classes, because a mesh fit for an ocean model has almost every
/// triangle above rho 0.9: a continuous 0..1 scale paints it one colour and hides the few
/// triangles that matter. Below the floor (strong red) are those the model may choke on;
/// the worst 1% of the triangles drawn (orange) show where the mesher struggles; the rest
/// is a calm neutral that lets the coastlines and the two alarm colours stand out.
enum class QualityClass { BelowFloor, WorstPercent, Rest };
inline constexpr double kWorstFraction = 0.01;
/// The class of each triangle given its rho, in order: below `floor`; else among the
/// ceil(1% of n) lowest rho (ties by position, so the split is the same on every run);
/// else the rest.
std::vector<QualityClass> quality_classes(const std::vector<double>& rho, double floor);
Rgb quality_colour(QualityClass c);

/// Pictures are at most this many pixels in either direction (cairo's image limit is
/// 32767): a very tall frame is scaled down to fit.
inline constexpr double kMaxPicturePx = 16384;

/// The scene of `mesh` as `opt` asks: entities chosen as the MSH writers choose them (those
/// in physical groups when there are any, unless save_all); the frame of the box, or of the
/// drawn triangles and curves (the whole longitude range at most in lon/lat); triangles and
/// curve segments wholly outside the box left out; triangles across the dateline drawn on
/// both sides, curves split where they wrap. A regional lon/lat frame (under 180 degrees of
/// longitude) is drawn with x shrunk by the cosine of its middle latitude, so that shapes
/// there are true. Triangle edges are drawn only when the triangles' mean edge is at least
/// kMinEdgePx pixels (a dense mesh drawn small would otherwise be all edge colour).
inline constexpr double kMinEdgePx = 3;
Scene build_scene(const MeshModel& mesh, const PictureOptions& opt);

/// The graticule's step in degrees for a frame `extent` degrees across: the largest of
/// 1, 2, 5 x 10^k and 15, 30, 45, 60, 90 that gives at least three lines.
double graticule_step(double extent);

}  // namespace sm::io
