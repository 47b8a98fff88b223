// Coastline statements (native extension, paper section 2.2): `Coastline[n] = GSHHS;`,
// `Coastline[n].Option = value;`, `Delete Coastline[n];` and the import `Coastline{n}`, which
// runs coast::build_coast_model and turns its loops into points, curves and curve loops.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <fmt/format.h>

#include "base/check.h"
#include "coast/import.h"
#include "coast/read.h"
#include "coast/read_shapefile.h"
#include "coast/region_polygon.h"
#include "field/registry.h"
#include "interp/kernel/coastline_report.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/field_eval.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/interpreter.h"
#include "interp/progress_sink.h"
#include "interp/provenance.h"

namespace sm::interp {

/// What one import created, in the order `Coastline{n}` returns it.
struct CoastlineImport {
  std::vector<int> loops;            // surface by surface, outer loop first; then unassigned holes
  std::vector<int> loop_points;      // control points of each loop
  std::vector<int> outer;            // the outer loop of each surface
  std::vector<int> loops_per_surface;   // outer + holes of each surface, as in `loops`
  std::vector<int> curves, open_curves, points;
  std::vector<int> coast_points;     // points of the coast curves (no open-boundary point but their ends)
  std::vector<int> coast_curves;     // curves that are not open boundaries (dams included)
  /// Per open curve: the sides of the Region box it runs along (bit 0 West, 1 East,
  /// 2 South, 3 North), or the edges of the Region polygon (0-based, as given).
  std::vector<std::uint8_t> open_sides;
  std::vector<std::vector<std::size_t>> open_edges;
  std::vector<std::vector<int>> surface_loops;   // loop tags of each sea, outer first
  /// `Coastline{n, "Deviation"}`: {largest distance of a source point from the curve (m),
  /// 95% quantile (m), largest before control points were put back (m), lon, lat of the
  /// largest, control points put back}.
  std::vector<double> deviation;
  std::vector<double> closures, dropped_seas;    // {lon, lat, width_m, ...}, {lon, lat, area_km2, ...}
  std::vector<double> straits;                   // {lon, lat, width_m, step_s, ...}
  /// Plane Surfaces of the seas, made on the first `Coastline{n, "Surfaces"}` (so that
  /// scripts making their own from "LoopsPerSurface" do not get them twice).
  mutable std::vector<int> surfaces;
  mutable bool surfaces_made = false;
  lang::SourceRange at;              // the query that imported
};

using namespace sm::lang;

namespace {

enum class OptType { String, Number, List };

struct CoastOption {
  std::string_view name;
  OptType type;
  bool loops2_only;
  std::string_view help;
};

// Every option, with the value it takes; docs/interpreter.md lists the same.
constexpr CoastOption kOptions[] = {
    {"FileName", OptType::String, false, "shoreline file, relative to the script (GSHHG: optional, a binned_GSHHS_*.nc)"},
    {"Resolution", OptType::String, false, "GSHHG only: \"c\", \"l\" (default), \"i\", \"h\" or \"f\", the system's binned file"},
    {"Levels", OptType::List, false, "GSHHS levels kept (default {1})"},
    {"AntarcticaLevel", OptType::Number, false, "level kept for Antarctica: 5 ice front (default), 6 grounding line, 0 none"},
    {"AccuracyField", OptType::Number, false, "size field giving gamma(x) in metres (required)"},
    {"Region", OptType::List, false, "{west, east, south, north} in degrees, or a polygon {lon1, lat1, lon2, lat2, lon3, lat3, ...} (great-circle edges)"},
    {"RegionFile", OptType::String, false, "a shapefile holding one polygon: the Region polygon, relative to the script"},
    {"Patch", OptType::String, false, "a local shoreline file (lon/lat text, or .shp) replacing this one inside PatchBox, relative to the script"},
    {"PatchBox", OptType::List, false, "{west, east, south, north}: the box where Patch replaces the shoreline"},
    {"MinArea", OptType::Number, false, "drop closed rings below this area (km^2)"},
    {"CurveType", OptType::String, false, "\"BSpline\" (default) or \"Line\""},
    {"MaxDeviation", OptType::Number, false, "the coast curve stays within this distance (m) of the source points (default: DeviationFactor * gamma)"},
    {"DeviationFactor", OptType::Number, false, "the curve's bound as a fraction of gamma (default 0.5: within gamma / 2 but for inlets and spits too narrow for the accuracy, reported; 0: measured and reported only)"},
    {"MinStraitsFactor", OptType::Number, false, "straits narrower than factor * gamma are reported (default 1)"},
    {"CloseStraits", OptType::Number, false, "1: merge islands across such straits (default 0: keep them open)"},
    {"CheckSplines", OptType::Number, false, "1 (default): put points back until no two B-splines cross; 0: off"},
    {"MinChannelWidth", OptType::Number, false, "close passages of water narrower than this (m) by dams (default 0: off)"},
    {"KeepPassages", OptType::Number, false, "1: MinChannelWidth fills only water that ends (inlets, lagoons); passages and straits stay open (default 0)"},
    {"Dams", OptType::List, false, "{lon1, lat1, lon2, lat2, ...}: dams closing the water each segment crosses"},
    {"SeaAt", OptType::List, false, "{lon, lat, ...}: keep only the seas holding these points"},
    {"KeepOpen", OptType::List, false, "{lon, lat, ...}: the passage at each point stays open whatever MinChannelWidth"},
    {"Coordinate", OptType::String, true, "lonlat, lonlat_degrees (default), utm or cartesian"},
    {"UTMZone", OptType::Number, true, "UTM zone of utm coordinates"},
    {"UTMEquatorialRadius", OptType::Number, true, "ellipsoid of utm coordinates (m)"},
    {"UTMPolarRadius", OptType::Number, true, "ellipsoid of utm coordinates (m)"},
};

// What `Coastline{n, "What"}` returns.
constexpr std::string_view kSelectors[] = {"Loops", "Curves", "OpenCurves", "Points", "CoastPoints", "ControlPoints",
                                           "Outer", "LoopsPerSurface", "CoastCurves", "Surfaces",
                                           "Closures", "DroppedSeas", "Straits", "Deviation"};
// The sides `Coastline{n, "OpenCurves", "West"}` takes, in the bit order of open_sides.
constexpr std::string_view kSides[] = {"West", "East", "South", "North"};

// A Region list of 6 or more numbers: the polygon's lon/lat vertices.
std::vector<geo::LonLat> polygon_vertices(const std::vector<double>& x) {
  std::vector<geo::LonLat> v;
  for (std::size_t i = 0; i + 1 < x.size(); i += 2) v.push_back({x[i], x[i + 1]});
  return v;
}

const CoastOption* find_option(std::string_view name) {
  for (const CoastOption& o : kOptions)
    if (o.name == name) return &o;
  return nullptr;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& names) {
  const std::string best = field::closest_name(name, names);
  return best.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", best);
}

int coast_id(Interpreter& in, ExprId e) {
  const double v = in.eval_number(e);
  if (!std::isfinite(v) || std::abs(v) > 2147483647.0)
    in.fail_fmt(in.ast().expr(e).range, Diag::WrongType, fmt::format("a coastline id must be an integer, not {}", v));
  return static_cast<int>(v);
}

CoastlineDef& require_coast(Interpreter& in, int id, SourceRange at, std::string_view doing) {
  auto& defs = in.kernel().coastlines;
  auto it = defs.find(id);
  if (it != defs.end()) return it->second;
  std::vector<int> ids;
  for (const auto& [k, d] : defs) ids.push_back(k);
  in.fail_fmt(at, Diag::MissingCoastline,
              fmt::format("cannot {} Coastline[{}]: it is not defined{}", doing, id,
                          ids.empty() ? std::string(" (no coastline is; write 'Coastline[n] = GSHHS;' first)")
                                      : fmt::format(" (defined: {})", fmt::join(ids, ", "))));
}

void exec_coast_new(Interpreter& in, const Stmt& s, const CoastlineNewStmt& n) {
  const int id = coast_id(in, n.id);
  const std::string format(in.ast().str(n.format));
  const auto parsed = coast::parse_coast_format(format);
  if (!parsed) {
    in.fail_fmt(n.format_range, Diag::UnknownCoastlineFormat, format,
                did_you_mean(format, {"GSHHS", "GSHHG", "Shapefile", "LonLatText", "Loops2"}));
  }
  auto& defs = in.kernel().coastlines;
  if (auto it = defs.find(id); it != defs.end()) {
    try {
      in.fail_fmt(in.ast().expr(n.id).range, Diag::DuplicateCoastline, id);
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{it->second.defined_at, "first defined here"});
      throw;
    }
  }
  CoastlineDef d;
  d.format = coast::coast_format_name(*parsed);
  d.defined_at = s.range;
  defs.emplace(id, std::move(d));
}

[[noreturn]] void fail_option(Interpreter& in, SourceRange at, int id, std::string_view option, const std::string& why) {
  in.fail_fmt(at, Diag::WrongCoastlineOption, fmt::format("Coastline[{}].{} {}", id, option, why));
}

// Checks a value against its option now, so that a mistake is reported where it is written.
void check_option_value(Interpreter& in, int id, const CoastOption& o, const Value& v, SourceRange at) {
  if (o.type == OptType::String) {
    if (!v.is_string() || v.strs().size() != 1) fail_option(in, at, id, o.name, "takes one string");
    const std::string& t = v.strs().front();
    if (o.name == "CurveType" && t != "BSpline" && t != "Line")
      fail_option(in, at, id, o.name, fmt::format("must be \"BSpline\" or \"Line\", not \"{}\"", t));
    if (o.name == "Coordinate" && !coast::parse_loops2_coordinate(t))
      fail_option(in, at, id, o.name,
                  fmt::format("must be lonlat, lonlat_degrees, utm or cartesian, not \"{}\"", t));
    if (o.name == "FileName" && t.empty()) fail_option(in, at, id, o.name, "is empty");
    if (o.name == "Resolution" && !coast::is_gshhg_resolution(t))
      fail_option(in, at, id, o.name,
                  fmt::format("must be \"c\", \"l\", \"i\", \"h\" or \"f\" (crude to full), not \"{}\"", t));
    return;
  }
  if (!v.is_numeric()) fail_option(in, at, id, o.name, o.type == OptType::List ? "takes a list of numbers" : "takes a number");
  const std::vector<double>& x = v.nums();
  for (double d : x)
    if (!std::isfinite(d)) fail_option(in, at, id, o.name, "is not finite");
  if (o.type == OptType::Number && x.size() != 1)
    fail_option(in, at, id, o.name, fmt::format("takes one number, not a list of {}", x.size()));
  const std::string_view name = o.name;
  if (name == "Levels") {
    if (x.empty()) fail_option(in, at, id, name, "is empty: no shoreline would be kept");
    for (double d : x)
      if (d != std::floor(d) || d < 1 || d > 6) fail_option(in, at, id, name, fmt::format("must list levels 1 to 6, not {}", d));
  } else if (name == "AntarcticaLevel") {
    if (x[0] != 0 && x[0] != 5 && x[0] != 6) fail_option(in, at, id, name, fmt::format("must be 0, 5 or 6, not {}", x[0]));
  } else if (name == "AccuracyField" || name == "UTMZone") {
    if (x[0] != std::floor(x[0]) || x[0] < (name == "UTMZone" ? 1 : 0) || x[0] > (name == "UTMZone" ? 60 : 2147483647.0))
      fail_option(in, at, id, name, fmt::format("must be {}, not {}", name == "UTMZone" ? "a zone 1 to 60" : "a field id", x[0]));
  } else if (name == "Region") {
    if (x.size() != 4) {   // a polygon
      if (x.size() < 6 || x.size() % 2 != 0)
        fail_option(in, at, id, name,
                    fmt::format("takes a box {{west, east, south, north}} or a polygon of 3 or more lon/lat vertices "
                                "{{lon1, lat1, lon2, lat2, lon3, lat3, ...}}, not {} numbers",
                                x.size()));
      auto poly = coast::RegionPolygon::make(polygon_vertices(x));
      if (!poly) fail_option(in, at, id, name, fmt::format("is not a usable polygon: {}", poly.error().message));
      return;
    }
    if (!(x[0] < x[1]) || x[1] - x[0] > 360)
      fail_option(in, at, id, name, fmt::format("needs west < east <= west + 360 (got {} and {})", x[0], x[1]));
    if (!(x[2] < x[3]) || x[2] < -90 || x[3] > 90)
      fail_option(in, at, id, name, fmt::format("needs -90 <= south < north <= 90 (got {} and {})", x[2], x[3]));
  } else if (name == "PatchBox") {
    if (x.size() != 4) fail_option(in, at, id, name, fmt::format("takes a box {{west, east, south, north}}, not {} numbers", x.size()));
    if (!(x[0] < x[1]) || x[1] - x[0] >= 360)
      fail_option(in, at, id, name, fmt::format("needs west < east < west + 360 (got {} and {})", x[0], x[1]));
    if (!(x[2] < x[3]) || x[2] < -90 || x[3] > 90)
      fail_option(in, at, id, name, fmt::format("needs -90 <= south < north <= 90 (got {} and {})", x[2], x[3]));
  } else if (name == "MinArea") {
    if (x[0] < 0) fail_option(in, at, id, name, "must not be negative");
  } else if (name == "MinStraitsFactor" || name == "UTMEquatorialRadius" || name == "UTMPolarRadius") {
    if (!(x[0] > 0)) fail_option(in, at, id, name, "must be positive");
  } else if (name == "MaxDeviation") {
    if (!(x[0] > 0)) fail_option(in, at, id, name, fmt::format("must be a positive distance in metres, not {}", x[0]));
  } else if (name == "DeviationFactor") {
    if (x[0] < 0) fail_option(in, at, id, name, fmt::format("must not be negative (0 is off), not {}", x[0]));
  } else if (name == "MinChannelWidth") {
    if (x[0] < 0) fail_option(in, at, id, name, fmt::format("must not be negative (0 is off), not {}", x[0]));
  } else if (name == "Dams" || name == "SeaAt" || name == "KeepOpen") {
    const std::size_t per = name == "Dams" ? 4 : 2;
    if (x.empty() || x.size() % per != 0)
      fail_option(in, at, id, name,
                  fmt::format("takes {} per {}, not {} number(s)", per == 4 ? "{lon1, lat1, lon2, lat2}" : "{lon, lat}",
                              per == 4 ? "dam" : "point", x.size()));
    for (std::size_t i = 1; i < x.size(); i += 2)
      if (x[i] < -90 || x[i] > 90)
        fail_option(in, at, id, name, fmt::format("has latitude {} (value {}): latitudes lie in [-90, 90]", x[i], i + 1));
  } else if (name == "CloseStraits" || name == "CheckSplines") {
    if (x[0] != 0 && x[0] != 1) fail_option(in, at, id, name, fmt::format("must be 0 or 1, not {}", x[0]));
  }
}

const Value* option_of(const CoastlineDef& d, std::string_view name) {
  auto it = d.options.find(std::string(name));
  return it == d.options.end() ? nullptr : &it->second;
}

// RegionFile: the one polygon (one outer ring, no hole) of a shapefile, as a Region list.
Value region_from_file(Interpreter& in, int id, const std::string& path, SourceRange at) {
  auto c = coast::read_shapefile(path);
  if (!c) fail_option(in, at, id, "RegionFile", fmt::format("cannot be read: {}", c.error().to_string()));
  std::vector<const coast::Ring*> outer;
  std::size_t holes = 0;
  for (const coast::Ring& r : c->rings) {
    if (r.closed && r.level == 1) outer.push_back(&r);
    else ++holes;
  }
  if (outer.size() != 1 || holes > 0)
    fail_option(in, at, id, "RegionFile",
                fmt::format("{}: a region file must hold one polygon without holes, and it holds {} outer ring(s) and "
                            "{} other part(s)",
                            path, outer.size(), holes));
  std::vector<double> x;
  for (const geo::LonLat p : outer.front()->pts) x.insert(x.end(), {p.lon, p.lat});
  auto poly = coast::RegionPolygon::make(polygon_vertices(x));
  if (!poly) fail_option(in, at, id, "RegionFile", fmt::format("{}: not a usable polygon: {}", path, poly.error().message));
  return Value::list(std::move(x));
}

void exec_coast_option(Interpreter& in, const Stmt& s, const CoastlineOptionStmt& n) {
  const int id = coast_id(in, n.id);
  CoastlineDef& d = require_coast(in, id, in.ast().expr(n.id).range, "set an option of");
  const std::string option(in.ast().str(n.option));
  const CoastOption* o = find_option(option);
  if (!o) {
    std::vector<std::string> names;
    for (const CoastOption& c : kOptions) names.emplace_back(c.name);
    in.fail_fmt(n.option_range, Diag::UnknownCoastlineOption,
                fmt::format("Coastline[{}] ({}) has no option '{}'{}", id, d.format, option, did_you_mean(option, names)));
  }
  if (o->loops2_only && d.format != "Loops2")
    in.fail_fmt(n.option_range, Diag::UnknownCoastlineOption,
                fmt::format("option '{}' applies to Loops2 coastlines only, and Coastline[{}] is {}", option, id, d.format));
  if (o->name == "Resolution" && d.format != "GSHHG")
    in.fail_fmt(n.option_range, Diag::UnknownCoastlineOption,
                fmt::format("option 'Resolution' applies to GSHHG coastlines only, and Coastline[{}] is {}", id, d.format));
  if (d.imported) {
    try {
      in.fail_fmt(s.range, Diag::WrongCoastlineOption,
                  fmt::format("Coastline[{}] was already imported: its options can no longer change", id));
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{d.imported->at, "imported here"});
      throw;
    }
  }
  Value v = in.eval(n.value);
  const SourceRange value_at = in.ast().expr(n.value).range;
  check_option_value(in, id, *o, v, value_at);
  if (o->name == "FileName" || o->name == "Patch") v = Value::string(resolve_script_path(in.builtin_env(), v.strs().front()));
  if ((o->name == "Region" && option_of(d, "RegionFile")) || (o->name == "RegionFile" && option_of(d, "Region") &&
                                                              !option_of(d, "RegionFile")))
    fail_option(in, s.range, id, o->name,
                "cannot be set with both Region and RegionFile: the region is either written or read from a file");
  if (o->name == "RegionFile") {
    // Read now, so that a file without one usable polygon is an error here; the polygon
    // then stands as the Region, set by this statement.
    v = Value::string(resolve_script_path(in.builtin_env(), v.strs().front()));
    d.options.insert_or_assign("Region", region_from_file(in, id, v.strs().front(), s.range));
    d.option_at.insert_or_assign("Region", s.range);
  }
  d.options.insert_or_assign(option, std::move(v));
  d.option_at.insert_or_assign(option, s.range);
}

