// Coastline statements (native extension, paper section 2.2): `Coastline[n] = GSHHS;`,
// `Coastline[n].Option = value;`, `Delete Coastline[n];` and the import `Coastline{n}`, which
// runs coast::build_coast_model and turns its loops into points, curves and curve loops.
#include <chrono>
#include <cmath>
#include <cstdio>
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
#include "base/cpu_clock.h"
#include "base/elapsed.h"
#include "coast/coastline_options.h"
#include "coast/import.h"
#include "coast/read.h"
#include "coast/read_shapefile.h"
#include "coast/region_polygon.h"
#include "field/registry.h"
#include "interp/coast_diagnostic.h"
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

using coast::CoastOpt;

// The options are rows of coast/coastline_options.def: read, checked and applied through
// its table (coast/coastline_options.h); here only their names are looked up.
std::string_view name_of(CoastOpt o) { return coast::coast_option_name(o); }

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

std::string did_you_mean(std::string_view name, const std::vector<std::string>& names) {
  const std::string best = field::closest_name(name, names);
  return best.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", best);
}

int coast_id(Interpreter& in, ExprId e) {
  const double v = in.eval_number(e);
  if (!std::isfinite(v) || std::abs(v) > 2147483647.0)
    in.fail(in.ast().expr(e).range, Diag::TypeIdNotInteger, std::string_view("coastline"), v);
  return static_cast<int>(v);
}

CoastlineDef& require_coast(Interpreter& in, int id, SourceRange at, std::string_view doing) {
  auto& defs = in.kernel().coastlines;
  auto it = defs.find(id);
  if (it != defs.end()) return it->second;
  std::vector<int> ids;
  for (const auto& [k, d] : defs) ids.push_back(k);
  if (ids.empty()) in.fail(at, Diag::CoastlineNoneDefined, doing, id);
  in.fail(at, Diag::CoastlineNotDefined, doing, id, fmt::format("{}", fmt::join(ids, ", ")));
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


// A value as the table reads it (its numbers, or its strings).
coast::CoastOptionValue table_value(const Value& v) {
  coast::CoastOptionValue t;
  if (v.is_string()) {
    t.is_string = true;
    t.strings = v.strs().size();
    if (!v.strs().empty()) t.str = v.strs().front();
  } else {
    t.nums = v.nums();
  }
  return t;
}

const Value* option(const CoastlineDef& d, CoastOpt o) {
  auto it = d.options.find(name_of(o));
  return it == d.options.end() ? nullptr : &it->second;
}

// Where the script set option `o` (nullptr when it did not).
const SourceRange* set_at(const CoastlineDef& d, CoastOpt o) {
  auto it = d.option_at.find(name_of(o));
  return it == d.option_at.end() ? nullptr : &it->second;
}

// RegionFile: the one polygon (one outer ring, no hole) of a shapefile, as a Region list.
Value region_from_file(Interpreter& in, int id, const std::string& path, SourceRange at) {
  auto c = coast::read_shapefile(path);
  const std::string_view region_file = name_of(CoastOpt::RegionFile);
  if (!c) in.fail(at, Diag::CoastlineOptionUnreadable, id, region_file, c.error().to_string());
  std::vector<const coast::Ring*> outer;
  std::size_t holes = 0;
  for (const coast::Ring& r : c->rings) {
    if (r.closed && r.level == 1) outer.push_back(&r);
    else ++holes;
  }
  if (outer.size() != 1 || holes > 0)
    in.fail(at, Diag::CoastlineRegionFileParts, id, region_file, path, outer.size(), holes);
  std::vector<double> x;
  for (const geo::LonLat p : outer.front()->pts) x.insert(x.end(), {p.lon, p.lat});
  auto poly = coast::RegionPolygon::make(polygon_vertices(x));
  if (!poly) in.fail(at, Diag::CoastlineRegionFileUnusable, id, region_file, path, poly.error().message);
  return Value::list(std::move(x));
}

void exec_coast_option(Interpreter& in, const Stmt& s, const CoastlineOptionStmt& n) {
  const int id = coast_id(in, n.id);
  CoastlineDef& d = require_coast(in, id, in.ast().expr(n.id).range, "set an option of");
  const std::string name(in.ast().str(n.option));
  const coast::CoastOptionSpec* o = coast::find_coast_option(name);
  if (!o) {
    std::vector<std::string> names;
    for (const coast::CoastOptionSpec& c : coast::coast_options()) names.emplace_back(c.name);
    in.fail(n.option_range, Diag::CoastlineNoOption, id, d.format, name, did_you_mean(name, names));
  }
  if (!o->only.empty() && d.format != o->only)
    in.fail(n.option_range, Diag::CoastlineOptionOtherFormat, name, o->only, id, d.format);
  if (d.imported) {
    try {
      in.fail(s.range, Diag::CoastlineOptionFrozen, id);
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{d.imported->at, "imported here"});
      throw;
    }
  }
  Value v = in.eval(n.value);
  // Checked now, so that a mistake is reported where it is written.
  if (auto why = coast::check_coast_option(*o, table_value(v)))
    in.fail(in.ast().expr(n.value).range, Diag::CoastlineOptionRefused, id, o->name, *why);
  if (o->type == coast::CoastOptionType::Path)
    v = Value::string(resolve_script_path(in.builtin_env(), v.strs().front()));
  const bool is_region = o == &coast::coast_option(CoastOpt::Region);
  const bool is_region_file = o == &coast::coast_option(CoastOpt::RegionFile);
  if ((is_region && option(d, CoastOpt::RegionFile)) ||
      (is_region_file && option(d, CoastOpt::Region) && !option(d, CoastOpt::RegionFile)))
    in.fail(s.range, Diag::CoastlineRegionTwice, id, o->name, name_of(CoastOpt::Region), name_of(CoastOpt::RegionFile));
  if (is_region_file) {
    // Read now, so that a file without one usable polygon is an error here; the polygon
    // then stands as the Region, set by this statement.
    const std::string region(name_of(CoastOpt::Region));
    d.options.insert_or_assign(region, region_from_file(in, id, v.strs().front(), s.range));
    d.option_at.insert_or_assign(region, s.range);
  }
  d.options.insert_or_assign(name, std::move(v));
  d.option_at.insert_or_assign(name, s.range);
}

