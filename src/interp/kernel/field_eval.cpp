// Field builds requested by scripts (FieldValue, FieldArgmin) and by the
// mesher (Background Field), and kernel field errors turned into located
// diagnostics that point at the statements defining the fields involved.
#include "interp/kernel/field_eval.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <set>

#include <fmt/format.h>

#include "field/bathymetry.h"
#include "field/min_max.h"
#include "io/mesh_model.h"
#include "field/size_check.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/field_context.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

/// Built fields by root id, valid for one model state (geo::Model::revision: a
/// FieldValue call in a loop over a 100,000-point coastline costs a lookup, not a walk
/// over the model).
struct FieldCache {
  std::uint64_t model_revision = 0;
  std::map<int, field::BuiltFields> by_root;
};

namespace {

std::string kind_of(Interpreter& in, int id) {
  return in.kernel().fields.contains(id) ? in.kernel().fields.options(id).kind().name : "?";
}

}  // namespace

std::string_view option_type_phrase(field::OptionType t) {
  switch (t) {
    case field::OptionType::Number: return "a number";
    case field::OptionType::String: return "a string";
    case field::OptionType::List: return "a list in braces";
  }
  return "a value";
}

namespace {

/// " (did you mean 'x'?)" after an unknown name, or "".
std::string did_you_mean(const std::string& suggestion) {
  return suggestion.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", suggestion);
}

/// A field error's diagnostic: each field::FieldErrc is reported as the kind of
/// lang/diag_kinds.def that names it, with the values its message's shape takes.
struct FieldDiagnostic {
  Diag kind;
  std::string message;
};

// A BadValue error in the words of its kind (field::BadValueWhat says which value).
FieldDiagnostic bad_value_diagnostic(const field::FieldError& e) {
  const double value = e.value.value_or(0);
  switch (e.bad) {
    case field::BadValueWhat::Option: break;
    case field::BadValueWhat::NotFieldIds:
      return {Diag::FieldOptionNotIds, format_diag(Diag::FieldOptionNotIds, e.option, e.name, value)};
    case field::BadValueWhat::Size: {
      const Vec3 p = e.point.value_or(Vec3{});
      return {Diag::FieldSizeNotPositive,
              format_diag(Diag::FieldSizeNotPositive, e.field_id, e.name, value, p.x, p.y, p.z)};
    }
    case field::BadValueWhat::DistanceSample:
      return {Diag::DistanceSampleNotFinite,
              format_diag(Diag::DistanceSampleNotFinite, static_cast<std::size_t>(value))};
    case field::BadValueWhat::CoastSample:
      return {Diag::ChannelWidthSampleNotFinite, format_diag(Diag::ChannelWidthSampleNotFinite)};
    case field::BadValueWhat::ElementsAcross:
      return {Diag::ChannelWidthElementsAcross, format_diag(Diag::ChannelWidthElementsAcross)};
    case field::BadValueWhat::TooManySamples: {
      const auto limit = static_cast<std::size_t>(value);
      if (e.option == "NumPointsPerCurve")
        return {Diag::CurveSamplesOverLimitNumPoints, format_diag(Diag::CurveSamplesOverLimitNumPoints, limit)};
      return {Diag::CurveSamplesOverLimit, format_diag(Diag::CurveSamplesOverLimit, limit)};
    }
  }
  return {Diag::FieldOptionRefused, format_diag(Diag::FieldOptionRefused, e.field_id, e.name, e.option, e.reason)};
}

FieldDiagnostic field_diagnostic(Interpreter& in, const field::FieldError& e) {
  const int first = e.ids.empty() ? e.field_id : e.ids.front();
  switch (e.code()) {
    case field::FieldErrc::UnknownKind:
      return {Diag::UnknownFieldKind, format_diag<std::string, std::string>(Diag::UnknownFieldKind, e.name,
                                                                            did_you_mean(e.suggestion))};
    case field::FieldErrc::UnknownOption:
      if (e.field_id >= 0)
        return {Diag::UnknownFieldOption,
                format_diag<int, std::string, std::string, std::string>(Diag::UnknownFieldOption, e.field_id, e.name,
                                                                        e.option, did_you_mean(e.suggestion))};
      return {Diag::UnknownKindOption, format_diag<std::string, std::string, std::string>(
                                           Diag::UnknownKindOption, e.option, e.name, did_you_mean(e.suggestion))};
    case field::FieldErrc::DuplicateId:
      return {Diag::DuplicateFieldId, format_diag<int>(Diag::DuplicateFieldId, e.field_id)};
    case field::FieldErrc::MissingField:
      if (e.field_id >= 0 && e.field_id != first)
        return {Diag::MissingFieldReference, format_diag<int, std::string, int>(Diag::MissingFieldReference, e.field_id,
                                                                                kind_of(in, e.field_id), first)};
      return {Diag::MissingField, format_diag<int>(Diag::MissingField, first)};
    case field::FieldErrc::Cycle: {
      std::string loop;
      for (std::size_t i = 0; i < e.ids.size(); ++i) loop += fmt::format("{}Field[{}]", i ? " -> " : "", e.ids[i]);
      return {Diag::FieldCycle, format_diag<std::string>(Diag::FieldCycle, loop)};
    }
    case field::FieldErrc::FileError:
      return {Diag::FieldFileError, format_diag<std::string, std::string>(Diag::FieldFileError, e.file, e.reason)};
    case field::FieldErrc::ParseError:
      return {Diag::FieldExpressionError, format_diag<std::string, int, std::string>(
                                              Diag::FieldExpressionError, e.expression, e.column, e.reason)};
    case field::FieldErrc::WrongOptionType:
      return {Diag::FieldOptionWrongType,
              format_diag<std::string, std::string, std::string_view, std::string_view>(
                  Diag::FieldOptionWrongType, e.option, e.name, option_type_phrase(e.expected),
                  option_type_phrase(e.given))};
    case field::FieldErrc::BadValue: return bad_value_diagnostic(e);
  }
  return bad_value_diagnostic(e);   // not reached: every code is a case
}

// Where option `option` (any spelling) of field `id` was set, if a statement did.
const SourceRange* option_site(Interpreter& in, int id, const std::string& option) {
  KernelState& k = in.kernel();
  if (!k.fields.contains(id) || option.empty()) return nullptr;
  const field::Options& o = k.fields.options(id);
  const int i = o.find(option);
  if (i < 0) return nullptr;
  auto it = k.field_option_at.find({id, o.kind().options[static_cast<std::size_t>(i)].name});
  return it == k.field_option_at.end() ? nullptr : &it->second;
}

// The option statement of field `id` that references field `ref`, if any.
const SourceRange* reference_site(Interpreter& in, int id, int ref) {
  KernelState& k = in.kernel();
  if (!k.fields.contains(id)) return nullptr;
  const field::Options& o = k.fields.options(id);
  const auto& specs = o.kind().options;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const field::OptionSpec& s = specs[i];
    bool refers = false;
    if (s.role == field::OptionRole::FieldRef) {
      refers = static_cast<int>(std::get<double>(o.value(static_cast<int>(i)))) == ref;
    } else if (s.role == field::OptionRole::FieldRefList) {
      for (double v : std::get<std::vector<double>>(o.value(static_cast<int>(i))))
        refers = refers || static_cast<int>(v) == ref;
    } else if (s.type == field::OptionType::Number && o.kind().extra_refs) {
      // A plain number naming a field only when set (TimeStep's DepthField).
      refers = static_cast<int>(std::get<double>(o.value(static_cast<int>(i)))) == ref;
    } else if (s.type == field::OptionType::String && o.kind().extra_refs) {
      refers = true;   // MathEval's F<n> live in its expression strings
    }
    if (!refers) continue;
    auto it = k.field_option_at.find({id, s.name});
    if (it != k.field_option_at.end()) return &it->second;
  }
  return nullptr;
}