void exec_delete_coast(Interpreter& in, const DeleteCoastlineStmt& n) {
  const int id = coast_id(in, n.id);
  require_coast(in, id, in.ast().expr(n.id).range, "delete");
  in.kernel().coastlines.erase(id);   // the entities an import created stay in the model
}

const Value* option(const CoastlineDef& d, std::string_view name) {
  auto it = d.options.find(name);
  return it == d.options.end() ? nullptr : &it->second;
}

double number_option(const CoastlineDef& d, std::string_view name, double fallback) {
  const Value* v = option(d, name);
  return v ? v->nums().front() : fallback;
}

// A kernel error at `at`, with notes at the definition and, for file errors, at FileName.
[[noreturn]] void fail_coast(Interpreter& in, int id, const CoastlineDef& d, SourceRange at, const coast::CoastError& e,
                             bool file_error) {
  std::vector<DiagNote> notes;
  if (file_error) {
    // Records of the file, or a bad gamma(x) value at a place of it.
    for (std::string_view o : {"FileName", "AccuracyField"}) {
      auto it = d.option_at.find(o);
      if (it != d.option_at.end()) notes.push_back({it->second, fmt::format("Coastline[{}].{} is set here", id, o)});
    }
  }
  notes.push_back({d.defined_at, fmt::format("Coastline[{}] ({}) is defined here", id, d.format)});
  in.fail_with_notes(at, Diag::CoastlineError, fmt::format("Coastline[{}]: {}", id, e.to_string()), std::move(notes));
}