void exec_delete_coast(Interpreter& in, const DeleteCoastlineStmt& n) {
  const int id = coast_id(in, n.id);
  require_coast(in, id, in.ast().expr(n.id).range, "delete");
  in.kernel().coastlines.erase(id);   // the entities an import created stay in the model
}

// A kernel error at `at`, with notes at the definition and, for file errors, at FileName.
[[noreturn]] void fail_coast(Interpreter& in, int id, const CoastlineDef& d, SourceRange at, const coast::CoastError& e,
                             bool file_error) {
  std::vector<DiagNote> notes;
  if (file_error) {
    // Records of the file, or a bad gamma(x) value at a place of it.
    for (CoastOpt o : {CoastOpt::FileName, CoastOpt::AccuracyField})
      if (const SourceRange* r = set_at(d, o))
        notes.push_back({*r, fmt::format("Coastline[{}].{} is set here", id, name_of(o))});
  }
  notes.push_back({d.defined_at, fmt::format("Coastline[{}] ({}) is defined here", id, d.format)});
  const CoastDiagnostic cd = coast_diagnostic(e, id);
  in.fail_message_with_notes(at, cd.kind, cd.message, std::move(notes));
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

// The import of one Coastline statement between its stages (import_coastline below): the
// statement, the settings the script gave, what the kernel built and what the script gets.
struct CoastImportWork {
  Interpreter& in;
  const int id;
  CoastlineDef& d;
  const SourceRange at;
  int geometry = 0;                        // the current PolarSphere's geometry id
  const geo::PolarSphere* sphere = nullptr;
  coast::CoastlineSettings set;
  std::vector<Vec3> moved;                 // the accuracy field's points, moved to the sphere's centre
  std::optional<coast::RegionPolygon> polygon;
  std::shared_ptr<CoastlineImport> imp = std::make_shared<CoastlineImport>();

  CoastImportWork(Interpreter& i, int n, CoastlineDef& def, SourceRange a) : in(i), id(n), d(def), at(a) {}
  coast::ImportOptions& io() { return set.import; }
  DiagNote defined_note() const { return {d.defined_at, fmt::format("Coastline[{}] is defined here", id)}; }
};

// The current geometry, which must be a PolarSphere: the coast's points go on it.
void find_polar_sphere(CoastImportWork& w) {
  geo::Model& model = w.in.kernel().model;
  const int g = model.current_geometry();
  const geo::SurfaceGeometry* sg = g ? model.geometry(g) : nullptr;
  if (!sg || !sg->polar()) {
    if (!sg) w.in.fail_with_notes(w.at, {w.defined_note()}, Diag::CoastlineNoPolarSphere, w.id);
    w.in.fail_with_notes(w.at, {w.defined_note()}, Diag::CoastlineOnLonLatSphere, w.id, g);
  }
  w.geometry = g;
  w.sphere = sg->polar();
}

// Every option the script set, applied by its row of the table in the table's order (each
// was checked when set); FileName (but for GSHHG) and AccuracyField are required.
void apply_settings(CoastImportWork& w) {
  for (const coast::CoastOptionSpec& o : coast::coast_options())
    if (auto it = w.d.options.find(o.name); it != w.d.options.end()) o.apply(w.set, table_value(it->second));
  const int id = w.id;
  const std::string_view file_option = name_of(CoastOpt::FileName), accuracy_option = name_of(CoastOpt::AccuracyField);
  const bool gshhg = w.d.format == "GSHHG";
  if (w.set.file_name.empty() && !gshhg)
    w.in.fail_with_notes(w.at, {w.defined_note()}, Diag::CoastlineNoFileName, id, file_option);
  if (!w.set.accuracy_field)
    w.in.fail_with_notes(w.at, {w.defined_note()}, Diag::CoastlineNoAccuracy, id, accuracy_option);
}

// The accuracy field: built now (errors located at this use), evaluated at points of
// the kernel's origin-centred sphere moved to the PolarSphere's centre.
void attach_accuracy_field(CoastImportWork& w) {
  coast::ImportOptions& io = w.io();
  const int field_id = *w.set.accuracy_field;
  const field::FieldPtr gamma_field =
      built_fields(w.in, field_id, *set_at(w.d, CoastOpt::AccuracyField)).shared(field_id);
  const Vec3 centre = w.sphere->centre();
  io.gamma = [gamma_field, centre, &moved = w.moved](std::span<const Vec3> pts, std::span<double> gamma) {
    moved.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) moved[i] = pts[i] + centre;
    gamma_field->eval(moved, gamma);
  };
  io.radius = w.sphere->radius();
}

