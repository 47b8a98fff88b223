// The scene of a mesh picture (see picture.h): projection, box and frame, colours, the
// graticule, the worst triangles, and the layout of the colour bar and legend.
#include "io/picture.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

#include "exact/quality.h"
#include "geo/sphere.h"

namespace sm::io {
namespace {

constexpr double kEps = 1e-9;

// Colour ramp for values in [0, 1]: blue (low) to red (high) through white,
// readable in print and by most colour-blind readers.
Rgb ramp(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  auto mix = [](double a, double b, double s) { return static_cast<std::uint8_t>(std::lround(a + (b - a) * s)); };
  if (t < 0.5) {
    const double s = t / 0.5;
    return {mix(49, 247, s), mix(54, 247, s), mix(149, 247, s)};
  }
  const double s = (t - 0.5) / 0.5;
  return {mix(247, 165, s), mix(247, 0, s), mix(247, 38, s)};
}

// Distinct colours for categories (size criteria) and for physical curve groups other than
// "coast" (the coastline red) and "open" (green): none close to the blue-white-red ramp's
// middle, so that they read on any fill.
constexpr std::array<Rgb, 8> kCategoryColours = {{{0x1b, 0x9e, 0x77}, {0xd9, 0x5f, 0x02}, {0x75, 0x70, 0xb3},
                                                  {0xe7, 0x29, 0x8a}, {0x66, 0xa6, 0x1e}, {0xe6, 0xab, 0x02},
                                                  {0xa6, 0x76, 0x1d}, {0x66, 0x66, 0x66}}};
constexpr std::array<Rgb, 6> kGroupColours = {{{0xe0, 0x82, 0x14}, {0x76, 0x2a, 0x83}, {0x01, 0x66, 0x5e},
                                               {0x00, 0x00, 0x00}, {0x8c, 0x51, 0x0a}, {0xc5, 0x1b, 0x7d}}};
constexpr Rgb kCoastColour{0xb2, 0x18, 0x2b};
constexpr Rgb kOpenColour{0x1a, 0x98, 0x50};
constexpr Rgb kTextColour{0x20, 0x20, 0x20};
constexpr Rgb kMarkColour{0x00, 0x00, 0x00};
constexpr Rgb kPointColour{0x08, 0x30, 0x6b};
// Quality classes (picture.h): red and orange for the alarms, a pale grey-blue for the bulk,
// lighter than the plain fill so that the alarms are the only saturated colours on the map.
constexpr Rgb kBelowFloorColour{0xd7, 0x19, 0x1c};
constexpr Rgb kWorstPercentColour{0xfd, 0xae, 0x61};
constexpr Rgb kGoodQualityColour{0xe6, 0xea, 0xee};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// "0.5°E", "10°W", "0°", "180°": a meridian's label, any longitude brought into (-180, 180].
std::string lon_label(double lon) {
  lon = std::remainder(lon, 360.0);
  if (lon <= -180 + kEps) lon = 180;
  const double a = std::round(std::abs(lon) * 1e6) / 1e6;
  if (a == 0 || a == 180) return fmt::format("{:g}\u00b0", a);
  return fmt::format("{:g}\u00b0{}", a, lon < 0 ? 'W' : 'E');
}

std::string lat_label(double lat) {
  const double a = std::round(std::abs(lat) * 1e6) / 1e6;
  if (a == 0) return "0\u00b0";
  return fmt::format("{:g}\u00b0{}", a, lat < 0 ? 'S' : 'N');
}

// Text width estimate for the layout (a sans-serif font averages about 0.55 em per
// character); UTF-8 continuation bytes do not count.
double text_width(const std::string& s, double size) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return 0.55 * size * static_cast<double>(n);
}

// Ticks for a linear scale from lo to hi: multiples of 1, 2 or 5 x 10^k, about five.
std::vector<double> linear_ticks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / 5;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * p;
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  for (double v = std::ceil(lo / step - kEps) * step; v <= hi + kEps * step; v += step)
    ticks.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  return ticks;
}

// Ticks for a log scale from lo to hi (> 0): 1, 2, 5 x 10^k, only the powers of ten when
// that gives too many; the two ends when fewer than two fall inside.
std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> ticks;
  for (const std::vector<double>& mantissas : {std::vector<double>{1, 2, 5}, std::vector<double>{1}}) {
    ticks.clear();
    for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= static_cast<int>(std::ceil(std::log10(hi))); ++k)
      for (double m : mantissas) {
        const double v = m * std::pow(10.0, k);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) ticks.push_back(v);
      }
    if (ticks.size() <= 8) break;
  }
  if (ticks.size() < 2) ticks = {lo, hi};
  return ticks;
}

// The vertices' positions in the view's plane (y up; flipped into pixels later). In lon/lat
// a longitude is taken within 180 degrees of `lon_centre`, the middle of the box.
struct Projection {
  const MeshModel& m;
  const PictureOptions& opt;
  geo::PolarSphere sphere;
  double lon_centre = 0;
  std::vector<Vec2> p;       // view coordinates
  std::vector<Vec2> ll;      // lon (near lon_centre), lat; the plane view: x, y

