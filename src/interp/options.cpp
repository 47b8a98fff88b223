// Option registry (see options.h). Validation ranges come from the option help
// texts of the Gmsh 4.8.4 manual; Gmsh itself stores any value, we refuse
// values no algorithm understands (documented in docs/interpreter.md).
#include "interp/options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "base/check.h"
#include "interp/node_data_names.h"
#include "io/picture.h"

namespace sm::interp {
namespace {

const std::vector<OptionInfo>& build_table() {
  static const std::vector<OptionInfo> table = {
#define OPT(kind, name, def, ro, help) OptionInfo{OptionKind::kind, name, def, ro, help},
#include "interp/options_table.def"
#include "interp/options_native.def"
#undef OPT
  };
  return table;
}

// Sorted copy of the names with their table index, for binary search.
struct NameIndex {
  std::vector<std::pair<std::string_view, std::size_t>> entries;
  NameIndex() {
    const auto& t = build_table();
    // A name that is an alias names its canonical option, even where the manual also
    // lists it on its own (Mesh.MinimumElementsPerTwoPi, a second name of
    // Mesh.MeshSizeFromCurvature in 4.8.4).
    const auto is_alias = [](std::string_view name) {
      for (const auto& a : Options::aliases())
        if (a.first == name) return true;
      return false;
    };
    for (std::size_t i = 0; i < t.size(); ++i)
      if (!is_alias(t[i].name)) entries.emplace_back(t[i].name, i);
    for (const auto& [alias, canon] : Options::aliases()) {
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i].name == canon) entries.emplace_back(alias, i);
    }
    std::sort(entries.begin(), entries.end());
  }
  std::size_t find(std::string_view name) const {
    auto it = std::lower_bound(entries.begin(), entries.end(), name,
                               [](const auto& e, std::string_view n) { return e.first < n; });
    return (it != entries.end() && it->first == name) ? it->second : kNotFound;
  }
  static constexpr std::size_t kNotFound = static_cast<std::size_t>(-1);
};

const NameIndex& name_index() {
  static const NameIndex index;
  return index;
}

Color parse_color(std::string_view text) {
  Color c{0, 0, 0, 255};
  std::size_t k = 0, pos = 0;
  while (k < 4 && pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    c[k++] = std::atof(std::string(text.substr(pos, comma - pos)).c_str());
    pos = comma + 1;
  }
  return c;
}

// What set_number accepts for an option (options_checks.def): one of `allowed`, or
// min <= v <= max (min < v when strict).
struct ValueCheck {
  std::string_view name;
  std::vector<double> allowed;
  double min = 0;
  bool strict = false;
  double max = 0;
  bool whole = false;
};
constexpr double kNoMax = std::numeric_limits<double>::infinity();
const std::vector<ValueCheck>& value_checks() {
  static const std::vector<ValueCheck> c = {
#define CHOICE(name, ...) ValueCheck{name, {__VA_ARGS__}, 0, false, 0},
#define RANGE(name, lo, strict_lo, hi) ValueCheck{name, {}, lo, strict_lo, hi},
#define WHOLE(name, lo, hi) ValueCheck{name, {}, lo, false, hi, true},
#include "interp/options_checks.def"
#undef WHOLE
#undef RANGE
#undef CHOICE
  };
  return c;
}

std::string_view kind_name(OptionKind k) {
  switch (k) {
    case OptionKind::Number: return "number";
    case OptionKind::String: return "string";
    case OptionKind::Color: return "color";
    case OptionKind::Box: return "box {W, E, S, N}";
  }
  return "?";
}

}  // namespace

const std::vector<OptionInfo>& Options::table() { return build_table(); }