// Mesh.MinTimeStep set before the import: passages too narrow for it at the depth of
// Mesh.DepthField are closed with the MinChannelWidth ones (coast/import.h). The depth
// must be known now, as the closures change the coastline the script then builds on.
void attach_time_step_depth(CoastImportWork& w) {
  Interpreter& in = w.in;
  KernelState& k = in.kernel();
  const double min_step = in.options().number("Mesh.MinTimeStep");
  if (!(min_step > 0)) return;
  const double depth_id = in.options().number("Mesh.DepthField");
  std::vector<DiagNote> notes;
  if (const auto it = k.option_set_at.find("Mesh.MinTimeStep"); it != k.option_set_at.end())
    notes.push_back({it->second, "Mesh.MinTimeStep was set here"});
  if (!(depth_id > 0) || !k.field_defined_at.count(static_cast<int>(depth_id))) {
    if (depth_id > 0)
      in.fail_with_notes(w.at, std::move(notes), Diag::CoastlineMinTimeStepFieldUndefined, w.id, min_step, depth_id);
    in.fail_with_notes(w.at, std::move(notes), Diag::CoastlineMinTimeStepNoDepthField, w.id, min_step);
  }
  const int did = static_cast<int>(depth_id);
  const auto dat = k.option_set_at.find("Mesh.DepthField");
  const field::FieldPtr depth = built_fields(in, did, dat != k.option_set_at.end() ? dat->second : w.at).shared(did);
  const double min_depth = in.options().number("Mesh.TimeStepMinDepth");
  w.io().min_time_step = min_step;
  w.io().depth_at = [depth, sphere = *w.sphere, min_depth](geo::LonLat ll) {
    const Vec3 x = sphere.from_lonlat(ll);
    double h = 0;
    depth->eval(std::span<const Vec3>(&x, 1), std::span<double>(&h, 1));
    return std::max(h, min_depth);
  };
}