void add_definition_note(Interpreter& in, int id, std::vector<DiagNote>& notes) {
  auto it = in.kernel().field_defined_at.find(id);
  if (it != in.kernel().field_defined_at.end())
    notes.push_back({it->second, fmt::format("Field[{}] ({}) is defined here", id, kind_of(in, id))});
}

// A MathEx syntax error inside a plain string literal (`F = "x +* 2";`):
// the column of the expression becomes a column of the script.
SourceRange expression_column(Interpreter& in, const field::FieldError& e, SourceRange stmt) {
  if (e.column < 1 || !in.kernel().fields.contains(e.field_id)) return stmt;
  const field::Options& o = in.kernel().fields.options(e.field_id);
  const int i = o.find(e.option);
  if (i < 0) return stmt;
  const auto* expr = std::get_if<std::string>(&o.value(i));
  const std::string_view t = in.text_of(stmt);
  const std::size_t eq = t.find('=');
  const std::size_t quote = eq == std::string_view::npos ? eq : t.find('"', eq);
  if (!expr || quote == std::string_view::npos || t.substr(quote + 1, expr->size()) != *expr ||
      t.substr(quote + 1 + expr->size(), 1) != "\"")
    return stmt;   // built by Sprintf or StrCat: no column of its own
  SourceRange r = stmt;
  r.begin = stmt.begin + static_cast<std::uint32_t>(quote + static_cast<std::size_t>(e.column));
  r.end = r.begin + 1;
  return r;
}

