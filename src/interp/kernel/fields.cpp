// Size field statements (docs/fields.md): Field[n] = Kind, options, actions,
// Delete Field and Background Field, recorded in the kernel's FieldSet with the
// statement of each definition and option, so that build errors are located.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "base/check.h"
#include "field/error.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/field_eval.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// Gmsh truncates the id to an int; we also refuse what no int can hold.
int field_id(Interpreter& in, ExprId e) {
  const double v = in.eval_number(e);
  if (!std::isfinite(v) || std::abs(v) > 2147483647.0)
    in.fail(in.ast().expr(e).range, Diag::TypeIdNotInteger, std::string_view("field"), v);
  return static_cast<int>(v);
}

void require_field(Interpreter& in, int id, ExprId id_expr, std::string_view doing) {
  if (in.kernel().fields.contains(id)) return;
  const auto ids = in.kernel().fields.ids();
  in.fail(in.ast().expr(id_expr).range, Diag::MissingFieldFor, doing, id,
          ids.empty() ? std::string(" (no field is)") : fmt::format(" (defined: {})", fmt::join(ids, ", ")));
}

void exec_field_new(Interpreter& in, const Stmt& s, const FieldNewStmt& n) {
  const int id = field_id(in, n.id);
  const std::string kind(in.ast().str(n.type));
  KernelState& k = in.kernel();
  try {
    k.fields.define(id, kind);
  } catch (const field::FieldError& e) {
    if (e.code() == field::FieldErrc::DuplicateId) {
      // Gmsh 4.8.4: "Field id n is already defined", and the old field stays.
      try {
        in.fail(in.ast().expr(n.id).range, Diag::DuplicateFieldId, id);
      } catch (RuntimeError& err) {
        auto it = k.field_defined_at.find(id);
        if (it != k.field_defined_at.end())
          err.notes.insert(err.notes.begin(), DiagNote{it->second, "first defined here"});
        throw;
      }
    }
    fail_field_error(in, e, n.type_range);
  }
  k.field_defined_at[id] = s.range;
  invalidate_field_cache(in);
}

// The script value as the option's type wants it. A bare number where a list
// is expected is ignored by Gmsh 4.8.4 without a word: we warn and ignore it
// too, so that a script means the same in both. Returns false to skip the set.
bool option_value(Interpreter& in, const FieldOptionStmt& n, int id, const field::OptionSpec* spec,
                  field::OptionValue& out) {
  const Value v = in.eval(n.value);
  const SourceRange value_at = in.ast().expr(n.value).range;
  if (v.is_string()) {
    // A Bathymetry's FileName takes a list of grids by priority: {"fine.nc", "coarse.nc"}
    // or "fine.nc, coarse.nc", each name relative to the script; the kernel gets them
    // comma-separated (field/bathymetry.cpp).
    const bool grid_list =
        spec && spec->name == "FileName" && in.kernel().fields.options(id).kind().name == "Bathymetry";
    if (v.kind() == Value::Kind::StringList && v.strs().size() != 1 && !(grid_list && v.strs().size() > 1))
      in.fail(value_at, Diag::FieldOptionOneString, in.ast().str(n.option), id, v.strs().size());
    std::string text;
    if (grid_list) {
      std::vector<std::string> names;
      for (const std::string& s : v.strs()) {
        std::size_t b = 0;
        for (std::size_t k = 0; k <= s.size(); ++k) {
          if (k < s.size() && s[k] != ',') continue;
          names.push_back(s.substr(b, k - b));
          b = k + 1;
        }
      }
      for (std::string& name : names) {
        const std::size_t lo = name.find_first_not_of(" \t"), hi = name.find_last_not_of(" \t");
        name = lo == std::string::npos ? std::string() : name.substr(lo, hi - lo + 1);
        if (!name.empty()) name = resolve_script_path(in.builtin_env(), name);
        if (&name != &names.front()) text += ", ";
        text += name;
      }
    } else {
      text = v.strs().empty() ? std::string() : v.strs().front();
      // File options are relative to the script, as Gmsh's FIELD_OPTION_PATH.
      if (spec && spec->name == "FileName" && !text.empty()) text = resolve_script_path(in.builtin_env(), text);
    }
    out = std::move(text);
    return true;
  }
  const bool list = n.braced || v.kind() == Value::Kind::List;
  if (spec && spec->type == field::OptionType::List && !list) {
    in.diags().report(value_at, Diag::FieldListWithoutBraces, in.ast().str(n.option), id,
                      in.kernel().fields.options(id).kind().name, in.text_of(value_at));
    return false;
  }
  // Ids and tags become ints in the kernel: they must fit one.
  const bool ids = spec && (spec->type == field::OptionType::List ||
                            spec->role != field::OptionRole::Plain);
  for (double x : v.nums()) {
    if (!std::isfinite(x))
      in.fail(value_at, Diag::FieldOptionNotFinite, in.ast().str(n.option), id);
    if (ids && std::abs(x) > 2147483647.0)
      in.fail(value_at, Diag::FieldOptionNotValidId, in.ast().str(n.option), id, x);
  }
  if (list) {
    out = v.nums();
  } else {
    out = v.nums().front();
  }
  return true;
}