// Points in the water (SeaAt, KeepOpen): inside the Region, longitudes compared modulo
// 360 as its box may run past +-180.
void check_water_points(CoastImportWork& w) {
  const coast::ImportOptions& io = w.io();
  if (!io.region_polygon.empty()) w.polygon = *coast::RegionPolygon::make(io.region_polygon);   // checked when set
  const int id = w.id;
  const auto region_note = [&] {
    return DiagNote{*set_at(w.d, CoastOpt::Region),
                    fmt::format("Coastline[{}].{} is set here", id, name_of(CoastOpt::Region))};
  };
  for (const CoastOpt o : {CoastOpt::SeaAt, CoastOpt::KeepOpen}) {
    const std::vector<geo::LonLat>& points = o == CoastOpt::SeaAt ? io.sea_at : io.passages.keep_open;
    for (const geo::LonLat p : points) {
      if (w.polygon && !w.polygon->contains(p))
        w.in.fail_with_notes(*set_at(w.d, o), {region_note(), {w.at, "the coastline is imported here"}},
                             Diag::CoastlinePointOutsidePolygon, id, name_of(o), p.lon, p.lat);
      if (io.region && !w.polygon) {
        const coast::LonLatBox& b = *io.region;
        const double lon = b.west + std::fmod(std::fmod(p.lon - b.west, 360.0) + 360.0, 360.0);
        if (lon > b.east || p.lat < b.south || p.lat > b.north)
          w.in.fail_with_notes(*set_at(w.d, o), {region_note(), {w.at, "the coastline is imported here"}},
                               Diag::CoastlinePointOutsideBox, id, name_of(o), p.lon, p.lat, b.west, b.east, b.south,
                               b.north);
      }
    }
  }
}

// Patch: the local shoreline, read now so that an unreadable file is an error at its
// statement; both Patch and PatchBox, or neither.
void read_patch(CoastImportWork& w) {
  coast::ImportOptions& io = w.io();
  if (w.set.patch_file.empty() && !io.patch_box) return;
  const int id = w.id;
  const CoastOpt given = w.set.patch_file.empty() ? CoastOpt::PatchBox : CoastOpt::Patch;
  const CoastOpt missing = w.set.patch_file.empty() ? CoastOpt::Patch : CoastOpt::PatchBox;
  const SourceRange given_at = *set_at(w.d, given);
  if (w.set.patch_file.empty() || !io.patch_box)
    w.in.fail(given_at, Diag::CoastlinePatchAlone, id, name_of(given), name_of(missing));
  const std::string& ppath = w.set.patch_file;
  const bool shp = ppath.size() > 4 && ppath.compare(ppath.size() - 4, 4, ".shp") == 0;
  auto pdata = coast::read_coastline(shp ? coast::CoastFormat::Shapefile : coast::CoastFormat::LonLatText, ppath);
  if (!pdata)
    w.in.fail(given_at, Diag::CoastlineOptionUnreadable, id, name_of(CoastOpt::Patch), pdata.error().to_string());
  io.patch = std::move(pdata->rings);
}

// The shoreline file read; an unreadable one is an error at the statement that named it:
// FileName, else Resolution, else the import.
coast::Coastline read_shoreline(CoastImportWork& w) {
  const coast::ImportOptions& io = w.io();
  // GSHHG: the reader itself keeps the levels, areas and bins asked for (the import
  // filters the same again), so that a Region reads only the polygons it touches.
  coast::GshhgBinnedOptions gopt;
  gopt.levels = io.levels;
  gopt.antarctica_level = io.antarctica_level;
  gopt.min_area_km2 = io.coarsen.min_area_km2;
  gopt.region = io.region;
  gopt.threads = io.threads;
  const std::string path =
      !w.set.file_name.empty() ? w.set.file_name : coast::gshhg_binned_file(w.set.resolution.front());
  auto data = coast::read_coastline(*coast::parse_coast_format(w.d.format), path, w.set.loops2, gopt);
  if (!data) {
    const SourceRange* f = set_at(w.d, CoastOpt::FileName);
    if (!f) f = set_at(w.d, CoastOpt::Resolution);
    if (!f) fail_coast(w.in, w.id, w.d, w.at, data.error(), false);
    try {
      fail_coast(w.in, w.id, w.d, *f, data.error(), false);
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{w.at, "the coastline is imported here"});
      throw;
    }
  }
  return std::move(*data);
}