  Projection(const MeshModel& mesh, const PictureOptions& o)
      : m(mesh), opt(o), sphere(o.centre, o.radius), lon_centre(o.box ? 0.5 * (o.box->west + o.box->east) : 0.0) {
    p.resize(m.xyz.size());
    ll.resize(m.xyz.size());
    for (std::size_t i = 0; i < m.xyz.size(); ++i) {
      if (opt.view == PictureView::Plane) {
        p[i] = ll[i] = {m.xyz[i].x, m.xyz[i].y};
        continue;
      }
      const geo::LonLat g = sphere.to_lonlat(m.xyz[i]);
      ll[i] = {lon_centre + std::remainder(g.lon - lon_centre, 360.0), g.lat};
      p[i] = opt.view == PictureView::LonLat ? ll[i] : sphere.param(m.xyz[i]);
    }
  }
  bool on_sphere() const { return opt.view != PictureView::Plane; }
  // A lon/lat point in the view's plane.
  Vec2 view_of(double lon, double lat) const {
    if (opt.view == PictureView::Stereographic) return sphere.param_from_lonlat({lon, lat});
    return {lon, lat};
  }
};

// Whether the lon/lat (or plane x, y) bounding box of `q` meets the box.
template <std::size_t N>
bool meets_box(const PictureBox& b, const std::array<Vec2, N>& q) {
  double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
  for (const Vec2& r : q)
    x0 = std::min(x0, r.x), x1 = std::max(x1, r.x), y0 = std::min(y0, r.y), y1 = std::max(y1, r.y);
  return x1 >= b.west && x0 <= b.east && y1 >= b.south && y0 <= b.north;
}

}  // namespace

PictureBoxProblem normalise_picture_box(double west, double east, double south, double north, PictureBox* out) {
  for (double v : {west, east, south, north})
    if (!std::isfinite(v)) return PictureBoxProblem::NotFinite;
  if (west < -360 || west > 360 || east < -360 || east > 360) return PictureBoxProblem::Longitudes;
  if (south < -90 || north > 90) return PictureBoxProblem::Latitudes;
  if (!(south < north)) return PictureBoxProblem::SouthNotBelowNorth;
  if (west == east) return PictureBoxProblem::NoWidth;
  // W > E: the box crosses the dateline (170, -170 is 170 to 190).
  const double e = west > east ? east + 360 : east;
  if (e - west > 360) return PictureBoxProblem::TooWide;
  *out = {west, e, south, north};
  return PictureBoxProblem::None;
}

std::vector<QualityClass> quality_classes(const std::vector<double>& rho, double floor) {
  std::vector<QualityClass> cls(rho.size(), QualityClass::Rest);
  std::vector<std::size_t> by_rho(rho.size());
  std::iota(by_rho.begin(), by_rho.end(), std::size_t{0});
  const std::size_t worst = std::min(
      rho.size(), static_cast<std::size_t>(std::ceil(kWorstFraction * static_cast<double>(rho.size()) - kEps)));
  std::partial_sort(by_rho.begin(), by_rho.begin() + static_cast<std::ptrdiff_t>(worst), by_rho.end(),
                    [&](std::size_t a, std::size_t b) { return rho[a] < rho[b] || (rho[a] == rho[b] && a < b); });
  for (std::size_t k = 0; k < worst; ++k) cls[by_rho[k]] = QualityClass::WorstPercent;
  for (std::size_t i = 0; i < rho.size(); ++i)
    if (rho[i] < floor) cls[i] = QualityClass::BelowFloor;
  return cls;
}

Rgb quality_colour(QualityClass c) {
  switch (c) {
    case QualityClass::BelowFloor: return kBelowFloorColour;
    case QualityClass::WorstPercent: return kWorstPercentColour;
    case QualityClass::Rest: break;
  }
  return kGoodQualityColour;
}

double graticule_step(double extent) {
  static constexpr double kSteps[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 15, 30, 45, 60, 90};
  for (double s : kSteps)
    if (extent / s <= 6 + kEps) return s;
  return 90;
}

namespace {

// A triangle drawn: its nodes, the pixels of its first copy (for its mark) and its copies
// in Scene::triangles (two when it wraps across the lon/lat seam).
struct Drawn {
  std::array<std::uint32_t, 3> v;
  std::array<Vec2, 3> px;   // the first copy drawn, for its mark
  std::size_t first_tri = 0, copies = 0;   // its copies in sc.triangles
};

// An entry of the legend under the map.
struct LegendEntry {
  enum Kind { Curve, Mark, Swatch, Dot } kind;
  Rgb colour;
  std::string text;
};

// The scene's state between its stages (build_scene below): the projection and the frame,
// the triangles drawn and their colour ranges, what the legend and the colour bar show.
struct SceneWork {
  const MeshModel& m;
  const PictureOptions& opt;
  const Projection proj;
  const std::vector<Vec2>& p;
  const std::vector<Vec2>& ll;
  bool has_physicals = false;
  std::vector<std::size_t> order;
  bool lonlat;
  bool categories;

  // The frame in view coordinates and its scale to pixels.
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0, kx = 1, scale = 1;
  double curve_width = 1, margin = 1, font = 9;