void check_geo(Interpreter& in, SourceRange at, const geo::GeoStatus& st) {
  if (!st) fail_geo(in, at, st.error());
}

// The sides of box b that an open-boundary curve runs along: a side counts when two
// consecutive points of the curve lie on it.
std::uint8_t box_sides(const std::vector<geo::LonLat>& ll, const coast::LonLatBox& b) {
  constexpr double kOn = 1e-7;   // degrees: region.cpp puts the pieces' points on the box exactly
  auto lon_at = [&](double lon, double edge) {
    return std::abs(std::fmod(std::fmod(lon - edge, 360.0) + 540.0, 360.0) - 180.0) < kOn;
  };
  std::uint8_t sides = 0;
  for (std::size_t i = 0; i + 1 < ll.size(); ++i) {
    const geo::LonLat p = ll[i], q = ll[i + 1];
    if (b.east - b.west < 360) {
      if (lon_at(p.lon, b.west) && lon_at(q.lon, b.west)) sides |= 1;
      if (lon_at(p.lon, b.east) && lon_at(q.lon, b.east)) sides |= 2;
    }
    if (std::abs(p.lat - b.south) < kOn && std::abs(q.lat - b.south) < kOn) sides |= 4;
    if (std::abs(p.lat - b.north) < kOn && std::abs(q.lat - b.north) < kOn) sides |= 8;
  }
  return sides;
}

