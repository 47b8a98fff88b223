// The field kinds: each declares its name, options and a factory. The
// interpreter, `stereomesh --help-fields` and docs/fields.md all read this.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/progress.h"
#include "base/vec.h"
#include "field/coast_chain.h"
#include "field/field.h"
#include "field/options.h"

namespace sm::field {

/// What fields need from the model, as plain data and callbacks (the
/// geometry module stays out of this module). An unset callback, or one that
/// returns nullopt, means "no such entity": the field fails with BadValue.
struct BuildContext {
  double bbox_diag = 1;  ///< model bounding-box diagonal (defaults of Delta, ...)
  /// Position of model point `tag`, or nullopt if there is none.
  std::function<std::optional<Vec3>(int tag)> point_position;
  /// Distance samples of curve `tag` given NumPointsPerCurve `n` (Gmsh: its
  /// interior mesh nodes plus uniform-parameter points, no end points).
  std::function<std::optional<std::vector<Vec3>>(int tag, int n)> curve_samples;
  /// Point cloud of surface `tag` with spacing about bbox_diag / n.
  std::function<std::optional<std::vector<Vec3>>(int tag, int n)> surface_samples;
  /// The listed curves (signed tags) sampled and chained into rings along the
  /// model's curve loops (ChannelWidth); nullopt if a curve does not exist.
  std::function<std::optional<std::vector<CoastChain>>(const std::vector<int>& curves)> curve_chains;
  /// The curve tags imported by Coastline[id]; nullopt if it is not imported.
  std::function<std::optional<std::vector<int>>(int id)> coastline_curves;
  /// Relative data file names (Structured, Bathymetry) resolve against this.
  std::filesystem::path base_dir;
  /// Threads a factory may use for its set-up (General.NumThreads; <= 0: the hardware's);
  /// the field built does not depend on it (ChannelWidth's searches).
  int threads = 1;
  /// Told of each kind's set-up as a stage "field <Kind>" (the run's time account); may be
  /// null.
  Progress* setup_clock = nullptr;
  /// Where Gmsh is lenient (a Distance field listing a point or curve that does not
  /// exist: Gmsh skips it), a factory that finds this set calls it with its field id, the
  /// option, the entity's kind ("Point", "Curve") and tag, and goes on; without it, that is
  /// an error. The interpreter words each as a gmsh-compat warning.
  std::function<void(int field_id, std::string_view option, std::string_view entity, int tag)> compat_note;
};

using FieldPtr = std::shared_ptr<const SizeField>;

/// Everything a factory sees: its id, options, context, and a resolver for
/// the fields it references (built first, cycles already ruled out).
struct BuildInputs {
  int id = -1;
  const Options& opts;
  const BuildContext& ctx;
  std::function<FieldPtr(int ref_id, std::string_view option)> field;

  /// Resolves a FieldRef option.
  FieldPtr input(std::string_view option) const;
  /// Resolves a FieldRefList option, in list order.
  std::vector<std::pair<int, FieldPtr>> inputs(std::string_view option) const;
  /// `file` resolved against ctx.base_dir when relative.
  std::filesystem::path path(const std::string& file) const;
  /// A BadValue error naming this field and option.
  [[noreturn]] void bad(std::string_view option, const std::string& why) const;
};

struct KindSpec {
  std::string name;
  std::string help;
  std::vector<OptionSpec> options;
  FieldPtr (*make)(const BuildInputs&) = nullptr;
  /// Field ids referenced beyond FieldRef/FieldRefList options (MathEval's F<n>).
  std::vector<int> (*extra_refs)(const Options&) = nullptr;
};

/// All kinds, sorted by name.
const std::vector<KindSpec>& kinds();
/// Exact (case-sensitive, as Gmsh) lookup; nullptr if unknown.
const KindSpec* find_kind(std::string_view name);
/// The field ids `opts` references, in option order (duplicates removed).
std::vector<int> referenced_ids(const Options& opts);
/// The candidate closest to `name` by edit distance (case-insensitive), or
/// "" when none is close enough to be a plausible typo.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);
/// Markdown reference of every kind and option (docs/fields.md, --help-fields).
std::string registry_markdown();

}  // namespace sm::field
