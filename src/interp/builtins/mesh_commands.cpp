// Mesh commands: `Mesh 1;` runs the 1D mesher (mesh/mesh1d) on the model with the
// script's Mesh.* options and Background Field, `Save "f";` writes the current mesh
// (MSH 2.2/4.1 or VTK by extension) atomically, and the command line's -1 does both.
// The other mesh commands and post-processing statements are reported as not supported.
#include "interp/builtins/mesh_commands.h"

#include <array>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "interp/builtins/dispatch.h"
#include "interp/builtins/field_context.h"
#include "interp/builtins/field_eval.h"
#include "interp/builtins/size_policy_from_options.h"
#include "interp/interpreter.h"
#include "io/from_model_mesh.h"
#include "io/msh_writer.h"
#include "io/vtk_writer.h"
#include "mesh/mesh1d.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

Mesh1dOptions mesh1d_options(Interpreter& in, const field::SizeField* background) {
  const Options& o = in.options();
  Mesh1dOptions opt;
  opt.size = size_policy_from_options(o);
  opt.background = background;
  opt.bbox_diag = model_bbox_diag(in.kernel().model);
  opt.min_curve_nodes = static_cast<int>(o.number("Mesh.MinimumCurveNodes"));
  opt.min_circle_nodes = static_cast<int>(o.number("Mesh.MinimumCircleNodes"));
  opt.smooth_ratio = o.number("Mesh.SmoothRatio");
  return opt;
}

// "curve 7 was created here" for the curves a mesher error names.
std::vector<DiagNote> curve_notes(const KernelState& k, const Mesh1dError& e) {
  std::vector<DiagNote> notes;
  for (int tag : {e.curve_a, e.curve_b}) {
    if (tag <= 0 || (tag == e.curve_b && e.curve_a == e.curve_b && !notes.empty())) continue;
    const auto it = k.created_at.find({1, tag});
    if (it != k.created_at.end()) notes.push_back({it->second, fmt::format("curve {} was created here", tag)});
  }
  return notes;
}

Diag diag_of(const Mesh1dError& e) {
  return e.kind == Mesh1dErrorKind::Intersection || e.kind == Mesh1dErrorKind::DuplicatePoint
             ? Diag::MeshCurvesIntersect
             : Diag::MeshFailed;
}

// Meshes the model up to `dim` into the kernel state; on failure returns the error.
Mesh1dError mesh_model(Interpreter& in, int dim) {
  KernelState& k = in.kernel();
  const field::FieldPtr background = background_size_field(in);
  Mesh1dResult r = mesh_curves(k.model, mesh1d_options(in, background.get()));
  if (!r.ok()) return r.error;
  k.mesh = std::make_shared<ModelMesh>(std::move(r.mesh));
  in.options().set_number("Mesh.NbNodes", static_cast<double>(k.mesh->nodes.size()), /*internal=*/true);
  (void)dim;
  return {};
}

// Writes the current mesh to `path` in `format` (see mesh_commands.h); "" or why not.
std::string save_mesh(Interpreter& in, const std::string& path, std::string format) {
  const KernelState& k = in.kernel();
  const ModelMesh empty;
  const io::MeshModel mm = io::from_model_mesh(k.model, k.mesh ? *k.mesh : empty);
  const Options& o = in.options();
  if (format.empty()) {
    const std::string ext = std::filesystem::path(path).extension().string();
    const int mesh_format = static_cast<int>(o.number("Mesh.Format"));
    if (mesh_format == 1 || (mesh_format == 10 && ext == ".msh")) format = "msh";
    else if (mesh_format == 16 || (mesh_format == 10 && ext == ".vtk")) format = "vtk";
    else return fmt::format("unsupported mesh format for '{}' (use .msh or .vtk)", path);
  }
  const bool binary = o.number("Mesh.Binary") != 0;
  const bool save_all = o.number("Mesh.SaveAll") != 0;
  std::string error;
  if (format == "vtk") {
    io::VtkOptions vo;
    vo.binary = binary;
    vo.save_all = save_all;
    return io::save_vtk(mm, vo, path, &error) ? std::string{} : error;
  }
  io::MshOptions mo;
  if (format == "msh22" || format == "msh2") mo.version = 22;
  else if (format == "msh41" || format == "msh4") mo.version = 41;
  else if (format == "msh") mo.version = o.number("Mesh.MshFileVersion") < 3 ? 22 : 41;
  else return fmt::format("unknown format '{}' (msh41, msh22, msh4, msh2, msh, vtk)", format);
  mo.binary = binary;
  mo.save_all = save_all;
  mo.save_parametric = o.number("Mesh.SaveParametric") != 0;
  return io::save_msh(mm, mo, path, &error) ? std::string{} : error;
}