// Runs the import of Coastline[id] and adds its entities to the model.
std::shared_ptr<const CoastlineImport> import_coastline(Interpreter& in, int id, CoastlineDef& d, SourceRange at) {
  KernelState& k = in.kernel();
  geo::Model& model = k.model;
  const int g = model.current_geometry();
  const geo::SurfaceGeometry* sg = g ? model.geometry(g) : nullptr;
  if (!sg || !sg->polar()) {
    in.fail_with_notes(
        at, Diag::CoastlineError,
        fmt::format("Coastline{{{}}} puts its points on the current PolarSphere, and {}: define one first with "
                    "'PolarSphere(s) = {{centre, pole}};' (its radius gives the metres of the accuracy field)",
                    id, !sg ? "there is none" : fmt::format("the current geometry {} is a lon/lat Sphere", g)),
        {{d.defined_at, fmt::format("Coastline[{}] is defined here", id)}});
  }
  const geo::PolarSphere& sphere = *sg->polar();
  const Value* file = option(d, "FileName");
  const bool gshhg = d.format == "GSHHG";
  if (!file && !gshhg)
    in.fail_with_notes(at, Diag::WrongCoastlineOption,
                       fmt::format("Coastline[{}] has no FileName: set 'Coastline[{}].FileName = \"...\";'", id, id),
                       {{d.defined_at, fmt::format("Coastline[{}] is defined here", id)}});
  const Value* accuracy = option(d, "AccuracyField");
  if (!accuracy)
    in.fail_with_notes(at, Diag::WrongCoastlineOption,
                       fmt::format("Coastline[{}] has no AccuracyField: set 'Coastline[{}].AccuracyField = n;' to a size "
                                   "field giving the accuracy gamma(x) in metres",
                                   id, id),
                       {{d.defined_at, fmt::format("Coastline[{}] is defined here", id)}});

  // The accuracy field: built now (errors located at this use), evaluated at points of
  // the kernel's origin-centred sphere moved to the PolarSphere's centre.
  const int field_id = static_cast<int>(accuracy->nums().front());
  auto fit = d.option_at.find("AccuracyField");
  const field::FieldPtr gamma_field = built_fields(in, field_id, fit->second).shared(field_id);
  const Vec3 centre = sphere.centre();
  std::vector<Vec3> moved;
  coast::ImportOptions io;
  io.gamma = [gamma_field, centre, &moved](std::span<const Vec3> pts, std::span<double> gamma) {
    moved.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) moved[i] = pts[i] + centre;
    gamma_field->eval(moved, gamma);
  };
  io.radius = sphere.radius();
  // Mesh.MinTimeStep set before the import: passages too narrow for it at the depth of
  // Mesh.DepthField are closed with the MinChannelWidth ones (coast/import.h). The depth
  // must be known now, as the closures change the coastline the script then builds on.
  if (const double min_step = in.options().number("Mesh.MinTimeStep"); min_step > 0) {
    const double depth_id = in.options().number("Mesh.DepthField");
    std::vector<DiagNote> notes;
    if (const auto it = k.option_set_at.find("Mesh.MinTimeStep"); it != k.option_set_at.end())
      notes.push_back({it->second, "Mesh.MinTimeStep was set here"});
    if (!(depth_id > 0) || !k.field_defined_at.count(static_cast<int>(depth_id)))
      in.fail_with_notes(at, Diag::InvalidOptionValue,
                         fmt::format("Coastline[{}]: Mesh.MinTimeStep = {:g} closes the passages too narrow for it "
                                     "at their depth, and {}: define the depth field and set Mesh.DepthField before "
                                     "this statement (or set Mesh.MinTimeStep after it)",
                                     id, min_step,
                                     depth_id > 0 ? fmt::format("Mesh.DepthField = {:g} names no field yet", depth_id)
                                                  : std::string("Mesh.DepthField is not set")),
                         std::move(notes));
    const int did = static_cast<int>(depth_id);
    const auto dat = k.option_set_at.find("Mesh.DepthField");
    const field::FieldPtr depth = built_fields(in, did, dat != k.option_set_at.end() ? dat->second : at).shared(did);
    const double min_depth = in.options().number("Mesh.TimeStepMinDepth");
    io.min_time_step = min_step;
    io.depth_at = [depth, sphere, min_depth](geo::LonLat ll) {
      const Vec3 x = sphere.from_lonlat(ll);
      double h = 0;
      depth->eval(std::span<const Vec3>(&x, 1), std::span<double>(&h, 1));
      return std::max(h, min_depth);
    };
  }
  if (const Value* v = option(d, "Levels")) {
    io.levels.clear();
    for (double l : v->nums()) io.levels.push_back(static_cast<int>(l));
  }
  io.antarctica_level = static_cast<int>(number_option(d, "AntarcticaLevel", io.antarctica_level));
  std::optional<coast::RegionPolygon> polygon;
  if (const Value* v = option(d, "Region")) {
    const auto& r = v->nums();
    if (r.size() == 4) {
      io.region = coast::LonLatBox{r[0], r[1], r[2], r[3]};
    } else {   // checked when set
      io.region_polygon = polygon_vertices(r);
      polygon = *coast::RegionPolygon::make(io.region_polygon);
      io.region = polygon->bounding_box();
    }
  }
  io.min_area_km2 = number_option(d, "MinArea", 0);
  io.strait_factor = number_option(d, "MinStraitsFactor", io.strait_factor);
  io.close_straits = number_option(d, "CloseStraits", 0) != 0;
  io.check_splines = number_option(d, "CheckSplines", 1) != 0;
  io.min_channel_width = number_option(d, "MinChannelWidth", 0);
  io.keep_passages = number_option(d, "KeepPassages", 0) != 0;
  io.max_deviation = number_option(d, "MaxDeviation", 0);
  io.deviation_factor = number_option(d, "DeviationFactor", io.deviation_factor);
  io.bspline_curves = !(option(d, "CurveType") && option(d, "CurveType")->strs().front() == "Line");
  if (const Value* v = option(d, "Dams")) {
    const auto& x = v->nums();
    for (std::size_t i = 0; i + 3 < x.size(); i += 4) io.dams.push_back({{x[i], x[i + 1]}, {x[i + 2], x[i + 3]}});
  }
  // Points in the water (SeaAt, KeepOpen): inside the Region, longitudes compared modulo
  // 360 as its box may run past +-180.
  for (const std::string_view name : {"SeaAt", "KeepOpen"}) {
    const Value* v = option(d, name);
    if (!v) continue;
    const auto& x = v->nums();
    for (std::size_t i = 0; i + 1 < x.size(); i += 2) {
      if (polygon && !polygon->contains({x[i], x[i + 1]}))
        in.fail_with_notes(d.option_at.find(name)->second, Diag::WrongCoastlineOption,
                           fmt::format("Coastline[{}].{} point (lon {}, lat {}) lies outside the Region polygon", id,
                                       name, x[i], x[i + 1]),
                           {{d.option_at.find("Region")->second, fmt::format("Coastline[{}].Region is set here", id)},
                            {at, "the coastline is imported here"}});
      if (io.region && !polygon) {
        const coast::LonLatBox& b = *io.region;
        const double lon = b.west + std::fmod(std::fmod(x[i] - b.west, 360.0) + 360.0, 360.0);
        if (lon > b.east || x[i + 1] < b.south || x[i + 1] > b.north)
          in.fail_with_notes(d.option_at.find(name)->second, Diag::WrongCoastlineOption,
                             fmt::format("Coastline[{}].{} point (lon {}, lat {}) lies outside the Region {{{}, {}, "
                                         "{}, {}}}",
                                         id, name, x[i], x[i + 1], b.west, b.east, b.south, b.north),
                             {{d.option_at.find("Region")->second, fmt::format("Coastline[{}].Region is set here", id)},
                              {at, "the coastline is imported here"}});
      }
      (name == "SeaAt" ? io.sea_at : io.keep_open).push_back({x[i], x[i + 1]});
    }
  }
  // Cleaning and coarsening ring by ring on -nt threads (the same rings for every count).
  io.threads = static_cast<int>(in.options().number("General.NumThreads"));
  io.progress = progress_sink(in);
  // Patch: the local shoreline, read now so that an unreadable file is an error at its
  // statement; both Patch and PatchBox, or neither.
  if (const Value* pf = option(d, "Patch"); pf || option(d, "PatchBox")) {
    const char* missing = pf ? "PatchBox" : "Patch";
    const SourceRange set_at = d.option_at.find(pf ? "Patch" : "PatchBox")->second;
    if (!option(d, "PatchBox") || !pf)
      fail_option(in, set_at, id, pf ? "Patch" : "PatchBox",
                  fmt::format("needs Coastline[{}].{} too: the patch replaces the shoreline inside a box", id, missing));
    const std::string& ppath = pf->strs().front();
    const bool shp = ppath.size() > 4 && ppath.compare(ppath.size() - 4, 4, ".shp") == 0;
    auto pdata = coast::read_coastline(shp ? coast::CoastFormat::Shapefile : coast::CoastFormat::LonLatText, ppath);
    if (!pdata) fail_option(in, set_at, id, "Patch", fmt::format("cannot be read: {}", pdata.error().to_string()));
    const auto& b = option(d, "PatchBox")->nums();
    io.patch = std::move(pdata->rings);
    io.patch_box = coast::LonLatBox{b[0], b[1], b[2], b[3]};
  }
  coast::Loops2Options l2;
  if (const Value* v = option(d, "Coordinate")) l2.coordinate = *coast::parse_loops2_coordinate(v->strs().front());
  l2.utm_zone = static_cast<int>(number_option(d, "UTMZone", l2.utm_zone));
  l2.utm_equatorial_radius = number_option(d, "UTMEquatorialRadius", l2.utm_equatorial_radius);
  l2.utm_polar_radius = number_option(d, "UTMPolarRadius", l2.utm_polar_radius);

  // The kernel's reading and building is the account's "import" stage; making the
  // script's entities from its loops below is the script's own time.
  std::optional<StageScope> import_stage(std::in_place, &in.kernel().clock, nullptr, "import");
  // GSHHG: the reader itself keeps the levels, areas and bins asked for (the import
  // filters the same again), so that a Region reads only the polygons it touches.
  coast::GshhgBinnedOptions gopt;
  gopt.levels = io.levels;
  gopt.antarctica_level = io.antarctica_level;
  gopt.min_area_km2 = io.min_area_km2;
  gopt.region = io.region;
  const Value* resolution = option(d, "Resolution");
  const std::string path = file ? file->strs().front()
                                : coast::gshhg_binned_file(resolution ? resolution->strs().front()[0] : 'l');
  auto data = coast::read_coastline(*coast::parse_coast_format(d.format), path, l2, gopt);
  if (!data) {
    // At the statement that named the file: FileName, else Resolution, else the import.
    auto f = d.option_at.find("FileName");
    if (f == d.option_at.end()) f = d.option_at.find("Resolution");
    if (f == d.option_at.end()) fail_coast(in, id, d, at, data.error(), false);
    try {
      fail_coast(in, id, d, f->second, data.error(), false);
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{at, "the coastline is imported here"});
      throw;
    }
  }
  auto built = coast::build_coast_model(std::move(*data), io);
  import_stage.reset();
  // The import's working arrays (the source points three times over, the passage pool:
  // hundreds of MB for the full-resolution world) are freed now, but many came from the
  // heap, whose free pages stay resident beside everything made after (the fields, the
  // mesh): given back to the system (the 3 km world's -2 peak, docs/benchmarks_scale.md).
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  if (!built) {
    const coast::CoastError& e = built.error();
    if (auto o = d.option_at.find(e.option); !e.option.empty() && o != d.option_at.end()) {
      try {   // a dam, a SeaAt or KeepOpen point: located where the option is set
        fail_coast(in, id, d, o->second, e, false);
      } catch (RuntimeError& err) {
        err.notes.insert(err.notes.begin(), DiagNote{at, "the coastline is imported here"});
        if (auto dams = d.option_at.find("Dams"); e.option == "KeepOpen" && dams != d.option_at.end() &&
                                                  e.message.find("dam from") != std::string::npos)
          err.notes.insert(err.notes.begin(), DiagNote{dams->second, fmt::format("Coastline[{}].Dams is set here", id)});
        throw;
      }
    }
    fail_coast(in, id, d, at, e, true);
  }
  const coast::CoastModel& m = *built;
  if (m.report.patch) {   // where the two shorelines disagree at the patch box
    const coast::PatchReport& pr = *m.report.patch;
    in.diags().report(d.option_at.find("Patch")->second, Diag::CoastlineDeviation,
                      fmt::format("Coastline[{}]: the patch replaces the shoreline inside its box ({} base and {} patch "
                                  "chain(s) cut at the box); {} stretch(es) of box edge close the gaps between the two, "
                                  "the longest {:.0f} m at lon {:.4f} lat {:.4f}",
                                  id, pr.base_chains, pr.local_chains, pr.steps, pr.max_step_m, pr.max_step_at.lon,
                                  pr.max_step_at.lat));
  }
  if (m.seas_dropped > 0)
    in.diags().report(d.option_at.find("SeaAt")->second, Diag::CoastlineSeasDropped,
                      fmt::format("Coastline[{}]: {} sea(s) holding no SeaAt point dropped, {} kept", id,
                                  m.seas_dropped, m.surfaces.size()));
  // Every change, each with its place and figure: the terminal groups the many of this
  // statement (cli/diagnostic_stream.h), --diagnostics FILE keeps every one.
  // A dropped sea goes with the count of them, at SeaAt.
  auto imp = std::make_shared<CoastlineImport>();
  for (const coast::ReportLine& line : m.report.items()) {
    const std::string name = fmt::format("Coastline[{}]", id);
    const std::string text = fmt::format("{}: {}", name, line.text);
    auto h = line.sea_dropped ? in.diags().report(d.option_at.find("SeaAt")->second, Diag::CoastlineSeasDropped, text)
             : line.step_unmet ? in.diags().report(d.option_at.find("KeepOpen")->second, Diag::CoastlinePassage, text)
             : line.kept_open ? in.diags().report(d.option_at.find("KeepOpen")->second, Diag::CoastlineKeptOpen, text)
             : line.passage   ? in.diags().report(at, Diag::CoastlinePassage, text)
                              : in.diags().report(at, Diag::CoastlineRepair, name, line.text);
    h.item(coastline_item(line));
  }
  for (const coast::RepairEntry& e : m.report.repair) {   // for Coastline{n, "Closures"} and "DroppedSeas"
    std::vector<double>* list = e.kind == coast::RepairKind::ClosedPassage ? &imp->closures
                                : e.kind == coast::RepairKind::DroppedSea  ? &imp->dropped_seas
                                                                           : nullptr;
    if (list) list->insert(list->end(), {e.where.lon, e.where.lat, e.value});
    // The straits left open, with the Courant step one element across costs (0 without
    // Mesh.MinTimeStep): what a script checks a time step's closures against.
    if (e.kind == coast::RepairKind::NarrowStrait)
      imp->straits.insert(imp->straits.end(), {e.where.lon, e.where.lat, e.value, std::isnan(e.step) ? 0.0 : e.step});
  }
  if (m.region_empty) {   // the box of the Region, or of the file's own -R
    auto r = d.option_at.find("Region");
    const std::string box =
        polygon ? std::string(" polygon")
        : io.region ? fmt::format(" {{{}, {}, {}, {}}}", io.region->west, io.region->east, io.region->south, io.region->north)
                  : std::string(" of the file");
    in.diags().report(r != d.option_at.end() ? r->second : at, Diag::CoastlineRegionEmpty,
                      fmt::format("Coastline[{}]: the Region{} holds no shoreline of the levels kept (none left at "
                                  "this accuracy and MinArea): its {} is the only loop, all open boundary",
                                  id, box, polygon ? "outline" : "box"));
  }

  // Loops surface by surface (outer first), then the holes no outer loop holds.
  std::vector<std::uint32_t> order;
  std::vector<bool> listed(m.loops.size(), false);
  auto add = [&](std::uint32_t l) {
    if (l < m.loops.size() && !listed[l]) order.push_back(l), listed[l] = true;
  };
  for (const coast::CoastSurface& s : m.surfaces) {
    add(s.outer);
    for (std::uint32_t h : s.holes) add(h);
  }
  for (std::uint32_t l : m.unassigned) add(l);
  for (std::uint32_t l = 0; l < m.loops.size(); ++l) add(l);

  sync_geometry_options(in);
  const bool polyline = option(d, "CurveType") && option(d, "CurveType")->strs().front() == "Line";
  imp->at = at;
  {
    const coast::DeviationReport& dev = m.report.deviation;
    imp->deviation = {dev.max, dev.p95, dev.max_before, dev.where.lon, dev.where.lat,
                      static_cast<double>(dev.points_added)};
    // One line per import: how far the coast the mesher follows lies from the data.
    // At the coastline's definition: the import statement's own caret heads the group of
    // its repairs (cli/diagnostic_stream.h).
    in.diags().report(d.defined_at, Diag::CoastlineDeviation,
                      fmt::format("Coastline[{}]: the coast curves lie within {:.0f} m of the source points (95% within "
                                  "{:.0f} m; {:.0f} m before {} control point(s) were put back), farthest at lon {:.4f} "
                                  "lat {:.4f}{}{}",
                                  id, dev.max, dev.p95, dev.max_before, dev.points_added, dev.where.lon, dev.where.lat,
                                  dev.narrow_features > 0
                                      ? fmt::format("; {} inlet(s) or spit(s) too narrow for the accuracy left out (up to "
                                                    "{:.0f} m deep; the first at lon {:.4f} lat {:.4f})",
                                                    dev.narrow_features, dev.narrow_max, dev.where_narrow.lon,
                                                    dev.where_narrow.lat)
                                      : std::string(),
                                  dev.left_over_bound > 0
                                      ? fmt::format("; {} span(s) over the bound with no source point left to put back "
                                                    "(first at lon {:.4f} lat {:.4f})",
                                                    dev.left_over_bound, dev.where_over.lon, dev.where_over.lat)
                                      : std::string()));
  }
  std::vector<int> loop_tag(m.loops.size(), 0);
  std::vector<int> pts;
  std::unordered_set<int> coast_point_seen;
  for (std::uint32_t l : order) {
    const coast::CoastLoop& loop = m.loops[l];
    // Each piece of a loop writes all its points but the last, which is the next piece's
    // first; a periodic curve (a whole island) writes all of its points and closes on
    // the first. All points of the loop exist before its curves refer to them.
    pts.clear();
    std::vector<std::size_t> start(loop.curves.size());
    for (std::size_t c = 0; c < loop.curves.size(); ++c) {
      const coast::CoastCurve& cc = m.curves[loop.curves[c]];
      start[c] = pts.size();
      const std::size_t n = cc.periodic || cc.uv.empty() ? cc.uv.size() : cc.uv.size() - 1;
      for (std::size_t i = 0; i < n; ++i) {
        const int tag = model.new_point_tag();
        check_geo(in, at, model.add_point_on_geometry(tag, g, cc.uv[i]));
        record_created(k, 0, tag, at);
        pts.push_back(tag);
      }
    }
    if (pts.size() < 2)   // the kernel never returns such a loop; refuse it rather than guess
      in.fail_fmt(at, Diag::CoastlineError,
                  fmt::format("Coastline[{}]: the import produced a loop with {} point(s)", id, pts.size()));
    std::vector<int> curves;
    for (std::size_t c = 0; c < loop.curves.size(); ++c) {
      const coast::CoastCurve& cc = m.curves[loop.curves[c]];
      const std::size_t end = c + 1 < loop.curves.size() ? start[c + 1] : pts.size();
      std::vector<int> cp(pts.begin() + static_cast<std::ptrdiff_t>(start[c]), pts.begin() + static_cast<std::ptrdiff_t>(end));
      cp.push_back(cc.periodic ? pts[start[c]] : pts[end == pts.size() ? 0 : end]);
      const geo::CurveKind kind = polyline || cp.size() == 2 ? geo::CurveKind::Line : geo::CurveKind::BSpline;
      const int tag = model.new_curve_tag();
      check_geo(in, at, model.add_curve(tag, kind, cp));
      record_created(k, 1, tag, at);
      curves.push_back(tag);
      imp->curves.push_back(tag);
      if (cc.open_boundary) {
        imp->open_curves.push_back(tag);
        imp->open_sides.push_back(io.region && !polygon ? box_sides(cc.ll, *io.region) : 0);
        imp->open_edges.push_back(polygon ? polygon->edges_along(cc.ll) : std::vector<std::size_t>{});
      } else {
        imp->coast_curves.push_back(tag);
        // Its points, the ends it shares with its neighbours once (the loop's first point
        // may come last, closing the loop).
        for (int p : cp)
          if (coast_point_seen.insert(p).second) imp->coast_points.push_back(p);
      }
    }
    const int tag = model.new_loop_tag();
    check_geo(in, at, model.add_curve_loop(tag, curves));
    record_created(k, kCurveLoopKey, tag, at);
    loop_tag[l] = tag;
    imp->loops.push_back(tag);
    imp->loop_points.push_back(static_cast<int>(pts.size()));
    imp->points.insert(imp->points.end(), pts.begin(), pts.end());
  }
  for (const coast::CoastSurface& s : m.surfaces) {
    std::vector<int> sl{loop_tag[s.outer]};
    for (std::uint32_t h : s.holes) sl.push_back(loop_tag[h]);
    imp->surface_loops.push_back(std::move(sl));
    imp->outer.push_back(loop_tag[s.outer]);
    imp->loops_per_surface.push_back(static_cast<int>(1 + s.holes.size()));
  }
  invalidate_field_cache(in);
  return imp;
}

}  // namespace