// Builds and evaluations recurse once per reference level, so a hostile chain
// (Field[i].InField = i - 1 for 200000 fields) would overflow the stack: the
// depth is measured here first, without recursion. Cycles and missing ids are
// left to the build, which reports them with their ids.
constexpr int kMaxFieldDepth = 1000;

void check_reference_depth(Interpreter& in, int root, SourceRange use) {
  const field::FieldSet& set = in.kernel().fields;
  std::map<int, int> depth;   // finished fields: longest reference chain below
  std::set<int> open;
  struct Item {
    int id;
    std::vector<int> refs;
    std::size_t next = 0;
  };
  std::vector<Item> stack;
  auto push = [&](int id) {
    std::vector<int> refs;
    try {
      refs = field::referenced_ids(set.options(id));
    } catch (const field::FieldError&) {
      // A MathEval syntax error: the build reports it where it belongs.
    }
    open.insert(id);
    stack.push_back({id, std::move(refs)});
    if (static_cast<int>(stack.size()) > kMaxFieldDepth)
      in.fail(use, Diag::LimitFieldNestingPath, root, kMaxFieldDepth, stack[0].id, stack[1].id);
  };
  if (!set.contains(root)) return;
  push(root);
  while (!stack.empty()) {
    Item& top = stack.back();
    if (top.next < top.refs.size()) {
      const int ref = top.refs[top.next++];
      if (set.contains(ref) && !depth.count(ref) && !open.count(ref)) push(ref);
      continue;
    }
    int d = 0;
    for (int ref : top.refs) {
      auto it = depth.find(ref);
      if (it != depth.end()) d = std::max(d, it->second + 1);
    }
    if (d >= kMaxFieldDepth)
      in.fail(use, Diag::LimitFieldNesting, root, kMaxFieldDepth);
    depth[top.id] = d;
    open.erase(top.id);
    stack.pop_back();
  }
}

}  // namespace

void fail_field_error(Interpreter& in, const field::FieldError& e, SourceRange at) {
  FieldDiagnostic d = field_diagnostic(in, e);
  std::string& message = d.message;
  std::vector<DiagNote> notes;
  SourceRange where = at;
  switch (e.code()) {
    case field::FieldErrc::Cycle: {
      // Each link of the loop: the option that makes Field[a] read Field[b].
      for (std::size_t i = 0; i + 1 < e.ids.size(); ++i) {
        const int a = e.ids[i], b = e.ids[i + 1];
        if (const SourceRange* r = reference_site(in, a, b))
          notes.push_back({*r, fmt::format("Field[{}] ({}) reads Field[{}] here", a, kind_of(in, a), b)});
        else
          add_definition_note(in, a, notes);
      }
      break;
    }
    case field::FieldErrc::MissingField: {
      const int missing = e.ids.empty() ? -1 : e.ids.front();
      if (e.field_id >= 0 && e.field_id != missing) {
        if (const SourceRange* r = reference_site(in, e.field_id, missing))
          notes.push_back({*r, fmt::format("Field[{}] refers to Field[{}] here", e.field_id, missing)});
        else
          add_definition_note(in, e.field_id, notes);
      }
      break;
    }
    default: {
      // A size the mesher met at a point: where on the sphere, when the model has one.
      if (e.point && !in.kernel().model.geometries().empty()) {
        const geo::SurfaceGeometry& g = in.kernel().model.geometries().begin()->second;
        geo::LonLat ll;
        if (g.polar()) {
          ll = g.polar()->to_lonlat(*e.point);
        } else {
          const Vec2 p = g.param(*e.point);
          ll = {p.x * geo::kRadToDeg, p.y * geo::kRadToDeg};
        }
        message += fmt::format(" (lon {:.6f}, lat {:.6f})", ll.lon, ll.lat);
      }
      // A bad value is best shown where it was set; the use comes as a note.
      if (const SourceRange* r = option_site(in, e.field_id, e.option)) {
        where = *r;
        if (e.code() == field::FieldErrc::ParseError) where = expression_column(in, e, where);
      } else {
        auto it = in.kernel().field_defined_at.find(e.field_id);
        if (it != in.kernel().field_defined_at.end()) where = it->second;
      }
      if (at.valid() && (where.begin != at.begin || where.file.value != at.file.value))
        notes.push_back({at, "the field is built for this use"});
      break;
    }
  }
  try {
    in.fail_message(where, d.kind, std::move(message));
  } catch (RuntimeError& err) {
    err.notes.insert(err.notes.begin(), notes.begin(), notes.end());
    throw;
  }
}