const std::vector<std::pair<std::string_view, std::string_view>>& Options::aliases() {
  // Gmsh 4.8.4 keeps the pre-4.7 names working as aliases of the MeshSize*
  // options; the ocean benchmarks still use them.
  static const std::vector<std::pair<std::string_view, std::string_view>> a = {
      {"Mesh.CharacteristicLengthMin", "Mesh.MeshSizeMin"},
      {"Mesh.CharacteristicLengthMax", "Mesh.MeshSizeMax"},
      {"Mesh.CharacteristicLengthFactor", "Mesh.MeshSizeFactor"},
      {"Mesh.CharacteristicLengthFromPoints", "Mesh.MeshSizeFromPoints"},
      {"Mesh.CharacteristicLengthFromCurvature", "Mesh.MeshSizeFromCurvature"},
      {"Mesh.CharacteristicLengthFromParametricPoints", "Mesh.MeshSizeFromParametricPoints"},
      {"Mesh.CharacteristicLengthExtendFromBoundary", "Mesh.MeshSizeExtendFromBoundary"},
      // 4.8.4's deprecated names of the same settings (DefaultOptions.h: one variable each).
      {"Mesh.MinimumCirclePoints", "Mesh.MinimumCircleNodes"},
      {"Mesh.MinimumCurvePoints", "Mesh.MinimumCurveNodes"},
      {"Mesh.MinimumElementsPerTwoPi", "Mesh.MeshSizeFromCurvature"},
      // Pre-4.0 "Line"/"Numbers" names that 4.8.4 still accepts (t4.geo uses
      // Geometry.DoubleClickedLineCommand); checked with gmsh -0.
      {"Geometry.DoubleClickedLineCommand", "Geometry.DoubleClickedCurveCommand"},
      {"Geometry.Lines", "Geometry.Curves"},
      {"Geometry.LineSelectWidth", "Geometry.CurveSelectWidth"},
      {"Geometry.LineType", "Geometry.CurveType"},
      {"Geometry.LineWidth", "Geometry.CurveWidth"},
      {"Geometry.Color.Lines", "Geometry.Color.Curves"},
      {"Geometry.PointNumbers", "Geometry.PointLabels"},
      {"Geometry.LineNumbers", "Geometry.CurveLabels"},
      {"Geometry.SurfaceNumbers", "Geometry.SurfaceLabels"},
      {"Geometry.VolumeNumbers", "Geometry.VolumeLabels"},
      {"Mesh.PointNumbers", "Mesh.NodeLabels"},
      {"Mesh.LineNumbers", "Mesh.LineLabels"},
      {"Mesh.SurfaceNumbers", "Mesh.SurfaceLabels"},
      {"Mesh.VolumeNumbers", "Mesh.VolumeLabels"},
      {"Mesh.Points", "Mesh.Nodes"},
      {"Mesh.PointSize", "Mesh.NodeSize"},
      {"Mesh.PointType", "Mesh.NodeType"},
      {"Mesh.Color.Points", "Mesh.Color.Nodes"},   // t3.geo sets it; gmsh -0 accepts it
      {"Mesh.Color.PointsSup", "Mesh.Color.NodesSup"},
  };
  return a;
}

Options::Options() { reset(); }

void Options::reset() {
  const auto& t = table();
  nums_.assign(t.size(), 0.0);
  strs_.assign(t.size(), std::string());
  colors_.assign(t.size(), Color{0, 0, 0, 255});
  boxes_.assign(t.size(), LonLatBox{0, 0, 0, 0});
  set_.assign(t.size(), false);
  for (std::size_t i = 0; i < t.size(); ++i) {
    switch (t[i].kind) {
      case OptionKind::Number: nums_[i] = std::atof(std::string(t[i].default_text).c_str()); break;
      case OptionKind::String: strs_[i] = std::string(t[i].default_text); break;
      case OptionKind::Color: colors_[i] = parse_color(t[i].default_text); break;
      case OptionKind::Box: break;   // all 0: no box
    }
  }
}

const OptionInfo* Options::find(std::string_view name) const {
  const std::size_t i = name_index().find(name);
  return i == NameIndex::kNotFound ? nullptr : &table()[i];
}