  Scene sc;
  std::vector<Drawn> drawn;
  std::map<double, std::size_t> category_index;   // value -> colour, by increasing value
  double vmin = 0, vmax = 1;                       // PictureColour::NodeValue's range
  std::vector<double> drawn_rho;                   // each drawn triangle's rho
  std::vector<QualityClass> classes;
  std::array<std::size_t, 3> class_count{};
  std::array<double, 3> class_lo{1, 1, 1}, class_hi{0, 0, 0};   // rho range per class
  double log_lo = 0, log_span = 1;   // PictureColour::Size: log of the edge length range
  double size_lo = 0, size_hi = 0;
  std::vector<bool> style_used;
  std::size_t point_count = 0;
  std::vector<std::pair<double, std::string>> ticks;   // position 0..1 along the bar, label
  Rgb (*bar_colour)(double) = nullptr;
  std::vector<LegendEntry> entries;

  SceneWork(const MeshModel& mesh, const PictureOptions& o)
      : m(mesh), opt(o), proj(mesh, o), p(proj.p), ll(proj.ll), order(entity_order(mesh)),
        lonlat(o.view == PictureView::LonLat),
        categories(o.colour == PictureColour::Category && o.node_values.size() == mesh.xyz.size()) {
    for (const EntityMesh& e : m.entities) has_physicals |= !e.physical_tags.empty();
  }
  SceneWork(const SceneWork&) = delete;
  SceneWork& operator=(const SceneWork&) = delete;

  bool saved(const EntityMesh& e) const { return opt.save_all || !has_physicals || !e.physical_tags.empty(); }

  // A triangle's copies in the view: in lon/lat one across the seam (lon_centre + 180)
  // has vertices on both sides; it is drawn shifted to either side and the frame clips it.
  // Each copy in lon/lat (or x, y) for the box test, and the shifts it is drawn with.
  bool unwrap(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::array<Vec2, 3>& q) const {
    q = {ll[a], ll[b], ll[c]};
    if (!proj.on_sphere()) return false;
    const double lo = std::min({q[0].x, q[1].x, q[2].x}), hi = std::max({q[0].x, q[1].x, q[2].x});
    if (hi - lo <= 180) return false;
    for (Vec2& r : q)
      if (r.x < proj.lon_centre) r.x += 360;
    return true;
  }
  static std::array<Vec2, 3> shifted(std::array<Vec2, 3> q, double s) {
    for (Vec2& r : q) r.x += s;
    return q;
  }
  Vec2 px(Vec2 q) const { return Vec2{margin + (q.x - x0) * kx * scale, margin + (y1 - q.y) * scale}; }
  // A copy's view coordinates: in lon/lat its shifted lon/lat, else the projection.
  std::array<Vec2, 3> view3(const std::array<std::uint32_t, 3>& v, const std::array<Vec2, 3>& q) const {
    return lonlat ? q : std::array<Vec2, 3>{p[v[0]], p[v[1]], p[v[2]]};
  }
  double mean_edge(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    return (norm(m.xyz[b] - m.xyz[a]) + norm(m.xyz[c] - m.xyz[b]) + norm(m.xyz[a] - m.xyz[c])) / 3;
  }
  // Categories: the value most of a triangle's nodes have (the smallest of three different).
  double category_of(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const double va = opt.node_values[a], vb = opt.node_values[b], vc = opt.node_values[c];
    if (va == vb || va == vc) return va;
    if (vb == vc) return vb;
    return std::min({va, vb, vc});
  }
  bool node_values_fit() const { return opt.node_values.size() == m.xyz.size(); }
};

// The frame in view coordinates: the box's, or that of the drawn curves and triangles (at
// most the whole longitude range in lon/lat). Model points (a PolarSphere's centre and
// pole, say) are not drawn and do not count. Then the scale, the picture's size and widths.
void frame_scene(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  auto grow = [&](Vec2 q) {
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) return;
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  };
  if (opt.box && opt.view != PictureView::Stereographic) {
    x0 = opt.box->west, x1 = opt.box->east, y0 = opt.box->south, y1 = opt.box->north;
  } else if (opt.box) {
    // The box's image: a grid over it (the pole of the projection excluded).
    constexpr int kSamples = 32;
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 0; j <= kSamples; ++j) {
        const double lon = opt.box->west + (opt.box->east - opt.box->west) * i / kSamples;
        const double lat = std::max(-89.0, opt.box->south + (opt.box->north - opt.box->south) * j / kSamples);
        grow(w.proj.view_of(lon, lat));
      }
  } else {
    for (const EntityMesh& e : w.m.entities) {
      if (e.type == ElementType::Point1 || !w.saved(e)) continue;
      for (std::uint32_t v : e.connectivity) grow(w.p[v]);
    }
    if (w.lonlat) x0 = std::max(x0, -180.0), x1 = std::min(x1, 180.0);
  }
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > y0)) y0 = 0, y1 = 1;
  // A regional lon/lat frame keeps shapes at its middle latitude true.
  const double kx = w.lonlat && x1 - x0 < 180 ? std::max(0.05, std::cos(0.5 * (y0 + y1) * geo::kDegToRad)) : 1.0;

  // A margin as wide as the coastlines, so that curves on the frame are drawn whole.
  const double curve_width = std::max(1.0, opt.width_px / 1000.0);
  const double margin = curve_width;
  const double font = std::clamp(opt.width_px / 60, 9.0, 32.0);
  double scale = std::max(1.0, opt.width_px - 2 * margin) / ((x1 - x0) * kx);
  if ((y1 - y0) * scale + 2 * margin > kMaxPicturePx) scale = (kMaxPicturePx - 2 * margin) / (y1 - y0);
  w.x0 = x0, w.y0 = y0, w.x1 = x1, w.y1 = y1, w.kx = kx, w.scale = scale;
  w.curve_width = curve_width, w.margin = margin, w.font = font;

  Scene& sc = w.sc;
  sc.width = (x1 - x0) * kx * scale + 2 * margin;
  sc.height = (y1 - y0) * scale + 2 * margin;
  sc.map = {{margin, margin}, {sc.width - margin, sc.height - margin}, {}};
  sc.draw_triangles = opt.draw_triangles;
  sc.edge_width = std::max(0.15, opt.width_px / 8000.0);
  // Coastlines a few pixels wide whatever the mesh's density, so they stand out.
  sc.curve_width = curve_width;
  sc.graticule_width = std::max(0.6, opt.width_px / 1200.0);
}