void invalidate_field_cache(Interpreter& in) { in.kernel().field_cache.reset(); }

field::BuildContext kernel_build_context(const KernelState& k, const CurveMeshNodes* mesh_nodes) {
  field::BuildContext ctx = make_build_context(k.model, {}, mesh_nodes);
  ctx.setup_clock = &k.clock;
  const KernelState* state = &k;
  ctx.coastline_curves = [state](int id) { return coastline_curves(*state, id); };
  return ctx;
}

namespace {

// The build context of the interpreter's fields: their gmsh-compat notes become warnings at
// the option statement they name (else at `use`), each once.
field::BuildContext interp_build_context(Interpreter& in, const CurveMeshNodes* mesh_nodes, SourceRange use) {
  field::BuildContext ctx = kernel_build_context(in.kernel(), mesh_nodes);
  ctx.threads = static_cast<int>(in.options().number("General.NumThreads"));
  Interpreter* interp = &in;
  ctx.compat_note = [interp, use](int id, std::string_view option, std::string_view entity, int tag) {
    KernelState& k = interp->kernel();
    if (!k.field_compat_reported.insert(fmt::format("{} {} {} {}", id, option, entity, tag)).second) return;
    auto it = k.field_option_at.find({id, std::string(option)});
    interp->diags().report(it != k.field_option_at.end() ? it->second : use, Diag::GmshCompatFieldMissing, id, option,
                           entity, tag);
  };
  return ctx;
}

}  // namespace

const field::BuiltFields& built_fields(Interpreter& in, int root, SourceRange use) {
  KernelState& k = in.kernel();
  const std::uint64_t revision = k.model.revision();
  if (!k.field_cache || k.field_cache->model_revision != revision) {
    k.field_cache = std::make_shared<FieldCache>();
    k.field_cache->model_revision = revision;
  }
  auto it = k.field_cache->by_root.find(root);
  if (it != k.field_cache->by_root.end()) return it->second;
  if (!k.fields.contains(root)) in.fail(use, Diag::MissingField, root);
  check_reference_depth(in, root, use);
  try {
    const StageScope stage(&k.clock, nullptr, "fields");
    field::BuildContext ctx = interp_build_context(in, nullptr, use);
    return k.field_cache->by_root.emplace(root, k.fields.build(root, ctx)).first->second;
  } catch (const field::FieldError& e) {
    fail_field_error(in, e, use);
  }
}

field::FieldPtr background_size_field(Interpreter& in, const CurveMeshNodes* mesh_nodes) {
  KernelState& k = in.kernel();
  if (!k.background_field || *k.background_field <= 0) return nullptr;
  const int id = *k.background_field;
  if (!k.fields.contains(id)) {
    try {
      in.fail(k.background_field_at, Diag::MissingBackgroundField, id);
    } catch (RuntimeError& err) {
      if (!k.fields.ids().empty())
        err.notes.insert(err.notes.begin(),
                         DiagNote{SourceRange{}, fmt::format("defined fields: {}", fmt::join(k.fields.ids(), ", "))});
      throw;
    }
  }
  // The mesher gets the field behind a check of every size it returns (meshing code
  // that catches the FieldError reports it with fail_field_error at the Background
  // Field statement).
  if (!mesh_nodes)
    return field::checked_size_field(built_fields(in, id, k.background_field_at).shared(id), id, kind_of(in, id));
  check_reference_depth(in, id, k.background_field_at);
  try {
    const StageScope stage(&k.clock, nullptr, "fields");
    return field::checked_size_field(
        k.fields.build(id, interp_build_context(in, mesh_nodes, k.background_field_at)).shared(id), id,
        kind_of(in, id));
  } catch (const field::FieldError& e) {
    fail_field_error(in, e, k.background_field_at);
  }
}

