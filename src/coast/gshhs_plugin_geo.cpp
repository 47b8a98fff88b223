// Plugin(GSHHS) compatibility: option mapping and the .geo writer.
#include "coast/gshhs_plugin_geo.h"

#include <fmt/format.h>

#include "base/output_file.h"
#include "coast/read_gshhs.h"
#include "coast/read_loops2.h"

namespace sm::coast {

std::string write_gshhs_plugin_geo(const CoastModel& m, const GshhsPluginOptions& opt,
                                   std::span<const CoastCurve> cut) {
  std::string out;
  auto w = [&out](const std::string& s) { out += s; };
  w("IP = newp;  IL = newl;  ILL = newll;  IS = news;  IFI = newf;\n");
  if (opt.write_polar_sphere > 0) {
    w(fmt::format("Point ( IP + 0 ) = {{0, 0, 0 }};  Point ( IP + 1 ) = {{0, 0,{:.16g}}};\n", opt.radius));
    w("PolarSphere ( IS + 0 ) = {IP , IP+1};\n");
  }
  const geo::StereoPlane plane(opt.radius);
  std::size_t ip = opt.write_polar_sphere > 0 ? 2 : 0;
  const std::size_t first_coast_point = ip;
  std::vector<std::size_t> curve_tag(m.curves.size());
  std::vector<std::size_t> open_curves;
  std::size_t il = 0;
  // Loops in model order (surface by surface); each loop's curves share end points.
  for (std::size_t l = 0; l < m.loops.size(); ++l) {
    const CoastLoop& loop = m.loops[l];
    // A periodic curve writes all its points and closes on its first. In a loop of
    // pieces, each piece writes all but its last point, which is the next piece's first;
    // all points of the loop are written before its curves refer to them.
    const std::size_t loop_first_point = ip;
    std::vector<std::size_t> start(loop.curves.size());
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const CoastCurve& c = m.curves[loop.curves[k]];
      start[k] = ip;
      const std::size_t n = c.periodic ? c.uv.size() : c.uv.size() - 1;
      for (std::size_t i = 0; i < n; ++i) {
        Vec2 p = c.uv[i];
        if (opt.write_polar_sphere == -2) p = plane.from_polar(p);
        w(fmt::format("Point ( IP + {} ) = {{{:.16g}, {:.16g}, 0 }};\n", ip++, p.x, p.y));
      }
    }
    for (std::size_t k = 0; k < loop.curves.size(); ++k) {
      const CoastCurve& c = m.curves[loop.curves[k]];
      const std::size_t tag = il++;
      curve_tag[loop.curves[k]] = tag;
      if (c.open_boundary) open_curves.push_back(tag);
      const std::size_t first = start[k];
      const std::size_t last = k + 1 < loop.curves.size() ? start[k + 1] - 1 : ip - 1;
      if (c.periodic) {
        w(fmt::format("LoopStart{} = IP + {};  LoopEnd{} = IP + {};\n", tag, first, tag, last));
        w(fmt::format("BSpline ( IL + {} ) = {{ IP + {} : IP + {}, IP + {} }};\n", tag, first, last, first));
        continue;
      }
      const std::size_t end = k + 1 < loop.curves.size() ? start[k + 1] : loop_first_point;
      if (c.uv.size() == 2)   // two points: a segment in (u,v)
        w(fmt::format("Line ( IL + {} ) = {{ IP + {}, IP + {} }};\n", tag, first, end));
      else if (end == last + 1)
        w(fmt::format("BSpline ( IL + {} ) = {{ IP + {} : IP + {} }};\n", tag, first, end));
      else
        w(fmt::format("BSpline ( IL + {} ) = {{ IP + {} : IP + {}, IP + {} }};\n", tag, first, last, end));
    }
    std::string ids;
    for (std::size_t k = 0; k < loop.curves.size(); ++k)
      ids += fmt::format("{}IL + {}", k ? ", " : "", curve_tag[loop.curves[k]]);
    w(fmt::format("Line Loop ( ILL + {} ) = {{ {} }};\n", l, ids));
  }
  // Cut coastlines (negative field values): curves without a loop.
  for (const CoastCurve& c : cut) {
    const std::size_t first = ip;
    for (Vec2 p : c.uv) {
      if (opt.write_polar_sphere == -2) p = plane.from_polar(p);
      w(fmt::format("Point ( IP + {} ) = {{{:.16g}, {:.16g}, 0 }};\n", ip++, p.x, p.y));
    }
    const std::size_t tag = il++;
    if (c.uv.size() == 2)
      w(fmt::format("Line ( IL + {} ) = {{ IP + {}, IP + {} }};\n", tag, first, ip - 1));
    else
      w(fmt::format("BSpline ( IL + {} ) = {{ IP + {} : IP + {} }};\n", tag, first, ip - 1));
  }
  // The Plane Surfaces Gmsh 2.6 meant to write (its buffer was cleared before writing).
  for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
    std::string ids = fmt::format("ILL + {}", m.surfaces[s].outer);
    for (std::uint32_t h : m.surfaces[s].holes) ids += fmt::format(", ILL + {}", h);
    w(fmt::format("Plane Surface ( IS + {} ) = {{ {} }};\n", s, ids));
  }
  if (!open_curves.empty()) {
    std::string ids;
    for (std::size_t k = 0; k < open_curves.size(); ++k) ids += fmt::format("{}IL + {}", k ? ", " : "", open_curves[k]);
    w(fmt::format("Physical Curve ( \"open\" ) = {{ {} }};\n", ids));
  }
  if (ip > first_coast_point) {
    w("Field [ IFI + 0]  = Distance;\n");
    w(fmt::format("Field [ IFI + 0].PointsList  = {{ IP + {} : IP + {} }};\n", first_coast_point, ip - 1));
  }
  return out;
}