std::string Options::closest(std::string_view name) const {
  std::string_view best;
  std::size_t best_d = static_cast<std::size_t>(-1);
  for (const auto& [n, i] : name_index().entries) {
    const std::size_t d = edit_distance(name, n);
    if (d < best_d) {
      best_d = d;
      best = n;
    }
  }
  return std::string(best);
}

std::size_t Options::index_of(std::string_view name, OptionKind kind) const {
  const std::size_t i = name_index().find(name);
  SM_ASSERT(i != NameIndex::kNotFound && table()[i].kind == kind, "unknown option or wrong kind");
  return i;
}

double Options::number(std::string_view name) const { return nums_[index_of(name, OptionKind::Number)]; }
const std::string& Options::string(std::string_view name) const {
  return strs_[index_of(name, OptionKind::String)];
}
const Color& Options::color(std::string_view name) const {
  return colors_[index_of(name, OptionKind::Color)];
}

const LonLatBox& Options::box(std::string_view name) const { return boxes_[index_of(name, OptionKind::Box)]; }

bool Options::was_set(std::string_view name) const {
  const std::size_t i = name_index().find(name);
  SM_ASSERT(i != NameIndex::kNotFound, "unknown option");
  return set_[i];
}

OptionRefusal Options::set_number(std::string_view name, double v, bool internal) {
  const std::size_t i = name_index().find(name);
  if (i == NameIndex::kNotFound) return option_refusal(lang::Diag::OptionNotKnown, name);
  const OptionInfo& info = table()[i];
  if (info.kind != OptionKind::Number)
    return option_refusal(lang::Diag::OptionWrongKind, name, kind_name(info.kind), std::string_view("number"));
  if (info.read_only && !internal) return option_refusal(lang::Diag::OptionReadOnly, name);
  if (!std::isfinite(v)) return option_refusal(lang::Diag::OptionNotFinite, name);
  for (const ValueCheck& c : value_checks()) {
    if (c.name != info.name) continue;
    if (!c.allowed.empty()) {
      if (std::find(c.allowed.begin(), c.allowed.end(), v) != c.allowed.end()) break;
      std::string list;
      for (double a : c.allowed) list += fmt::format("{}{}", list.empty() ? "" : ", ", a);
      return option_refusal(lang::Diag::OptionValueNotAllowed, v, name, list);
    }
    if (c.whole && (v != std::floor(v) || v < c.min || v > c.max))
      return option_refusal(lang::Diag::OptionValueNotWhole, v, name, c.min, c.max);
    if (v < c.min || (c.strict && v == c.min) || v > c.max) {
      const std::string_view bound = c.strict ? ">" : ">=";
      if (c.max == kNoMax) return option_refusal(lang::Diag::OptionValueBelow, v, name, bound, c.min);
      return option_refusal(lang::Diag::OptionValueOutside, v, name, bound, c.min, c.max);
    }
    break;
  }
  nums_[i] = v;
  set_[i] = true;
  return {};
}

OptionRefusal Options::set_string(std::string_view name, std::string v, bool internal) {
  const std::size_t i = name_index().find(name);
  if (i == NameIndex::kNotFound) return option_refusal(lang::Diag::OptionNotKnown, name);
  const OptionInfo& info = table()[i];
  if (info.kind != OptionKind::String)
    return option_refusal(lang::Diag::OptionWrongKind, name, kind_name(info.kind), std::string_view("string"));
  if (info.read_only && !internal) return option_refusal(lang::Diag::OptionReadOnly, name);
  if (name == "Mesh.NodeData") {
    std::string unknown;
    if (split_node_data_names(v, &unknown).empty() && !unknown.empty())
      return option_refusal(lang::Diag::NodeDataUnknownValue, unknown);
  }
  strs_[i] = std::move(v);
  set_[i] = true;
  return {};
}