namespace {

struct FieldCallArgs {
  int id = 0;
  Vec3 p;
  std::optional<field::EntityRef> on;
};

FieldCallArgs field_call_args(Interpreter& in, const CallExpr& c, std::string_view fname) {
  if (c.args.size() != 4 && c.args.size() != 6)
    in.fail_fmt(c.func_range, Diag::WrongArgumentCount, fname, "4 or 6", "s", c.args.size());
  double v[6] = {0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < c.args.size(); ++i) {
    v[i] = in.eval_number(c.args[i]);
    if (!std::isfinite(v[i]))
      in.fail_fmt(in.ast().expr(c.args[i]).range, Diag::BuiltinFailed, fname,
                  fmt::format("argument {} is not finite", i + 1));
  }
  auto as_int = [&](std::size_t i) {
    if (std::abs(v[i]) > 2e9 || v[i] != std::trunc(v[i]))
      in.fail_fmt(in.ast().expr(c.args[i]).range, Diag::BuiltinFailed, fname,
                  fmt::format("argument {} must be an integer, not {}", i + 1, v[i]));
    return static_cast<int>(v[i]);
  };
  FieldCallArgs out;
  out.id = as_int(0);
  out.p = Vec3{v[1], v[2], v[3]};
  if (c.args.size() == 6) {
    const int dim = as_int(4);
    if (dim < 0 || dim > 3)
      in.fail_fmt(in.ast().expr(c.args[4]).range, Diag::BuiltinFailed, fname,
                  fmt::format("the entity dimension must be 0 to 3, not {}", dim));
    out.on = field::EntityRef{dim, as_int(5)};
  }
  return out;
}

}  // namespace

Value eval_field_call(Interpreter& in, const Expr& e, const CallExpr& c) {
  const std::string_view fname = in.ast().str(c.func);
  const bool value = c.fn == BuiltinId::FieldValue;   // else FieldArgmin
  const FieldCallArgs a = field_call_args(in, c, fname);
  const field::BuiltFields& built = built_fields(in, a.id, e.range);
  const field::SizeField& f = *built.get(a.id);
  double h = 0;
  const field::EntityRef* on = a.on ? &*a.on : nullptr;
  if (value) {
    field::eval_input(f, on, std::span<const Vec3>(&a.p, 1), std::span<double>(&h, 1));
    return Value::number(h);
  }
  int which = -1;
  if (!field::eval_argmin(f, on, std::span<const Vec3>(&a.p, 1), std::span<double>(&h, 1),
                          std::span<int>(&which, 1)))
    in.fail_fmt(in.ast().expr(c.args[0]).range, Diag::BuiltinFailed, fname,
                fmt::format("Field[{}] is a {} field, not a Min", a.id, kind_of(in, a.id)));
  return Value::number(which);
}

OptionRefusal depth_at(Interpreter& in, const io::MeshModel& mm, std::vector<double>& depth) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  if (in.options().number("Mesh.DepthSampling") == 1)
    for (const io::EntityMesh& e : mm.entities) {
      if (e.dim != 2 || (e.type != io::ElementType::Triangle3 && e.type != io::ElementType::Quad4)) continue;
      const std::size_t n = static_cast<std::size_t>(io::nodes_per_element(e.type));
      for (std::size_t b = 0; b + n <= e.connectivity.size(); b += n)
        for (std::size_t c = 0; c < n; ++c) edges.push_back({e.connectivity[b + c], e.connectivity[b + (c + 1) % n]});
    }
  return depth_at(in, mm.xyz, edges, depth);
}

OptionRefusal check_depth_sampling(Interpreter& in, const field::SizeField& depth) {
  if (in.options().number("Mesh.DepthSampling") == 0 || dynamic_cast<const field::GridDepthField*>(&depth)) return {};
  return option_refusal(Diag::DepthSamplingNeedsGrid);
}

OptionRefusal depth_at(Interpreter& in, std::span<const Vec3> xyz,
                       const std::vector<std::array<std::uint32_t, 2>>& edges, std::vector<double>& depth,
                       std::optional<field::DepthClampReport>* report) {
  const KernelState& k = in.kernel();
  const int id = static_cast<int>(in.options().number("Mesh.DepthField"));
  const auto at = k.option_set_at.find("Mesh.DepthField");
  const field::SizeField* f = built_fields(in, id, at != k.option_set_at.end() ? at->second : SourceRange{}).get(id);
  if (!f) return option_refusal(Diag::DepthFieldNoSuchField, id);
  if (OptionRefusal r = check_depth_sampling(in, *f); !r.empty()) return r;
  depth.resize(xyz.size());
  const auto* grid = dynamic_cast<const field::GridDepthField*>(f);
  if (!grid) {
    f->eval(xyz, depth);
    return {};
  }
  std::vector<double> half;
  if (in.options().number("Mesh.DepthSampling") == 1) half = field::half_edge_angles(xyz, edges);
  field::DepthClampReport r;
  grid->node_depths(xyz, half, depth, &r);
  if (report) *report = r;
  return {};
}

}  // namespace sm::interp