// The kernel's import failed: located where the option at fault is set (a dam, a SeaAt or
// KeepOpen point), else at the import with notes at the definition and the file.
[[noreturn]] void fail_build(CoastImportWork& w, const coast::CoastError& e) {
  if (auto o = w.d.option_at.find(e.option); !e.option.empty() && o != w.d.option_at.end()) {
    try {
      fail_coast(w.in, w.id, w.d, o->second, e, false);
    } catch (RuntimeError& err) {
      err.notes.insert(err.notes.begin(), DiagNote{w.at, "the coastline is imported here"});
      const SourceRange* dams = set_at(w.d, CoastOpt::Dams);
      if (e.option == name_of(CoastOpt::KeepOpen) && dams && e.message.find("dam from") != std::string::npos)
        err.notes.insert(err.notes.begin(),
                         DiagNote{*dams, fmt::format("Coastline[{}].{} is set here", w.id, name_of(CoastOpt::Dams))});
      throw;
    }
  }
  fail_coast(w.in, w.id, w.d, w.at, e, true);
}

// The kernel's reading and building: the account's "import" stage (making the script's
// entities from its loops is the script's own time).
coast::CoastModel read_and_build(CoastImportWork& w) {
  std::optional<StageScope> import_stage(std::in_place, &w.in.kernel().clock, nullptr, "import");
  const double read_start = process_cpu_seconds();
  const auto read_wall_start = std::chrono::steady_clock::now();
  coast::Coastline source = read_shoreline(w);
  const double read_cpu = process_cpu_seconds() - read_start, read_wall = seconds_since(read_wall_start);
  auto built = coast::build_coast_model(std::move(source), w.io());
  import_stage.reset();
  // Where the import's time went, step by step (CPU seconds of every thread / wall
  // seconds), at Gmsh's debug level (-v 99): the Time line's "import" taken apart.
  if (built && w.in.options().number("General.Verbosity") >= 99) {
    std::string line = fmt::format("Import steps (CPU/wall s): read {:.3f}/{:.3f}", read_cpu, read_wall);
    for (const coast::ImportStepTime& t : built->report.step_cpu)
      line += fmt::format(", {} {:.3f}/{:.3f}", t.name, t.seconds, t.wall);
    std::fflush(stdout);
    std::fputs((line + "\n").c_str(), stderr);
    std::fflush(stderr);
  }
  // The import's working arrays (the source points three times over, the passage pool:
  // hundreds of MB for the full-resolution world) are freed now, but many came from the
  // heap, whose free pages stay resident beside everything made after (the fields, the
  // mesh): given back to the system (the 3 km world's -2 peak, docs/benchmarks_scale.md).
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  if (!built) fail_build(w, built.error());
  return std::move(*built);
}