// The triangles drawn: those of the saved surfaces whose lon/lat box meets the box; the
// categories they hold, numbered by increasing value.
void collect_triangles(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  for (std::size_t i : w.order) {
    const EntityMesh& e = w.m.entities[i];
    if (e.type != ElementType::Triangle3 || !w.saved(e)) continue;
    for (std::size_t k = 0; k + 2 < e.connectivity.size(); k += 3) {
      const std::array<std::uint32_t, 3> v{e.connectivity[k], e.connectivity[k + 1], e.connectivity[k + 2]};
      std::array<Vec2, 3> q;
      const bool wraps = w.unwrap(v[0], v[1], v[2], q);
      std::array<bool, 2> keep{true, wraps};
      for (int c = 0; c < 2; ++c)
        if (keep[c] && opt.box) keep[c] = meets_box(*opt.box, SceneWork::shifted(q, c == 0 ? 0.0 : -360.0));
      if (!keep[0] && !keep[1]) continue;
      if (w.categories) w.category_index.emplace(w.category_of(v[0], v[1], v[2]), 0);
      Drawn d{v, {}, w.sc.triangles.size(), 0};
      bool first = true;
      // In the stereographic view a triangle has one place, however it wraps in lon/lat.
      for (int c = 0; c < (w.lonlat ? 2 : 1); ++c) {
        if (w.lonlat && !keep[c]) continue;
        const std::array<Vec2, 3> u = w.view3(v, SceneWork::shifted(q, c == 0 ? 0.0 : -360.0));
        const std::array<Vec2, 3> t{w.px(u[0]), w.px(u[1]), w.px(u[2])};
        if (first) d.px = t, first = false;
        if (opt.draw_triangles) w.sc.triangles.push_back({t, Rgb{}}), ++d.copies;
      }
      w.drawn.push_back(d);
    }
  }
  std::size_t n = 0;
  for (auto& [value, index] : w.category_index) index = n++;
}

// The colour ranges, now that the triangles drawn are known. A node field's range is that
// of the nodes of the triangles drawn, so that a regional picture spreads the colours over
// its own depths (the whole mesh's range would paint a shelf one colour).
void measure_colour_ranges(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  if (opt.colour == PictureColour::NodeValue && w.node_values_fit()) {
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const Drawn& d : w.drawn)
      for (std::uint32_t v : d.v)
        if (std::isfinite(opt.node_values[v]))
          lo = std::min(lo, opt.node_values[v]), hi = std::max(hi, opt.node_values[v]);
    if (lo <= hi) w.vmin = lo, w.vmax = hi > lo ? hi : lo + 1;
    if (opt.colour_max > opt.colour_min) w.vmin = opt.colour_min, w.vmax = opt.colour_max;
  }
  // Each drawn triangle's rho, for the quality classes and the worst triangles.
  if (opt.colour == PictureColour::Quality || opt.worst > 0) {
    w.drawn_rho.reserve(w.drawn.size());
    for (const Drawn& d : w.drawn) w.drawn_rho.push_back(rho(w.m.xyz[d.v[0]], w.m.xyz[d.v[1]], w.m.xyz[d.v[2]]));
  }
  if (opt.colour == PictureColour::Quality) {
    w.classes = quality_classes(w.drawn_rho, opt.quality_floor);
    for (std::size_t i = 0; i < w.classes.size(); ++i) {
      const auto k = static_cast<std::size_t>(w.classes[i]);
      ++w.class_count[k];
      w.class_lo[k] = std::min(w.class_lo[k], w.drawn_rho[i]), w.class_hi[k] = std::max(w.class_hi[k], w.drawn_rho[i]);
    }
  }
  if (opt.colour == PictureColour::Size) {
    double lo = std::numeric_limits<double>::max(), hi = 0;
    for (const Drawn& d : w.drawn) {
      const double l = w.mean_edge(d.v[0], d.v[1], d.v[2]);
      if (l > 0) lo = std::min(lo, l), hi = std::max(hi, l);
    }
    if (opt.colour_max > opt.colour_min && opt.colour_min > 0) lo = 1000 * opt.colour_min, hi = 1000 * opt.colour_max;
    if (hi > 0)
      w.log_lo = std::log(lo), w.log_span = hi > lo ? std::log(hi / lo) : 1, w.size_lo = lo, w.size_hi = hi;
  }
}