void exec_coastline_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  switch (s.kind()) {
    case StmtKind::CoastlineNew: exec_coast_new(in, s, std::get<CoastlineNewStmt>(s.node)); break;
    case StmtKind::CoastlineOption: exec_coast_option(in, s, std::get<CoastlineOptionStmt>(s.node)); break;
    case StmtKind::DeleteCoastline: exec_delete_coast(in, std::get<DeleteCoastlineStmt>(s.node)); break;
    case StmtKind::CoastlineAction: {
      const auto& n = std::get<CoastlineActionStmt>(s.node);
      const int cid = coast_id(in, n.id);
      require_coast(in, cid, in.ast().expr(n.id).range, "run an action of");
      in.fail_fmt(n.action_range, Diag::UnknownCoastlineOption,
                  fmt::format("Coastline[{}] has no action '{}': import it with 'loops[] = Coastline{{{}}};'", cid,
                              in.ast().str(n.action), cid));
      break;
    }
    default: SM_ASSERT(false, "kernel/statements.def sent a statement that is not a coastline statement");
  }
}

Value eval_coastline_query(Interpreter& in, ExprId e) {
  const Expr& x = in.ast().expr(e);
  const auto& q = std::get<CoastlineQueryExpr>(x.node);
  std::vector<std::pair<int, SourceRange>> ids;
  std::string what = "Loops";
  int side = -1;   // OpenCurves of one side of the Region box (index into kSides)
  long edge = -1;  // or of one edge of the Region polygon ("Edge1" is 0)
  bool have_what = false;
  for (ExprId item : q.ids) {
    const Value v = in.eval(item);
    const SourceRange r = in.ast().expr(item).range;
    if (v.is_string() && have_what) {
      const std::string t = v.strs().empty() ? std::string() : v.strs().front();
      std::vector<std::string> names;
      for (std::size_t k = 0; k < std::size(kSides); ++k)
        if (names.emplace_back(kSides[k]), kSides[k] == t) side = static_cast<int>(k);
      if (what != "OpenCurves")
        in.fail_fmt(r, Diag::UnknownCoastlineOption,
                    fmt::format("Coastline{{}} takes a side (\"{}\") only after \"OpenCurves\", not after \"{}\"", t, what));
      if (side < 0 && v.strs().size() == 1 && t.size() > 4 && t.size() < 12 && t.starts_with("Edge") &&
          t.find_first_not_of("0123456789", 4) == std::string::npos && t[4] != '0')
        edge = std::stol(t.substr(4)) - 1;
      if ((side < 0 && edge < 0) || v.strs().size() != 1)
        in.fail_fmt(r, Diag::UnknownCoastlineOption,
                    fmt::format("Coastline{{}}: \"{}\" is not a side of the Region box{}; the sides are West, East, South "
                                "and North (Edge1, Edge2, ... for a Region polygon)",
                                t, did_you_mean(t, names)));
      continue;
    }
    if (v.is_string()) {
      have_what = true;
      what = v.strs().empty() ? std::string() : v.strs().front();
      bool known = false;
      std::vector<std::string> names;
      for (std::string_view s : kSelectors) known = known || s == what, names.emplace_back(s);
      if (!known || v.strs().size() != 1)
        in.fail_fmt(r, Diag::UnknownCoastlineOption,
                    fmt::format("Coastline{{}} cannot return \"{}\"{}; it returns {}", what, did_you_mean(what, names),
                                "Loops, Curves, OpenCurves, Points, CoastPoints, ControlPoints, Outer, LoopsPerSurface, CoastCurves, "
                                "Surfaces, Closures, DroppedSeas, Straits or Deviation"));
      continue;
    }
    for (double d : v.nums()) {
      if (!std::isfinite(d) || std::abs(d) > 2147483647.0)
        in.fail_fmt(r, Diag::WrongType, fmt::format("a coastline id must be an integer, not {}", d));
      ids.emplace_back(static_cast<int>(d), r);
    }
  }
  if (ids.empty()) in.fail_fmt(x.range, Diag::MissingCoastline, "Coastline{} needs the id of a coastline: 'Coastline{1}'");
  std::vector<double> out;
  for (const auto& [id, r] : ids) {
    CoastlineDef& d = require_coast(in, id, r, "import");
    // A side or an edge the Region does not have: an error before the import runs.
    const Value* region = option(d, "Region");
    if (what == "OpenCurves" && edge >= 0) {
      const std::size_t n = region ? region->nums().size() / 2 : 0;
      if (!region || n == 2)
        in.fail_fmt(r, Diag::WrongCoastlineOption,
                    fmt::format("Coastline{{{}, \"OpenCurves\", \"Edge{}\"}} needs a Region polygon: {}", id, edge + 1,
                                region ? "this Region is a box, whose sides are West, East, South and North"
                                       : "there is no Region"));
      if (static_cast<std::size_t>(edge) >= n)
        in.fail_fmt(r, Diag::WrongCoastlineOption,
                    fmt::format("Coastline{{{}, \"OpenCurves\", \"Edge{}\"}}: the Region polygon has {} edges, Edge1 to "
                                "Edge{}",
                                id, edge + 1, n, n));
    }
    if (what == "OpenCurves" && side >= 0) {
      if (!region)
        in.fail_fmt(r, Diag::WrongCoastlineOption,
                    fmt::format("Coastline{{{}, \"OpenCurves\", \"{}\"}} needs a Region: the sides are those of its box",
                                id, kSides[side]));
      if (region->nums().size() != 4)
        in.fail_fmt(r, Diag::WrongCoastlineOption,
                    fmt::format("Coastline{{{}, \"OpenCurves\", \"{}\"}}: the Region is a polygon, whose edges are "
                                "Edge1, Edge2, ...",
                                id, kSides[side]));
    }
    if (!d.imported) d.imported = import_coastline(in, id, d, x.range);
    const CoastlineImport& imp = *d.imported;
    if (what == "OpenCurves" && edge >= 0) {
      for (std::size_t c = 0; c < imp.open_curves.size(); ++c)
        for (std::size_t k : imp.open_edges[c])
          if (k == static_cast<std::size_t>(edge)) out.push_back(imp.open_curves[c]);
      continue;
    }
    if (what == "OpenCurves" && side >= 0) {
      for (std::size_t c = 0; c < imp.open_curves.size(); ++c)
        if (imp.open_sides[c] & (1u << side)) out.push_back(imp.open_curves[c]);
      continue;
    }
    if (what == "Deviation") {
      out.insert(out.end(), imp.deviation.begin(), imp.deviation.end());
      continue;
    }
    if (what == "Surfaces" && !imp.surfaces_made) {
      geo::Model& model = in.kernel().model;
      for (const std::vector<int>& loops : imp.surface_loops) {
        const int tag = model.new_surface_tag();
        check_geo(in, x.range, model.add_plane_surface(tag, loops));
        record_created(in.kernel(), 2, tag, x.range);
        imp.surfaces.push_back(tag);
      }
      imp.surfaces_made = true;
    }
    if (what == "Closures" || what == "DroppedSeas" || what == "Straits") {
      const std::vector<double>& f = what == "Closures" ? imp.closures : what == "Straits" ? imp.straits : imp.dropped_seas;
      out.insert(out.end(), f.begin(), f.end());
      continue;
    }
    const std::vector<int>& list = what == "Curves"          ? imp.curves
                                   : what == "CoastCurves"   ? imp.coast_curves
                                   : what == "Surfaces"      ? imp.surfaces
                                   : what == "OpenCurves"    ? imp.open_curves
                                   : what == "Points"        ? imp.points
                                   : what == "CoastPoints"   ? imp.coast_points
                                   : what == "ControlPoints" ? imp.loop_points
                                   : what == "Outer"         ? imp.outer
                                   : what == "LoopsPerSurface" ? imp.loops_per_surface
                                                             : imp.loops;
    out.insert(out.end(), list.begin(), list.end());
  }
  return Value::list(std::move(out));
}

std::optional<std::vector<int>> coastline_curves(const KernelState& k, int id) {
  const auto it = k.coastlines.find(id);
  if (it == k.coastlines.end() || !it->second.imported) return std::nullopt;
  const CoastlineImport& imp = *it->second.imported;
  std::vector<int> out;
  for (int c : imp.curves) {
    bool open = false;
    for (int o : imp.open_curves) open = open || o == c;
    if (!open) out.push_back(c);
  }
  return out;
}

}  // namespace sm::interp