// What the import changed, each with its place and figure: the terminal groups the many of
// this statement (cli/diagnostic_stream.h), --diagnostics FILE keeps every one. A dropped
// sea goes with the count of them, at SeaAt. The closures, dropped seas and straits are
// kept for Coastline{n, "..."}.
void report_changes(CoastImportWork& w, const coast::CoastModel& m) {
  Interpreter& in = w.in;
  const CoastlineDef& d = w.d;
  const int id = w.id;
  if (m.report.patch) {   // where the two shorelines disagree at the patch box
    const coast::PatchReport& pr = *m.report.patch;
    in.diags().report(*set_at(d, CoastOpt::Patch), Diag::CoastlinePatchSplice, id, pr.base_chains, pr.local_chains,
                      pr.steps, pr.max_step_m, pr.max_step_at.lon, pr.max_step_at.lat);
  }
  if (m.seas_dropped > 0)
    in.diags().report(*set_at(d, CoastOpt::SeaAt), Diag::CoastlineSeasDroppedCount, id, m.seas_dropped,
                      m.surfaces.size());
  CoastlineImport& imp = *w.imp;
  for (const coast::ReportLine& line : m.report.items()) {
    // A dropped sea at SeaAt, a passage kept open at KeepOpen, a closure at the import.
    if (line.sea_dropped)
      report_passage_change(in.diags(), *set_at(d, CoastOpt::SeaAt), id, line);
    else if (line.step_unmet || line.kept_open)
      report_passage_change(in.diags(), *set_at(d, CoastOpt::KeepOpen), id, line);
    else if (line.passage)
      report_passage_change(in.diags(), w.at, id, line);
    else
      in.diags()
          .report(w.at, Diag::CoastlineRepair, fmt::format("Coastline[{}]", id), line.text)
          .item(coastline_item(line));
  }
  for (const coast::RepairEntry& e : m.report.repair) {   // for Coastline{n, "Closures"} and "DroppedSeas"
    std::vector<double>* list = e.kind == coast::RepairKind::ClosedPassage ? &imp.closures
                                : e.kind == coast::RepairKind::DroppedSea  ? &imp.dropped_seas
                                                                           : nullptr;
    if (list) list->insert(list->end(), {e.where.lon, e.where.lat, e.value});
    // The straits left open, with the Courant step one element across costs (0 without
    // Mesh.MinTimeStep): what a script checks a time step's closures against.
    if (e.kind == coast::RepairKind::NarrowStrait)
      imp.straits.insert(imp.straits.end(), {e.where.lon, e.where.lat, e.value, std::isnan(e.step) ? 0.0 : e.step});
  }
  if (m.region_empty) {   // the box of the Region, or of the file's own -R
    const coast::ImportOptions& io = w.io();
    const SourceRange* r = set_at(d, CoastOpt::Region);
    const SourceRange region_at = r ? *r : w.at;
    if (w.polygon)
      in.diags().report(region_at, Diag::CoastlineRegionPolygonEmpty, id);
    else if (io.region)
      in.diags().report(region_at, Diag::CoastlineRegionBoxEmpty, id, io.region->west, io.region->east,
                        io.region->south, io.region->north);
    else
      in.diags().report(region_at, Diag::CoastlineFileRegionEmpty, id);
  }
}

// Loops surface by surface (outer first), then the holes no outer loop holds.
std::vector<std::uint32_t> loop_order(const coast::CoastModel& m) {
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
  return order;
}

// One line per import: how far the coast the mesher follows lies from the data. At the
// coastline's definition: the import statement's own caret heads the group of its repairs
// (cli/diagnostic_stream.h).
void report_deviation(CoastImportWork& w, const coast::CoastModel& m) {
  const coast::DeviationReport& dev = m.report.deviation;
  w.imp->deviation = {dev.max, dev.p95, dev.max_before, dev.where.lon, dev.where.lat,
                      static_cast<double>(dev.points_added)};
  lang::Diagnostics& diags = w.in.diags();
  const SourceRange at = w.d.defined_at;
  const bool narrow = dev.narrow_features > 0, over = dev.left_over_bound > 0;
  if (narrow && over)
    diags.report(at, Diag::CoastlineDeviationNarrowOverBound, w.id, dev.max, dev.p95, dev.max_before, dev.points_added,
                 dev.where.lon, dev.where.lat, dev.narrow_features, dev.narrow_max, dev.where_narrow.lon,
                 dev.where_narrow.lat, dev.left_over_bound, dev.where_over.lon, dev.where_over.lat);
  else if (narrow)
    diags.report(at, Diag::CoastlineDeviationNarrow, w.id, dev.max, dev.p95, dev.max_before, dev.points_added,
                 dev.where.lon, dev.where.lat, dev.narrow_features, dev.narrow_max, dev.where_narrow.lon,
                 dev.where_narrow.lat);
  else if (over)
    diags.report(at, Diag::CoastlineDeviationOverBound, w.id, dev.max, dev.p95, dev.max_before, dev.points_added,
                 dev.where.lon, dev.where.lat, dev.left_over_bound, dev.where_over.lon, dev.where_over.lat);
  else
    diags.report(at, Diag::CoastlineDeviation, w.id, dev.max, dev.p95, dev.max_before, dev.points_added, dev.where.lon,
                 dev.where.lat);
}