// Each drawn triangle's fill (on all its copies); no edges when they would be shorter on
// average than kMinEdgePx.
void fill_triangles(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  Scene& sc = w.sc;
  if (opt.draw_triangles) {
    for (std::size_t i = 0; i < w.drawn.size(); ++i) {
      const Drawn& d = w.drawn[i];
      const auto [a, b, c] = d.v;
      Rgb fill{0xdf, 0xe9, 0xf2};
      if (opt.colour == PictureColour::Quality) {
        fill = quality_colour(w.classes[i]);
      } else if (opt.colour == PictureColour::NodeValue && w.node_values_fit()) {
        const double v = (opt.node_values[a] + opt.node_values[b] + opt.node_values[c]) / 3;
        fill = ramp((v - w.vmin) / (w.vmax - w.vmin));
      } else if (opt.colour == PictureColour::Size) {
        const double l = w.mean_edge(a, b, c);
        fill = ramp(l > 0 ? (std::log(l) - w.log_lo) / w.log_span : 0.0);
      } else if (w.categories) {
        fill = kCategoryColours[w.category_index.at(w.category_of(a, b, c)) % kCategoryColours.size()];
      }
      for (std::size_t k = 0; k < d.copies; ++k) sc.triangles[d.first_tri + k].fill = fill;
    }
  }
  if (!sc.triangles.empty()) {
    double sum = 0;
    for (const Scene::Triangle& t : sc.triangles)
      sum += norm(t.p[1] - t.p[0]) + norm(t.p[2] - t.p[1]) + norm(t.p[0] - t.p[2]);
    if (sum / (3.0 * static_cast<double>(sc.triangles.size())) < kMinEdgePx) sc.edge_width = 0;
  }
}

// The curves as polylines. Curve styles: [0] the curves of no physical group, then one per
// physical curve group (by tag) that has a drawn segment; an entity in several groups is
// drawn in its first.
void draw_curves(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  Scene& sc = w.sc;
  const std::vector<Vec2>& ll = w.ll;
  sc.curve_styles.push_back({kCoastColour, "boundary curves"});
  std::vector<const PhysicalGroup*> groups;
  for (const PhysicalGroup& g : w.m.physicals)
    if (g.dim == 1) groups.push_back(&g);
  std::sort(groups.begin(), groups.end(),
            [](const PhysicalGroup* a, const PhysicalGroup* b) { return a->tag < b->tag; });
  std::map<int, std::uint32_t> style_of_group;   // physical tag -> curve style
  std::size_t next_group_colour = 0;
  auto style_for = [&](const EntityMesh& e) -> std::uint32_t {
    const PhysicalGroup* first = nullptr;
    for (const PhysicalGroup* g : groups)
      if (std::find(e.physical_tags.begin(), e.physical_tags.end(), g->tag) != e.physical_tags.end()) {
        first = g;
        break;
      }
    if (!first) return 0;
    if (auto it = style_of_group.find(first->tag); it != style_of_group.end()) return it->second;
    const std::string name = first->name.empty() ? fmt::format("Physical Curve {}", first->tag) : first->name;
    Rgb colour = kGroupColours[next_group_colour % kGroupColours.size()];
    if (lower(first->name) == "coast") colour = kCoastColour;
    else if (lower(first->name) == "open") colour = kOpenColour;
    else ++next_group_colour;
    sc.curve_styles.push_back({colour, name});
    return style_of_group[first->tag] = static_cast<std::uint32_t>(sc.curve_styles.size() - 1);
  };
  std::vector<bool>& style_used = w.style_used;
  style_used.assign(1, false);
  for (std::size_t i : w.order) {
    const EntityMesh& e = w.m.entities[i];
    if (e.type != ElementType::Line2 || !w.saved(e)) continue;
    // Consecutive segments of a curve share nodes: emit maximal chains, breaking them
    // where the lon/lat view wraps at the seam and where a segment is outside the box.
    std::vector<Vec2> chain;
    std::uint32_t last = 0xFFFFFFFFu;
    std::uint32_t style = 0xFFFFFFFFu;
    auto flush = [&] {
      if (chain.size() > 1) sc.polylines.push_back({std::move(chain), style});
      chain.clear();
    };
    for (std::size_t k = 0; k + 1 < e.connectivity.size(); k += 2) {
      const std::uint32_t a = e.connectivity[k], b = e.connectivity[k + 1];
      const bool seam = w.proj.on_sphere() && std::abs(ll[a].x - ll[b].x) > 180;
      const bool jump = seam && w.lonlat;
      bool outside = false;
      if (opt.box && !jump) {
        std::array<Vec2, 2> q{ll[a], ll[b]};
        if (seam)
          for (Vec2& r : q)
            if (r.x < w.proj.lon_centre) r.x += 360;
        outside =
            !meets_box(*opt.box, q) &&
            !(seam && meets_box(*opt.box, std::array<Vec2, 2>{Vec2{q[0].x - 360, q[0].y}, Vec2{q[1].x - 360, q[1].y}}));
      }
      if (jump || outside) {
        flush();
        last = 0xFFFFFFFFu;
        continue;
      }
      if (style == 0xFFFFFFFFu) {
        style = style_for(e);
        style_used.resize(sc.curve_styles.size(), false);
        style_used[style] = true;
      }
      if (a != last) {
        flush();
        chain.push_back(w.px(w.p[a]));
      }
      chain.push_back(w.px(w.p[b]));
      last = b;
    }
    flush();
  }
  style_used.resize(sc.curve_styles.size(), false);
}

