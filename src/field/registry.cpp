// The kind registry, option-name suggestions and the generated reference.
#include "field/registry.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "base/edit_distance.h"
#include "field/error.h"
#include "field/kinds.h"

namespace sm::field {

const std::vector<KindSpec>& kinds() {
  // Built once, immutable afterwards (thread-safe static initialisation).
  static const std::vector<KindSpec> all = [] {
    std::vector<KindSpec> v = {
        ball_kind(),          bathymetry_kind(), boundary_layer_kind(),    box_kind(),
        channel_width_kind(), constant_kind(),   curvature_kind(),         cylinder_kind(),
        distance_kind(),      gradation_kind(),  gradient_kind(),          laplacian_kind(),
        lonlat_kind(),        math_eval_kind(),  max_eigen_hessian_kind(), max_kind(),
        mean_kind(),          min_kind(),        min_aniso_kind(),         param_kind(),
        restrict_kind(),      structured_kind(), threshold_kind(),         time_step_kind(),
    };
    std::sort(v.begin(), v.end(),
              [](const KindSpec& a, const KindSpec& b) { return a.name < b.name; });
    return v;
  }();
  return all;
}

const KindSpec* find_kind(std::string_view name) {
  for (const KindSpec& k : kinds())
    if (k.name == name) return &k;
  // Gmsh 4.8.4 still accepts the deprecated Attractor as a Distance.
  if (name == "Attractor") return find_kind("Distance");
  return nullptr;
}

std::vector<int> referenced_ids(const Options& opts) {
  std::vector<int> ids;
  auto add = [&](double v) {
    const int id = static_cast<int>(v);
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  };
  const KindSpec& kind = opts.kind();
  for (std::size_t i = 0; i < kind.options.size(); ++i) {
    const OptionSpec& o = kind.options[i];
    if (o.role == OptionRole::FieldRef) add(std::get<double>(opts.value(static_cast<int>(i))));
    if (o.role == OptionRole::FieldRefList)
      for (double v : std::get<std::vector<double>>(opts.value(static_cast<int>(i)))) add(v);
  }
  if (kind.extra_refs)
    for (int id : kind.extra_refs(opts)) add(id);
  return ids;
}


std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = static_cast<std::size_t>(-1);
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(name, c, LetterCase::Insensitive);
    if (d < best_d) {  // first of equals wins: candidates come in a fixed order
      best_d = d;
      best = c;
    }
  }
  // A plausible typo changes at most about a third of the letters.
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  return best_d <= limit ? best : std::string();
}

FieldPtr BuildInputs::input(std::string_view option) const {
  return field(static_cast<int>(opts.number(option)), option);
}

std::vector<std::pair<int, FieldPtr>> BuildInputs::inputs(std::string_view option) const {
  std::vector<std::pair<int, FieldPtr>> out;
  for (double v : opts.list(option)) {
    const int ref = static_cast<int>(v);
    out.emplace_back(ref, field(ref, option));
  }
  return out;
}

std::filesystem::path BuildInputs::path(const std::string& file) const {
  std::filesystem::path p(file);
  if (p.is_relative() && !ctx.base_dir.empty()) p = ctx.base_dir / p;
  return p;
}

void BuildInputs::bad(std::string_view option, const std::string& why) const {
  FieldError e(FieldErrc::BadValue,
               fmt::format("Field[{}] ({}): option '{}': {}", id, opts.kind().name, option, why));
  e.field_id = id;
  e.option = std::string(option);
  e.name = opts.kind().name;
  e.reason = why;
  throw e;
}

namespace {

std::string format_value(const OptionValue& v) {
  if (const double* d = std::get_if<double>(&v)) {
    if (*d == kMaxLc) return "1e22 (MAX_LC)";
    if (*d == -kMaxLc) return "-1e22";
    return fmt::format("{:g}", *d);
  }
  if (const std::string* s = std::get_if<std::string>(&v)) return fmt::format("\"{}\"", *s);
  const auto& l = std::get<std::vector<double>>(v);
  std::string out = "{";
  for (std::size_t i = 0; i < l.size(); ++i) out += fmt::format("{}{:g}", i ? ", " : "", l[i]);
  return out + "}";
}

const char* type_word(const OptionSpec& o) {
  if (o.role == OptionRole::FieldRef) return "field id";
  if (o.role == OptionRole::FieldRefList) return "list of field ids";
  switch (o.type) {
    case OptionType::Number: return "number";
    case OptionType::String: return "string";
    case OptionType::List: return "list";
  }
  return "?";
}

}  // namespace

std::string registry_markdown() {
  std::string md;
  md += "Field kinds (`Field[n] = Kind;`, then `Field[n].Option = value;`). Sizes are\n";
  md += "evaluated at 3D points; 1e22 (MAX_LC) means \"no constraint\".\n\n";
  for (const KindSpec& k : kinds()) {
    md += fmt::format("### {}\n\n{}\n\n", k.name, k.help);
    if (k.options.empty()) continue;
    md += "| option | type | default | aliases | description |\n|---|---|---|---|---|\n";
    for (const OptionSpec& o : k.options) {
      std::string aliases;
      for (const std::string& a : o.aliases) aliases += (aliases.empty() ? "" : ", ") + a;
      md += fmt::format("| `{}` | {} | {} | {} | {} |\n", o.name, type_word(o),
                        format_value(o.def), aliases, o.help);
    }
    md += "\n";
  }
  return md;
}

}  // namespace sm::field