// One loop's points, curves and curve loop in the model; returns the loop's tag. Each piece
// of a loop writes all its points but the last, which is the next piece's first; a periodic
// curve (a whole island) writes all of its points and closes on the first. All points of
// the loop exist before its curves refer to them.
int add_loop(CoastImportWork& w, const coast::CoastModel& m, const coast::CoastLoop& loop,
             std::unordered_set<int>& coast_point_seen) {
  Interpreter& in = w.in;
  KernelState& k = in.kernel();
  geo::Model& model = k.model;
  const SourceRange at = w.at;
  const coast::ImportOptions& io = w.io();
  CoastlineImport& imp = *w.imp;
  const bool polyline = !io.deviation.bspline;   // CurveType "Line"
  std::vector<int> pts;
  std::vector<std::size_t> start(loop.curves.size());
  for (std::size_t c = 0; c < loop.curves.size(); ++c) {
    const coast::CoastCurve& cc = m.curves[loop.curves[c]];
    start[c] = pts.size();
    const std::size_t n = cc.periodic || cc.uv.empty() ? cc.uv.size() : cc.uv.size() - 1;
    for (std::size_t i = 0; i < n; ++i) {
      const int tag = model.new_point_tag();
      check_geo(in, at, model.add_point_on_geometry(tag, w.geometry, cc.uv[i]));
      record_created(k, 0, tag, at);
      pts.push_back(tag);
    }
  }
  if (pts.size() < 2)   // the kernel never returns such a loop; refuse it rather than guess
    in.fail(at, Diag::CoastlineLoopTooShort, w.id, pts.size());
  std::vector<int> curves;
  for (std::size_t c = 0; c < loop.curves.size(); ++c) {
    const coast::CoastCurve& cc = m.curves[loop.curves[c]];
    const std::size_t end = c + 1 < loop.curves.size() ? start[c + 1] : pts.size();
    std::vector<int> cp(pts.begin() + static_cast<std::ptrdiff_t>(start[c]),
                        pts.begin() + static_cast<std::ptrdiff_t>(end));
    cp.push_back(cc.periodic ? pts[start[c]] : pts[end == pts.size() ? 0 : end]);
    const geo::CurveKind kind = polyline || cp.size() == 2 ? geo::CurveKind::Line : geo::CurveKind::BSpline;
    const int tag = model.new_curve_tag();
    check_geo(in, at, model.add_curve(tag, kind, cp));
    record_created(k, 1, tag, at);
    curves.push_back(tag);
    imp.curves.push_back(tag);
    if (cc.open_boundary) {
      imp.open_curves.push_back(tag);
      imp.open_sides.push_back(io.region && !w.polygon ? box_sides(cc.ll, *io.region) : 0);
      imp.open_edges.push_back(w.polygon ? w.polygon->edges_along(cc.ll) : std::vector<std::size_t>{});
    } else {
      imp.coast_curves.push_back(tag);
      // Its points, the ends it shares with its neighbours once (the loop's first point
      // may come last, closing the loop).
      for (int p : cp)
        if (coast_point_seen.insert(p).second) imp.coast_points.push_back(p);
    }
  }
  const int tag = model.new_loop_tag();
  check_geo(in, at, model.add_curve_loop(tag, curves));
  record_created(k, kCurveLoopKey, tag, at);
  imp.loops.push_back(tag);
  imp.loop_points.push_back(static_cast<int>(pts.size()));
  imp.points.insert(imp.points.end(), pts.begin(), pts.end());
  return tag;
}

// The script's entities: the loops in loop_order, then each surface's loops (outer first).
void add_entities(CoastImportWork& w, const coast::CoastModel& m, const std::vector<std::uint32_t>& order) {
  std::vector<int> loop_tag(m.loops.size(), 0);
  std::unordered_set<int> coast_point_seen;
  for (std::uint32_t l : order) loop_tag[l] = add_loop(w, m, m.loops[l], coast_point_seen);
  for (const coast::CoastSurface& s : m.surfaces) {
    std::vector<int> sl{loop_tag[s.outer]};
    for (std::uint32_t h : s.holes) sl.push_back(loop_tag[h]);
    w.imp->surface_loops.push_back(std::move(sl));
    w.imp->outer.push_back(loop_tag[s.outer]);
    w.imp->loops_per_surface.push_back(static_cast<int>(1 + s.holes.size()));
  }
}