// The model points as dots (those on the sphere: a PolarSphere's centre is not), inside
// the box when there is one.
void draw_points(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  if (!opt.draw_points) return;
  const double r = std::max(1.5, 1.5 * w.curve_width);
  for (std::size_t i : w.order) {
    const EntityMesh& e = w.m.entities[i];
    if (e.type != ElementType::Point1 || !w.saved(e)) continue;
    for (std::uint32_t v : e.connectivity) {
      if (w.proj.on_sphere() && std::abs(norm(w.m.xyz[v] - opt.centre) - opt.radius) > 1e-6 * opt.radius) continue;
      if (!std::isfinite(w.p[v].x) || !std::isfinite(w.p[v].y)) continue;
      if (opt.box && !meets_box(*opt.box, std::array<Vec2, 1>{w.ll[v]})) continue;
      w.sc.points.push_back({w.px(w.p[v]), r, kPointColour, 0});
      ++w.point_count;
    }
  }
}

// The worst triangles drawn, circled: by increasing rho, ties by drawing order.
void mark_worst_triangles(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  if (opt.worst <= 0 || w.drawn.empty()) return;
  const double font = w.font;
  std::vector<std::pair<double, std::size_t>> by_rho(w.drawn.size());
  for (std::size_t i = 0; i < w.drawn.size(); ++i) by_rho[i] = {w.drawn_rho[i], i};
  const std::size_t n = std::min(by_rho.size(), static_cast<std::size_t>(opt.worst));
  std::partial_sort(by_rho.begin(), by_rho.begin() + static_cast<std::ptrdiff_t>(n), by_rho.end());
  for (std::size_t k = 0; k < n; ++k) {
    const std::array<Vec2, 3>& t = w.drawn[by_rho[k].second].px;
    const Vec2 c = (t[0] + t[1] + t[2]) / 3.0;
    const double r = std::max({0.7 * font, norm(t[0] - c), norm(t[1] - c), norm(t[2] - c)}) + 2;
    w.sc.marks.push_back({c, r, kMarkColour, std::max(1.0, font / 8)});
  }
  w.sc.legend.push_back(n == 1 ? fmt::format("the worst triangle (rho {:.2f})", by_rho[0].first)
                               : fmt::format("the {} worst triangles (rho {:.2f} to {:.2f})", n, by_rho[0].first,
                                             by_rho[n - 1].first));
}

// Each graticule label where its line first enters the map, nudged inside; one that would
// overlap a label already placed is left out (parallels crowd near a pole).
void label_graticule(SceneWork& w) {
  Scene& sc = w.sc;
  const double lf = 0.8 * w.font;
  std::vector<std::array<double, 4>> placed;   // x0, y0, x1, y1
  auto overlaps = [&](const std::array<double, 4>& r) {
    return std::any_of(placed.begin(), placed.end(), [&](const std::array<double, 4>& o) {
      return r[0] < o[2] && o[0] < r[2] && r[1] < o[3] && o[1] < r[3];
    });
  };
  for (const Scene::GridLine& g : sc.graticule) {
    const std::string text = g.meridian ? lon_label(g.value) : lat_label(g.value);
    for (const Vec2& q : g.p) {
      if (!(q.x >= sc.map.lo.x - kEps && q.x <= sc.map.hi.x + kEps && q.y >= sc.map.lo.y - kEps &&
            q.y <= sc.map.hi.y + kEps))
        continue;
      const double tw = text_width(text, lf);
      const double left = sc.map.lo.x + 0.2 * lf, top = sc.map.lo.y + lf;
      const Vec2 at{std::clamp(q.x + 0.25 * lf, left, std::max(left, sc.map.hi.x - tw)),
                    std::clamp(q.y - 0.3 * lf, top, std::max(top, sc.map.hi.y - 0.3 * lf))};
      const std::array<double, 4> rect{at.x - 0.2 * lf, at.y - lf, at.x + tw + 0.2 * lf, at.y + 0.3 * lf};
      if (!overlaps(rect)) {
        placed.push_back(rect);
        sc.map_labels.push_back({at, text, lf, Scene::Anchor::Start, kTextColour, true});
      }
      break;
    }
  }
}