Result<GshhsPluginResult> run_gshhs_plugin(const GshhsPluginOptions& opt) {
  if (!(opt.radius > 0)) return CoastError{opt.in_file_name, -1, "Plugin(GSHHS): radius must be positive", {}};
  if (opt.write_polar_sphere != 1 && opt.write_polar_sphere != 0 && opt.write_polar_sphere != -2)
    return CoastError{opt.in_file_name,
                      -1,
                      fmt::format("Plugin(GSHHS): WritePolarSphere must be 1, 0 or -2, not {}", opt.write_polar_sphere),
                      {}};
  Result<Coastline> data = CoastError{};
  if (opt.format == "gshhs") {
    data = read_gshhs(opt.in_file_name);
  } else if (opt.format == "loops2") {
    const auto coord = parse_loops2_coordinate(opt.coordinate);
    if (!coord)
      return CoastError{
          opt.in_file_name, -1, fmt::format("Plugin(GSHHS): unknown Coordinate '{}'", opt.coordinate), {}};
    Loops2Options lo;
    lo.coordinate = *coord;
    lo.utm_zone = opt.utm_zone;
    lo.utm_equatorial_radius = opt.utm_equatorial_radius;
    lo.utm_polar_radius = opt.utm_polar_radius;
    data = read_loops2(opt.in_file_name, lo);
  } else {
    return CoastError{
        opt.in_file_name, -1, fmt::format("Plugin(GSHHS): unknown Format '{}' (gshhs or loops2)", opt.format), {}};
  }
  if (!data) return data.error();
  if (opt.format == "loops2")
    for (Ring& r : data->rings) r.level = 1;   // loops2 has no levels: every loop is a coastline
  // The plugin's field semantics: 0 (or no field) keeps every point, < 0 cuts the loop.
  constexpr double kKeepAll = 1e-3;   // metres
  const AccuracyFn field = opt.field;
  const AccuracyFn positive = [field](std::span<const Vec3> pts, std::span<double> g) {
    if (field)
      field(pts, g);
    else
      for (double& x : g) x = kKeepAll;
    for (double& x : g)
      if (x == 0) x = kKeepAll;
  };
  ImportOptions io;
  io.radius = opt.radius;
  io.gamma = positive;
  io.repair.strait_factor = opt.min_straits_factor > 0 ? opt.min_straits_factor : 1.0;
  io.repair.close_straits = opt.min_straits_factor > 0;
  GshhsPluginResult res;
  {
    // Levels first (as the import would), then loops with negative values are cut.
    std::vector<Ring> rings;
    for (Ring& r : data->rings)
      if (r.level == 1 || r.level == io.antarctica_level) rings.push_back(std::move(r));
    data->rings = std::move(rings);
    clean(*data);
    std::vector<Ring> whole, pieces;
    std::vector<Vec3> xyz;
    std::vector<double> g;
    for (Ring& r : data->rings) {
      xyz.resize(r.pts.size());
      g.assign(r.pts.size(), 0.0);
      for (std::size_t i = 0; i < r.pts.size(); ++i) xyz[i] = geo::sphere_from_lonlat(r.pts[i], opt.radius);
      positive(xyz, g);
      std::size_t neg = r.pts.size();
      for (std::size_t i = 0; i < r.pts.size() && neg == r.pts.size(); ++i)
        if (g[i] < 0) neg = i;
      if (neg == r.pts.size()) {
        whole.push_back(std::move(r));
        continue;
      }
      // Runs of non-negative points, starting after a negative one (the ring is cyclic).
      const std::size_t n = r.pts.size();
      Ring piece;
      for (std::size_t s = 1; s <= n; ++s) {
        const std::size_t i = (neg + s) % n;
        if (g[i] >= 0) {
          piece.pts.push_back(r.pts[i]);
          continue;
        }
        if (piece.pts.size() >= 2) {
          piece.closed = false;
          piece.record = r.record;
          piece.id = r.id;
          pieces.push_back(std::move(piece));
        }
        piece = Ring{};
      }
    }
    data->rings = std::move(whole);
    CoarsenOptions co;
    co.gamma = positive;
    co.radius = opt.radius;
    auto cut = coarsen(std::move(pieces), co);
    if (!cut) return cut.error();
    const geo::PolarSphere ps({0, 0, 0}, 1.0);
    for (const CoarseRing& cr : cut->rings) {
      CoastCurve c;
      c.record = cr.ring.record;
      c.id = cr.ring.id;
      for (auto k : cr.keep) {
        c.ll.push_back(cr.ring.pts[k]);
        c.uv.push_back(ps.param_from_lonlat(cr.ring.pts[k]));
      }
      res.cut.push_back(std::move(c));
    }
  }
  io.levels = {1};
  auto model = build_coast_model(std::move(*data), io);
  if (!model) return model.error();
  res.geo = write_gshhs_plugin_geo(*model, opt, res.cut);
  res.model = std::move(*model);
  base::OutputFile out;
  if (!out.open(opt.out_file_name) || !out.write(res.geo) || !out.commit())
    return CoastError{opt.out_file_name, -1, "Plugin(GSHHS): cannot write the output file: " + out.error(), {}};
  return res;
}

}  // namespace sm::coast