void exec_mesh(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  const double n = c.arg.valid() ? in.eval_number(c.arg) : 2;
  if (n >= 2) {
    in.not_supported_stmt(id, "Mesh 2");
    return;
  }
  const Mesh1dError e = mesh_model(in, 1);
  if (e.kind != Mesh1dErrorKind::None) in.fail_with_notes(s.range, diag_of(e), e.message, curve_notes(in.kernel(), e));
}

void exec_save(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  std::string name = in.eval_string(c.arg);
  // Relative to the script (Gmsh: relative to the directory of the file being parsed).
  std::filesystem::path p(name);
  if (p.is_relative()) p = std::filesystem::path(in.sources().path(s.range.file)).parent_path() / p;
  if (const std::string err = save_mesh(in, p.string(), ""); !err.empty())
    in.fail_fmt(c.arg.valid() ? in.ast().expr(c.arg).range : s.range, Diag::FileWriteError, name, err);
}

}  // namespace

bool exec_mesh_command(Interpreter& in, StmtId id, std::string_view command) {
  const Stmt& s = in.ast().stmt(id);
  if (const auto* c = std::get_if<CommandStmt>(&s.node)) {
    if (command == "Mesh") {
      exec_mesh(in, id, *c);
      return true;
    }
    if (command == "Save" && c->arg.valid()) {
      exec_save(in, id, *c);
      return true;
    }
  }
  static constexpr std::array<std::string_view, 18> kKnown = {
      "Mesh", "Save", "Merge", "Print", "SystemCall", "CreateDir", "OptimizeMesh", "SetName",
      "SetOrder", "Sleep", "PartitionMesh", "RefineMesh", "RecombineMesh", "RenumberMeshNodes",
      "RenumberMeshElements", "SyncModel", "BoundingBox", "Coherence"};
  for (std::string_view k : kKnown) {
    if (k == command) {
      check_stmt_exprs(in, id);
      in.not_supported_stmt(id, command);
      return true;
    }
  }
  return false;
}

void exec_mesh_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  check_stmt_exprs(in, id);
  switch (s.kind()) {
    case StmtKind::Plugin: in.not_supported_stmt(id, "Plugin"); break;
    case StmtKind::View: in.not_supported_stmt(id, "View"); break;
    case StmtKind::Color: in.not_supported_stmt(id, "Color"); break;
    default: in.not_supported_stmt(id, "Coherence Mesh"); break;
  }
}

bool mesh_from_command_line(Interpreter& in, int dim, const std::string& output, const std::string& format,
                            const std::string& first_script) {
  Diagnostics& diags = in.diags();
  if (dim >= 2) {
    diags.report_message(SourceRange{}, Diag::NotSupportedYet,
                         fmt::format("'-{}' is not supported yet: 2D meshing arrives with the 2D mesher; use -1", dim));
    return false;
  }
  Mesh1dError e;
  try {
    e = mesh_model(in, dim);
  } catch (const RuntimeError& err) {   // e.g. the background field cannot be built
    auto h = diags.report_message(err.range, err.kind, err.message);
    for (const DiagNote& n : err.notes) h.note(n.range, n.message);
    return false;
  }
  if (e.kind != Mesh1dErrorKind::None) {
    auto h = diags.report_message(SourceRange{}, diag_of(e), e.message);
    for (const DiagNote& n : curve_notes(in.kernel(), e)) h.note(n.range, n.message);
    return false;
  }
  std::string path = output;
  if (path.empty()) {
    std::filesystem::path p(first_script);
    p.replace_extension(format == "vtk" ? ".vtk" : ".msh");
    path = p.string();
  }
  if (const std::string err = save_mesh(in, path, format); !err.empty()) {
    diags.report(SourceRange{}, Diag::FileWriteError, path, err);
    return false;
  }
  return true;
}

}  // namespace sm::interp