// The graticule: meridians and parallels at a round step over the frame's lon/lat range
// (the box's; in the stereographic view without a box, that of the drawn nodes).
void draw_graticule(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  if (!opt.decorations || !w.proj.on_sphere()) return;
  double lon_lo = w.x0, lon_hi = w.x1, lat_lo = w.y0, lat_hi = w.y1;
  if (opt.view == PictureView::Stereographic) {
    if (opt.box) {
      lon_lo = opt.box->west, lon_hi = opt.box->east, lat_lo = opt.box->south, lat_hi = opt.box->north;
    } else {
      lon_lo = lat_lo = std::numeric_limits<double>::max(), lon_hi = lat_hi = -lon_lo;
      for (const Drawn& d : w.drawn)
        for (std::uint32_t v : d.v)
          lon_lo = std::min(lon_lo, w.ll[v].x), lon_hi = std::max(lon_hi, w.ll[v].x),
          lat_lo = std::min(lat_lo, w.ll[v].y), lat_hi = std::max(lat_hi, w.ll[v].y);
      if (w.drawn.empty()) lon_lo = -180, lon_hi = 180, lat_lo = -90, lat_hi = 90;
      if (lon_hi - lon_lo > 180) lon_lo = -180, lon_hi = 180;
    }
  }
  const bool whole_circle = lon_hi - lon_lo >= 360 - kEps;
  const double lon_step = graticule_step(lon_hi - lon_lo), lat_step = graticule_step(lat_hi - lat_lo);
  // In lon/lat lines on the frame's edges are the frame; in the stereographic view only the
  // meridian at the end of a whole circle repeats the first.
  const bool skip_edges = w.lonlat;
  const double s_lo = std::max(lat_lo, -89.0), s_hi = std::min(lat_hi, 90.0);
  for (double v = std::ceil(lon_lo / lon_step - kEps) * lon_step; v <= lon_hi + kEps; v += lon_step) {
    if ((skip_edges && (v < lon_lo + kEps || v > lon_hi - kEps)) || (whole_circle && v > lon_hi - kEps)) continue;
    Scene::GridLine g{{}, true, v};
    for (int j = 0; j <= 64; ++j) g.p.push_back(w.px(w.proj.view_of(v, s_lo + (s_hi - s_lo) * j / 64)));
    w.sc.graticule.push_back(std::move(g));
  }
  for (double v = std::ceil(lat_lo / lat_step - kEps) * lat_step; v <= lat_hi + kEps; v += lat_step) {
    if ((skip_edges && (v < lat_lo + kEps || v > lat_hi - kEps)) || std::abs(v) >= 90 - kEps || v < -89) continue;
    Scene::GridLine g{{}, false, v};
    for (int j = 0; j <= 180; ++j) g.p.push_back(w.px(w.proj.view_of(lon_lo + (lon_hi - lon_lo) * j / 180, v)));
    w.sc.graticule.push_back(std::move(g));
  }
  label_graticule(w);
}

// The colour bar's title, range and ticks.
void scale_colour_bar(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  Scene& sc = w.sc;
  if (!opt.draw_triangles || w.drawn.empty()) return;
  if (opt.colour == PictureColour::Quality) {
    // No bar: the classes are swatches in the legend, under this title.
    sc.bar_title = "quality rho = 2 r_in / r_circ (1: equilateral)";
  } else if (opt.colour == PictureColour::Size && w.size_hi > 0) {
    sc.bar_title = "size: mean edge length (km, log scale)";
    sc.bar_min = w.size_lo / 1000, sc.bar_max = w.size_hi / 1000;
    for (double v : log_ticks(sc.bar_min, sc.bar_max))
      w.ticks.push_back({w.size_hi > w.size_lo ? std::log(v / sc.bar_min) / std::log(sc.bar_max / sc.bar_min) : 0.5,
                         fmt::format("{:.3g}", v)});
    w.bar_colour = [](double s) { return ramp(s); };
  } else if (opt.colour == PictureColour::NodeValue && w.node_values_fit()) {
    sc.bar_title = opt.node_values_title.empty() ? "node value" : opt.node_values_title;
    sc.bar_min = w.vmin, sc.bar_max = w.vmax;
    for (double v : linear_ticks(w.vmin, w.vmax))
      w.ticks.push_back({(v - w.vmin) / (w.vmax - w.vmin), fmt::format("{:.4g}", v)});
    w.bar_colour = [](double s) { return ramp(s); };
  }
}

// The legend's entries: the quality classes, the worst triangles' (pushed by
// mark_worst_triangles), the curve groups, the model points, then the categories.
void list_legend(SceneWork& w) {
  const PictureOptions& opt = w.opt;
  Scene& sc = w.sc;
  std::vector<LegendEntry>& entries = w.entries;
  if (!w.classes.empty()) {
    const double floor = opt.quality_floor;
    auto range = [&](QualityClass c) {
      const auto k = static_cast<std::size_t>(c);
      return w.class_count[k] == 0 ? std::string("none")
                                   : fmt::format("{} triangle{}, rho {:.2f} to {:.2f}", w.class_count[k],
                                                 w.class_count[k] == 1 ? "" : "s", w.class_lo[k], w.class_hi[k]);
    };
    entries.push_back({LegendEntry::Swatch, kBelowFloorColour,
                       fmt::format("below the floor {:g}: {}", floor, range(QualityClass::BelowFloor))});
    entries.push_back({LegendEntry::Swatch, kWorstPercentColour,
                       fmt::format("worst {:g}%: {}", 100 * kWorstFraction, range(QualityClass::WorstPercent))});
    entries.push_back(
        {LegendEntry::Swatch, kGoodQualityColour, fmt::format("the rest: {}", range(QualityClass::Rest))});
  }
  if (!sc.marks.empty()) entries.push_back({LegendEntry::Mark, kMarkColour, sc.legend.front()});
  sc.legend.clear();
  for (std::size_t s = 0; s < sc.curve_styles.size(); ++s)
    if (w.style_used[s]) entries.push_back({LegendEntry::Curve, sc.curve_styles[s].colour, sc.curve_styles[s].name});
  if (w.point_count > 0)
    entries.push_back({LegendEntry::Dot, kPointColour, fmt::format("{} model points", w.point_count)});
  if (w.categories && opt.draw_triangles)
    for (const auto& [value, index] : w.category_index) {
      std::string text = fmt::format("{:g}", value);
      for (const auto& [v, name] : opt.category_names)
        if (v == value) text = name;
      entries.push_back({LegendEntry::Swatch, kCategoryColours[index % kCategoryColours.size()], text});
    }
  for (const LegendEntry& e : entries) sc.legend.push_back(e.text);
}

