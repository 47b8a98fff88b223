// `Plugin(GSHHS).Option = value; Plugin(GSHHS).Run;`: Gmsh 2.6's coastline plugin with its old
// options (docs/coastlines.md), run by coast::run_gshhs_plugin; the .geo it writes is read by
// stereomesh and Gmsh 4.8.4 alike. The output file appears whole or not at all.
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

#include "coast/gshhs_plugin_geo.h"
#include "field/registry.h"
#include "interp/coast_diagnostic.h"
#include "interp/kernel/coastline_report.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/field_eval.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

struct PluginOption {
  std::string_view name;
  bool is_string;
};

// Gmsh 2.6's option names (case as Gmsh prints them).
constexpr PluginOption kPluginOptions[] = {
    {"InFileName", true},  {"OutFileName", true},        {"iField", false},         {"Format", true},
    {"Coordinate", true},  {"UTMZone", false},           {"UTMEquatorialRadius", false},
    {"UTMPolarRadius", false}, {"radius", false},        {"WritePolarSphere", false}, {"MinStraitsFactor", false},
};

const PluginOption* find_plugin_option(std::string_view name) {
  for (const PluginOption& o : kPluginOptions)
    if (o.name == name) return &o;
  return nullptr;
}

void set_plugin_option(Interpreter& in, const PluginStmt& p, const std::string& name) {
  const PluginOption* o = find_plugin_option(name);
  if (!o) {
    std::vector<std::string> names;
    for (const PluginOption& c : kPluginOptions) names.emplace_back(c.name);
    const std::string best = field::closest_name(name, names);
    if (best.empty()) in.fail(p.member_range, Diag::PluginNoOption, name, fmt::format("{}", fmt::join(names, ", ")));
    in.fail(p.member_range, Diag::PluginNoOptionLike, name, best);
  }
  const Value v = in.eval(p.value);
  const SourceRange at = in.ast().expr(p.value).range;
  if (o->is_string != v.is_string() || (v.is_string() ? v.strs().size() : v.nums().size()) != 1)
    in.fail(at, Diag::PluginOptionType, name, std::string_view(o->is_string ? "one string" : "one number"));
  if (!o->is_string && !std::isfinite(v.nums().front()))
    in.fail(at, Diag::PluginOptionNotFinite, name);
  in.kernel().gshhs_plugin_options.insert_or_assign(name, v);
}

void run_plugin(Interpreter& in, const Stmt& s) {
  const auto& set = in.kernel().gshhs_plugin_options;
  auto str = [&](std::string_view n, std::string fallback) {
    auto it = set.find(n);
    return it == set.end() ? fallback : it->second.strs().front();
  };
  auto num = [&](std::string_view n, double fallback) {
    auto it = set.find(n);
    return it == set.end() ? fallback : it->second.nums().front();
  };
  coast::GshhsPluginOptions opt;
  // Both file names are relative to the script, like every file name of a script here.
  opt.in_file_name = resolve_script_path(in.builtin_env(), str("InFileName", opt.in_file_name));
  const std::string out = resolve_script_path(in.builtin_env(), str("OutFileName", opt.out_file_name));
  opt.format = str("Format", opt.format);
  opt.coordinate = str("Coordinate", opt.coordinate);
  opt.utm_zone = static_cast<int>(num("UTMZone", opt.utm_zone));
  opt.utm_equatorial_radius = num("UTMEquatorialRadius", opt.utm_equatorial_radius);
  opt.utm_polar_radius = num("UTMPolarRadius", opt.utm_polar_radius);
  opt.radius = num("radius", opt.radius);
  opt.write_polar_sphere = static_cast<int>(num("WritePolarSphere", opt.write_polar_sphere));
  opt.min_straits_factor = num("MinStraitsFactor", opt.min_straits_factor);
  const int field_id = static_cast<int>(num("iField", -1));
  if (field_id >= 0) {
    // Gmsh evaluates iField at the points of the origin-centred sphere of `radius`.
    const field::FieldPtr f = built_fields(in, field_id, s.range).shared(field_id);
    opt.field = [f](std::span<const Vec3> pts, std::span<double> g) { f->eval(pts, g); };
  }
  // Written under a temporary name beside the target, then renamed over it.
  opt.out_file_name = fmt::format("{}.part{}", out, static_cast<long>(::getpid()));
  auto res = coast::run_gshhs_plugin(opt);
  std::error_code ec;
  if (!res) {
    std::filesystem::remove(opt.out_file_name, ec);
    coast::CoastError e = res.error();
    if (e.file == opt.out_file_name) e.file = out;
    const CoastDiagnostic cd = coast_diagnostic(e, std::nullopt);
    in.fail_message(s.range, cd.kind, cd.message);
  }
  std::filesystem::rename(opt.out_file_name, out, ec);
  if (ec) {
    std::filesystem::remove(opt.out_file_name, ec);
    in.fail_fmt(s.range, Diag::FileWriteError, out, ec.message());
  }
  for (const coast::ReportLine& line : res->model.report.items())
    in.diags().report(s.range, Diag::CoastlineRepair, "Plugin(GSHHS)", line.text).item(coastline_item(line));
}

void exec_gshhs_plugin_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  const auto& p = std::get<PluginStmt>(s.node);
  const std::string member(in.ast().str(p.member));
  if (p.value.valid()) {
    set_plugin_option(in, p, member);
    return;
  }
  if (member != "Run")
    in.fail(p.member_range, Diag::PluginNoAction, member);
  run_plugin(in, s);
}

}  // namespace

void exec_plugin_stmt(Interpreter& in, StmtId id) {
  if (in.ast().str(std::get<PluginStmt>(in.ast().stmt(id).node).plugin) == "GSHHS")
    exec_gshhs_plugin_stmt(in, id);
  else
    exec_mesh_stmt(in, id);   // the other plugins: not supported
}

}  // namespace sm::interp