// Runs the import of Coastline[id] and adds its entities to the model.
std::shared_ptr<const CoastlineImport> import_coastline(Interpreter& in, int id, CoastlineDef& d, SourceRange at) {
  CoastImportWork w(in, id, d, at);
  find_polar_sphere(w);
  apply_settings(w);
  attach_accuracy_field(w);
  attach_time_step_depth(w);
  check_water_points(w);
  // Cleaning and coarsening ring by ring on -nt threads (the same rings for every count).
  w.io().threads = static_cast<int>(in.options().number("General.NumThreads"));
  w.io().progress = progress_sink(in);
  read_patch(w);
  const coast::CoastModel m = read_and_build(w);
  report_changes(w, m);
  const std::vector<std::uint32_t> order = loop_order(m);
  sync_geometry_options(in);
  w.imp->at = at;
  report_deviation(w, m);
  add_entities(w, m, order);
  invalidate_field_cache(in);
  return w.imp;
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
      in.fail(n.action_range, Diag::CoastlineNoAction, cid, std::string(in.ast().str(n.action)));
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
        in.fail(r, Diag::CoastlineSideMisplaced, t, what);
      if (side < 0 && v.strs().size() == 1 && t.size() > 4 && t.size() < 12 && t.starts_with("Edge") &&
          t.find_first_not_of("0123456789", 4) == std::string::npos && t[4] != '0')
        edge = std::stol(t.substr(4)) - 1;
      if ((side < 0 && edge < 0) || v.strs().size() != 1)
        in.fail(r, Diag::CoastlineNotASide, t, did_you_mean(t, names));
      continue;
    }
    if (v.is_string()) {
      have_what = true;
      what = v.strs().empty() ? std::string() : v.strs().front();
      bool known = false;
      std::vector<std::string> names;
      for (std::string_view s : kSelectors) known = known || s == what, names.emplace_back(s);
      if (!known || v.strs().size() != 1)
        in.fail(r, Diag::CoastlineUnknownSelector, what, did_you_mean(what, names),
                fmt::format("{}", fmt::join(std::begin(kSelectors), std::end(kSelectors) - 1, ", ")),
                std::end(kSelectors)[-1]);
      continue;
    }
    for (double d : v.nums()) {
      if (!std::isfinite(d) || std::abs(d) > 2147483647.0)
        in.fail(r, Diag::TypeIdNotInteger, std::string_view("coastline"), d);
      ids.emplace_back(static_cast<int>(d), r);
    }
  }
  if (ids.empty()) in.fail(x.range, Diag::CoastlineQueryNoId);
  std::vector<double> out;
  for (const auto& [id, r] : ids) {
    CoastlineDef& d = require_coast(in, id, r, "import");
    // A side or an edge the Region does not have: an error before the import runs.
    const Value* region = option(d, CoastOpt::Region);
    if (what == "OpenCurves" && edge >= 0) {
      const std::size_t n = region ? region->nums().size() / 2 : 0;
      if (!region) in.fail(r, Diag::CoastlineEdgeNoRegion, id, edge + 1);
      if (n == 2) in.fail(r, Diag::CoastlineEdgeOfBox, id, edge + 1);
      if (static_cast<std::size_t>(edge) >= n) in.fail(r, Diag::CoastlineEdgeOutOfRange, id, edge + 1, n);
    }
    if (what == "OpenCurves" && side >= 0) {
      if (!region) in.fail(r, Diag::CoastlineSideNoRegion, id, kSides[side]);
      if (region->nums().size() != 4) in.fail(r, Diag::CoastlineSideOfPolygon, id, kSides[side]);
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
      const std::vector<double>& f = what == "Closures"  ? imp.closures
                                     : what == "Straits" ? imp.straits
                                                         : imp.dropped_seas;
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
