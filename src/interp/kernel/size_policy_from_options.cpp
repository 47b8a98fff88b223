// Mesh.MeshSize{Factor,Min,Max,FromPoints,ExtendFromBoundary,FromCurvature} ->
// field::SizePolicyOptions. Each CharacteristicLength* alias shares its option's
// slot in the registry, so reading the current names sees either spelling.
// Mesh.ElementsAcrossChannels -> field/channel_width.h on the coastlines' surfaces.
#include "interp/kernel/size_policy_from_options.h"

#include <algorithm>
#include <array>
#include <set>
#include <string_view>

#include <fmt/format.h>

#include "base/check.h"
#include "coast/coastline_option_id.h"
#include "field/channel_width.h"
#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/field_eval.h"

namespace sm::interp {

field::SizePolicyOptions size_policy_from_options(const Options& options) {
  static constexpr std::array<std::string_view, 6> kNames = {
      "Mesh.MeshSizeFactor",   "Mesh.MeshSizeMin",
      "Mesh.MeshSizeMax",      "Mesh.MeshSizeFromPoints",
      "Mesh.MeshSizeExtendFromBoundary", "Mesh.MeshSizeFromCurvature"};
  field::SizePolicyOptions out;
  for (std::string_view name : kNames) {
    const bool known = field::set_size_option(out, name, options.number(name));
    SM_ASSERT(known, "size option missing from field::set_size_option");
  }
  return out;
}

OptionRefusal check_elements_across_channels(const Options& options) {
  const double n = options.number("Mesh.ElementsAcrossChannels");
  if (n > 0 && n < 1) return option_refusal(lang::Diag::ElementsAcrossChannelsBelowOne, n);
  return {};
}

field::FieldPtr with_channel_sizes(Interpreter& in, field::FieldPtr background) {
  const Options& o = in.options();
  const double n = o.number("Mesh.ElementsAcrossChannels");
  if (!(n >= 1)) return background;
  const KernelState& k = in.kernel();
  // The coast curves, and the smallest accuracy gamma at their control points. A channel
  // narrower than gamma is not in the coast as drawn (the coarsening moved the shore by up
  // to gamma), so the criterion never asks for elements smaller than that: without this
  // floor the straits of metres the data keeps open refine the world ocean's mesh at no
  // gain in fidelity.
  std::vector<int> coast;
  double gamma_floor = field::kMaxLc;
  for (const auto& [id, def] : k.coastlines) {
    const auto own = coastline_curves(k, id);
    if (!own) continue;
    coast.insert(coast.end(), own->begin(), own->end());
    const std::string_view accuracy = coast::coast_option_name(coast::CoastOpt::AccuracyField);
    const auto f = def.options.find(accuracy);
    const auto at = def.option_at.find(accuracy);
    if (f == def.options.end() || f->second.nums().empty() || at == def.option_at.end()) continue;
    std::vector<Vec3> pts;
    for (int c : *own)
      if (const geo::ModelCurve* mc = k.model.curve(std::abs(c)))
        for (int v : mc->points)
          if (const geo::ModelVertex* mv = k.model.vertex(v)) pts.push_back(mv->xyz);
    const int field_id = static_cast<int>(f->second.nums().front());
    const field::FieldPtr gamma = built_fields(in, field_id, at->second).shared(field_id);
    std::vector<double> g(pts.size());
    field::eval_input(*gamma, nullptr, pts, g);
    for (double v : g)
      if (v > 0) gamma_floor = std::min(gamma_floor, v);
  }
  if (coast.empty()) return background;
  const std::set<int> coast_set = [&] {
    std::set<int> s;
    for (int c : coast) s.insert(std::abs(c));
    return s;
  }();
  // The surfaces with a coast curve in a loop, and every curve of their loops (open
  // boundaries crossing a strait are sized by it too).
  std::set<int> surfaces, curves = coast_set;
  for (const auto& [tag, s] : k.model.surfaces()) {
    bool bounded = false;
    std::vector<int> own;
    for (int l : s.loops)
      if (const geo::ModelCurveLoop* loop = k.model.curve_loop(std::abs(l)))
        for (int c : loop->curves) {
          own.push_back(std::abs(c));
          bounded = bounded || coast_set.count(std::abs(c)) > 0;
        }
    if (!bounded) continue;
    surfaces.insert(tag);
    curves.insert(own.begin(), own.end());
  }
  // Its set-up (the chains along every coast, their widths) is this kind's stage.
  const StageScope stage(&k.clock, nullptr, "field ChannelWidth");
  const field::BuildContext ctx = kernel_build_context(k, nullptr);
  std::optional<std::vector<field::CoastChain>> chains = ctx.curve_chains(coast);
  if (!chains) return background;   // a coastline's curve was deleted since the import
  field::ChannelWidthOptions opts;
  opts.elements_across = n;
  opts.size_min = std::max(o.number("Mesh.MeshSizeMin"), gamma_floor < field::kMaxLc ? gamma_floor : 0.0);
  opts.size_max = o.number("Mesh.MeshSizeMax");
  opts.threads = static_cast<int>(o.number("General.NumThreads"));
  auto channels = field::make_channel_width_field(std::move(*chains), opts);
  return field::min_on_entities(std::move(background), std::move(channels), std::move(curves), std::move(surfaces));
}

}  // namespace sm::interp