OptionRefusal Options::set_color(std::string_view name, const Color& c) {
  const std::size_t i = name_index().find(name);
  if (i == NameIndex::kNotFound) return option_refusal(lang::Diag::OptionNotKnown, name);
  const OptionInfo& info = table()[i];
  if (info.kind != OptionKind::Color)
    return option_refusal(lang::Diag::OptionWrongKind, name, kind_name(info.kind), std::string_view("color"));
  for (double x : c)
    if (!(x >= 0 && x <= 255)) return option_refusal(lang::Diag::OptionColorComponents, name);
  colors_[i] = c;
  set_[i] = true;
  return {};
}

OptionRefusal Options::set_box(std::string_view name, const LonLatBox& b) {
  const std::size_t i = name_index().find(name);
  if (i == NameIndex::kNotFound) return option_refusal(lang::Diag::OptionNotKnown, name);
  const OptionInfo& info = table()[i];
  if (info.kind != OptionKind::Box)
    return option_refusal(lang::Diag::OptionWrongKind, name, kind_name(info.kind), std::string_view("box"));
  if (b != LonLatBox{0, 0, 0, 0}) {
    io::PictureBox normalised;
    if (OptionRefusal r = check_picture_box(b, &normalised); !r.empty()) return r;
  }
  boxes_[i] = b;
  set_[i] = true;
  return {};
}

OptionRefusal check_picture_box(const LonLatBox& b, io::PictureBox* out) {
  using lang::Diag;
  const auto [west, east, south, north] = b;
  switch (io::normalise_picture_box(west, east, south, north, out)) {
    case io::PictureBoxProblem::None: break;
    case io::PictureBoxProblem::NotFinite: return option_refusal(Diag::PictureBoxNotFinite);
    case io::PictureBoxProblem::Longitudes: return option_refusal(Diag::PictureBoxLongitudes, west, east);
    case io::PictureBoxProblem::Latitudes: return option_refusal(Diag::PictureBoxLatitudes, south, north);
    case io::PictureBoxProblem::SouthNotBelowNorth: return option_refusal(Diag::PictureBoxSouthNorth, south, north);
    case io::PictureBoxProblem::NoWidth: return option_refusal(Diag::PictureBoxNoWidth, west);
    case io::PictureBoxProblem::TooWide: return option_refusal(Diag::PictureBoxTooWide, west, east);
  }
  return {};
}

bool named_color(std::string_view name, Color& out) {
  struct Named {
    std::string_view name;
    Color c;
  };
  // The common X11 names; Gmsh accepts the whole X11 list.
  static const Named kColors[] = {
      {"Black", {0, 0, 0, 255}},         {"White", {255, 255, 255, 255}},
      {"Red", {255, 0, 0, 255}},         {"Green", {0, 255, 0, 255}},
      {"Blue", {0, 0, 255, 255}},        {"Yellow", {255, 255, 0, 255}},
      {"Cyan", {0, 255, 255, 255}},      {"Magenta", {255, 0, 255, 255}},
      {"Gray", {190, 190, 190, 255}},    {"Grey", {190, 190, 190, 255}},
      {"Orange", {255, 165, 0, 255}},    {"Purple", {160, 32, 240, 255}},
      {"Brown", {165, 42, 42, 255}},     {"Pink", {255, 192, 203, 255}},
      {"Navy", {0, 0, 128, 255}},        {"Maroon", {176, 48, 96, 255}},
      {"Gold", {255, 215, 0, 255}},      {"Orchid", {218, 112, 214, 255}},
      {"LightGray", {211, 211, 211, 255}}, {"DarkGray", {169, 169, 169, 255}},
  };
  for (const auto& n : kColors) {
    if (n.name.size() != name.size()) continue;
    bool eq = true;
    for (std::size_t i = 0; i < name.size() && eq; ++i)
      eq = std::tolower(static_cast<unsigned char>(n.name[i])) ==
           std::tolower(static_cast<unsigned char>(name[i]));
    if (eq) {
      out = n.c;
      return true;
    }
  }
  return false;
}


}  // namespace sm::interp