void exec_field_option(Interpreter& in, const Stmt& s, const FieldOptionStmt& n) {
  const int id = field_id(in, n.id);
  require_field(in, id, n.id, "set an option of");
  KernelState& k = in.kernel();
  const std::string option(in.ast().str(n.option));
  const field::Options& opts = k.fields.options(id);
  const int index = opts.find(option);
  const field::OptionSpec* spec =
      index < 0 ? nullptr : &opts.kind().options[static_cast<std::size_t>(index)];
  if (!spec) {
    std::vector<std::string> names;
    for (const field::OptionSpec& o : opts.kind().options) {
      names.push_back(o.name);
      names.insert(names.end(), o.aliases.begin(), o.aliases.end());
    }
    const std::string best = field::closest_name(option, names);
    in.fail(n.option_range, Diag::UnknownFieldOption, id, opts.kind().name, option,
            best.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", best));
  }
  field::OptionValue value;
  if (!option_value(in, n, id, spec, value)) return;
  try {
    k.fields.set(id, option, std::move(value));
  } catch (const field::FieldError& e) {
    const SourceRange at = in.ast().expr(n.value).range;
    if (e.code() == field::FieldErrc::WrongOptionType)
      in.fail(at, Diag::FieldOptionWrongTypeOf, id, e.option, e.name, option_type_phrase(e.expected),
              option_type_phrase(e.given));
    if (e.code() == field::FieldErrc::BadValue && e.value)
      in.fail(at, Diag::FieldOptionNotIdsOf, id, e.option, e.name, *e.value);
    fail_field_error(in, e, at);
  }
  k.field_option_at[{id, spec->name}] = s.range;
  invalidate_field_cache(in);
}

void exec_field_action(Interpreter& in, const FieldActionStmt& n) {
  const int id = field_id(in, n.id);
  require_field(in, id, n.id, "run an action of");
  // No kind declares a callback (Gmsh's are for views and the GUI), so every
  // action is unknown, as Gmsh reports "Unknown callback".
  in.fail_fmt(n.action_range, Diag::UnknownFieldAction, id, in.kernel().fields.options(id).kind().name,
              in.ast().str(n.action));
}

void exec_delete_field(Interpreter& in, const DeleteFieldStmt& n) {
  const int id = field_id(in, n.id);
  require_field(in, id, n.id, "delete");   // Gmsh: "Cannot delete field id n, it does not exist"
  KernelState& k = in.kernel();
  k.fields.remove(id);
  k.field_defined_at.erase(id);
  for (auto it = k.field_option_at.begin(); it != k.field_option_at.end();)
    it = it->first.first == id ? k.field_option_at.erase(it) : std::next(it);
  invalidate_field_cache(in);
}

void exec_background_field(Interpreter& in, const Stmt& s, const BackgroundFieldStmt& n) {
  if (in.ast().str(n.which) != "Background") {
    // Gmsh 4.8.4 takes one id or a list of them and adds them to its boundary-layer
    // fields; checked when the mesher builds them, as options may still change.
    const Value v = in.eval(n.value);
    if (v.is_string())
      in.fail(in.ast().expr(n.value).range, Diag::TypeBoundaryLayerFieldString);
    KernelState& k = in.kernel();
    for (double x : v.nums()) {
      if (!std::isfinite(x) || std::abs(x) > 2147483647.0)
        in.fail(in.ast().expr(n.value).range, Diag::TypeIdNotInteger, std::string_view("field"), x);
      const int fid = static_cast<int>(x);
      bool seen = false;
      for (const auto& e : k.boundary_layer_fields) seen = seen || e.first == fid;
      if (!seen) k.boundary_layer_fields.emplace_back(fid, s.range);
    }
    return;
  }
  // Checked when the mesher builds it: options may still change after this.
  KernelState& k = in.kernel();
  k.background_field = field_id(in, n.value);
  k.background_field_at = s.range;
}

}  // namespace

void exec_field_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  switch (s.kind()) {
    case StmtKind::FieldNew: exec_field_new(in, s, std::get<FieldNewStmt>(s.node)); break;
    case StmtKind::FieldOption: exec_field_option(in, s, std::get<FieldOptionStmt>(s.node)); break;
    case StmtKind::FieldAction: exec_field_action(in, std::get<FieldActionStmt>(s.node)); break;
    case StmtKind::DeleteField: exec_delete_field(in, std::get<DeleteFieldStmt>(s.node)); break;
    case StmtKind::BackgroundField: exec_background_field(in, s, std::get<BackgroundFieldStmt>(s.node)); break;
    default: SM_ASSERT(false, "kernel/statements.def sent a statement that is not a field statement");
  }
}

}  // namespace sm::interp