// The colour bar at the left of the strip below the map, its title above it; returns the
// bar's right end and bottom.
std::pair<double, double> lay_out_colour_bar(SceneWork& w, double pad, double top) {
  Scene& sc = w.sc;
  const double font = w.font;
  const double bar_w = std::min(0.45 * sc.width - pad, 22 * font), bar_h = font;
  const double bar_y = top + 1.5 * font;
  sc.texts.push_back({{pad, top + font}, sc.bar_title, font, Scene::Anchor::Start, kTextColour, false});
  constexpr int kCells = 64;
  for (int i = 0; i < kCells; ++i)
    sc.boxes.push_back({{pad + bar_w * i / kCells, bar_y}, {pad + bar_w * (i + 1) / kCells, bar_y + bar_h},
                        w.bar_colour((i + 0.5) / kCells)});
  for (const auto& [pos, label] : w.ticks) {
    const double x = pad + bar_w * pos;
    sc.lines.push_back({{{x, bar_y + bar_h}, {x, bar_y + bar_h + 0.3 * font}}, kTextColour, 1});
    sc.texts.push_back(
        {{x, bar_y + bar_h + 1.3 * font}, label, 0.85 * font, Scene::Anchor::Middle, kTextColour, false});
  }
  sc.lines.push_back(
      {{{pad, bar_y}, {pad + bar_w, bar_y}, {pad + bar_w, bar_y + bar_h}, {pad, bar_y + bar_h}, {pad, bar_y}},
       kTextColour,
       1});
  return {pad + bar_w + 2 * font, bar_y + bar_h + 1.6 * font};
}

// The legend's entries in rows from (left, first_row), wrapping at the picture's right
// edge; returns the last row's baseline.
double lay_out_entries(SceneWork& w, double pad, double left, double first_row) {
  Scene& sc = w.sc;
  const double font = w.font;
  const double row_h = 1.5 * font;
  double x = left, y = first_row;   // y: the baseline of the row
  for (const LegendEntry& e : w.entries) {
    const double ew = 2.2 * font + text_width(e.text, font) + 1.5 * font;
    if (x > left && x + ew > sc.width - pad) x = left, y += row_h;
    const Vec2 c{x + 0.8 * font, y - 0.35 * font};
    switch (e.kind) {
      case LegendEntry::Curve:
        sc.lines.push_back({{{x, c.y}, {x + 1.6 * font, c.y}}, e.colour, std::max(2.0, 2 * w.curve_width)});
        break;
      case LegendEntry::Mark: sc.circles.push_back({c, 0.5 * font, e.colour, std::max(1.0, font / 8)}); break;
      case LegendEntry::Dot: sc.circles.push_back({c, 0.3 * font, e.colour, 0}); break;
      case LegendEntry::Swatch:
        sc.boxes.push_back({{x + 0.2 * font, c.y - 0.5 * font}, {x + 1.4 * font, c.y + 0.5 * font}, e.colour});
        // Outlined: the good-quality swatch is nearly the background's colour.
        sc.lines.push_back({{{x + 0.2 * font, c.y - 0.5 * font}, {x + 1.4 * font, c.y - 0.5 * font},
                             {x + 1.4 * font, c.y + 0.5 * font}, {x + 0.2 * font, c.y + 0.5 * font},
                             {x + 0.2 * font, c.y - 0.5 * font}},
                            kTextColour, 0.5});
        break;
    }
    sc.texts.push_back({{x + 2.0 * font, y}, e.text, font, Scene::Anchor::Start, kTextColour, false});
    x += ew;
  }
  return y;
}

// The strip below the map: the colour bar on the left, the entries flowing to its right;
// the picture grows to hold it.
void lay_out_strip(SceneWork& w) {
  Scene& sc = w.sc;
  if (!w.opt.decorations || (!w.bar_colour && w.entries.empty())) return;
  const double font = w.font;
  const double pad = 0.6 * font, top = sc.height + pad;
  double left = pad, bottom = top;
  double first_row = top + font;   // the baseline of the entries' first row
  if (!w.bar_colour && !sc.bar_title.empty()) {
    // A title without a bar (quality): the entries are its key, in rows below it.
    sc.texts.push_back({{pad, top + font}, sc.bar_title, font, Scene::Anchor::Start, kTextColour, false});
    first_row = top + 2.6 * font;
    bottom = top + 1.4 * font;
  }
  if (w.bar_colour) std::tie(left, bottom) = lay_out_colour_bar(w, pad, top);
  const double y = lay_out_entries(w, pad, left, first_row);
  if (!w.entries.empty()) bottom = std::max(bottom, y + 0.6 * font);
  sc.height = std::min(kMaxPicturePx, bottom + pad);
}

}  // namespace

Scene build_scene(const MeshModel& m, const PictureOptions& opt) {
  SceneWork w(m, opt);
  frame_scene(w);
  collect_triangles(w);
  measure_colour_ranges(w);
  fill_triangles(w);
  draw_curves(w);
  draw_points(w);
  mark_worst_triangles(w);
  draw_graticule(w);
  scale_colour_bar(w);
  list_legend(w);
  lay_out_strip(w);
  return std::move(w.sc);
}

}  // namespace sm::io
