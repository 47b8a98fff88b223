// Model -> field BuildContext: the positions and samples Distance, Restrict and
// the finite-difference kinds need, computed from geo::Model at build time.
#include "interp/kernel/field_context.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "field/error.h"

namespace sm::interp {

namespace {
constexpr std::size_t kMaxCurveSamples = 50'000'000;
// ChannelWidth's samples per polynomial piece of a curve.
constexpr int kChannelSamplesPerPiece = 4;

// The side of loop `tag` (in its stored curve order) the water is on, as
// field::CoastChain::water_side: from the one surface the loop bounds, outer loop
// (the surface inside) or hole (outside), the loop's signed area in the surface's
// (u,v) plane, and whether the (u,v) map keeps the orientation seen from outside
// the sphere. 0 when no single surface is bounded by it or the area vanishes.
int loop_water_side(const geo::Model& m, int tag) {
  const geo::ModelSurface* owner = nullptr;
  bool outer = false;
  for (const auto& [stag, s] : m.surfaces())
    for (std::size_t k = 0; k < s.loops.size(); ++k)
      if (std::abs(s.loops[k]) == tag) {
        if (owner) return 0;
        owner = &s;
        outer = k == 0;
      }
  const geo::ModelCurveLoop* loop = m.curve_loop(tag);
  if (!owner || !loop) return 0;
  double area = 0;
  Vec2 first{}, prev{};
  bool have = false;
  double map_sign = 1;
  for (int c : loop->curves) {
    const geo::ModelCurve* mc = m.curve(std::abs(c));
    if (!mc || !mc->shape) return 0;
    const geo::Curve& cv = *mc->shape;
    const int k = kChannelSamplesPerPiece * std::max(cv.pieces(), 1);
    for (int i = 0; i < k; ++i) {
      const double t = static_cast<double>(i) / k;
      Vec2 uv;
      if (cv.on_surface()) {
        uv = cv.eval_uv(t, c < 0).p;
        if (!have) {
          const geo::SurfaceGeometry& g = *cv.surface();
          Vec3 du, dv;
          g.tangents(uv, du, dv);
          map_sign = dot(cross(du, dv), g.point(uv) - g.centre()) < 0 ? -1 : 1;
        }
      } else {
        const Vec3 p = cv.eval(t, c < 0).p;
        uv = {p.x, p.y};
      }
      if (!have) {
        first = uv;
        have = true;
      } else {
        area += cross(prev, uv);
      }
      prev = uv;
    }
  }
  if (!have) return 0;
  area += cross(prev, first);
  if (area == 0) return 0;
  const bool left_in_uv = outer ? area > 0 : area < 0;
  return left_in_uv == (map_sign > 0) ? 1 : -1;
}
}  // namespace

std::vector<Vec3> distance_curve_samples(const geo::Curve& c, int n, std::span<const Vec3> mesh_nodes) {
  std::vector<Vec3> out(mesh_nodes.begin(), mesh_nodes.end());
  const long k = static_cast<long>(n) - static_cast<long>(mesh_nodes.size());
  for (long i = 1; i < k - 1; ++i) out.push_back(c.point(static_cast<double>(i) / static_cast<double>(k - 1)));
  return out;
}

double model_bbox_diag(const geo::Model& model) {
  const double d = model.bounding_box().diagonal();
  return d > 0 ? d : 1.0;
}

field::BuildContext make_build_context(const geo::Model& model, std::filesystem::path base_dir,
                                       const CurveMeshNodes* mesh_nodes) {
  field::BuildContext ctx;
  ctx.bbox_diag = model_bbox_diag(model);
  ctx.base_dir = std::move(base_dir);
  const geo::Model* m = &model;
  ctx.point_position = [m](int tag) -> std::optional<Vec3> {
    const geo::ModelVertex* v = m->vertex(tag);
    if (!v) return std::nullopt;
    return v->xyz;
  };
  // A negative tag names the reversed curve: the same samples (Gmsh's FindCurve(-tag)).
  // A hostile NumPointsPerCurve must not exhaust memory: the samples of one
  // build stay below kMaxCurveSamples (1.2 GB), well above real coastlines.
  auto total = std::make_shared<std::size_t>(0);
  ctx.curve_samples = [m, mesh_nodes, total](int tag, int n) -> std::optional<std::vector<Vec3>> {
    const geo::ModelCurve* c = m->curve(std::abs(tag));
    if (!c || !c->shape) return std::nullopt;
    *total += static_cast<std::size_t>(std::max(n, 0));
    if (*total > kMaxCurveSamples) {
      field::FieldError e(field::FieldErrc::BadValue,
                          fmt::format("NumPointsPerCurve: more than {} curve samples in one build",
                                      kMaxCurveSamples));
      e.option = "NumPointsPerCurve";
      e.bad = field::BadValueWhat::TooManySamples;
      e.value = static_cast<double>(kMaxCurveSamples);
      throw e;
    }
    std::span<const Vec3> nodes;
    if (mesh_nodes) {
      auto it = mesh_nodes->find(std::abs(tag));
      if (it != mesh_nodes->end()) nodes = it->second;
    }
    return distance_curve_samples(*c->shape, n, nodes);
  };
  // ChannelWidth's coast: runs of the listed curves along each curve loop, in
  // loop order (a whole loop is a closed ring), then the curves no loop holds.
  ctx.curve_chains = [m, total](const std::vector<int>& tags) -> std::optional<std::vector<field::CoastChain>> {
    std::map<int, bool> wanted;   // |tag| -> already chained
    for (int t : tags) {
      const geo::ModelCurve* c = m->curve(std::abs(t));
      if (!c || !c->shape) return std::nullopt;
      wanted.emplace(std::abs(t), false);
    }
    std::vector<field::CoastChain> out;
    // Samples: kChannelSamplesPerPiece per polynomial piece, the end point left to the
    // next curve.
    constexpr int kPerPiece = kChannelSamplesPerPiece;
    auto append = [&](field::CoastChain& chain, int signed_tag) {
      const geo::Curve& c = *m->curve(std::abs(signed_tag))->shape;
      const int k = kPerPiece * std::max(c.pieces(), 1);
      *total += static_cast<std::size_t>(k);
      if (*total > kMaxCurveSamples) {
        field::FieldError e(field::FieldErrc::BadValue,
                            fmt::format("more than {} curve samples in one build", kMaxCurveSamples));
        e.bad = field::BadValueWhat::TooManySamples;
        e.value = static_cast<double>(kMaxCurveSamples);
        throw e;
      }
      for (int i = 0; i < k; ++i) chain.points.push_back(c.eval(static_cast<double>(i) / k, signed_tag < 0).p);
    };
    auto close_open = [&](field::CoastChain& chain, int last_signed) {
      const geo::Curve& c = *m->curve(std::abs(last_signed))->shape;
      chain.points.push_back(c.eval(1.0, last_signed < 0).p);
    };
    for (const auto& entry : m->curve_loops()) {
      const int ltag = entry.first;   // not a structured binding: clang 14 lambdas cannot capture one
      const geo::ModelCurveLoop& loop = entry.second;
      const std::size_t n = loop.curves.size();
      auto in_set = [&](std::size_t i) {
        const auto it = wanted.find(std::abs(loop.curves[i % n]));
        return it != wanted.end() && !it->second;
      };
      std::size_t first_out = n;
      for (std::size_t i = 0; i < n; ++i)
        if (!in_set(i)) {
          first_out = i;
          break;
        }
      bool any = false;
      for (std::size_t i = 0; i < n; ++i) any = any || in_set(i);
      if (!any) continue;
      const int water = loop_water_side(*m, ltag);
      if (first_out == n) {   // the whole loop
        field::CoastChain chain;
        chain.closed = true;
        chain.water_side = water;
        for (int t : loop.curves) append(chain, t), wanted[std::abs(t)] = true;
        out.push_back(std::move(chain));
        continue;
      }
      // Runs, starting after a curve outside the set so that none wraps unseen.
      for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (first_out + k) % n;
        if (!in_set(i)) continue;
        field::CoastChain chain;
        chain.water_side = water;
        std::size_t j = i;
        int last = 0;
        while (in_set(j) && j != first_out) {
          append(chain, loop.curves[j]);
          last = loop.curves[j];
          wanted[std::abs(last)] = true;
          j = (j + 1) % n;
        }
        close_open(chain, last);
        out.push_back(std::move(chain));
      }
    }
    for (auto& [tag, used] : wanted) {
      if (used) continue;
      field::CoastChain chain;
      chain.closed = m->curve(tag)->periodic();
      append(chain, tag);
      if (!chain.closed) close_open(chain, tag);
      out.push_back(std::move(chain));
      used = true;
    }
    return out;
  };
  // Surface point clouds need a surface parametrisation the model does not
  // expose yet (Gmsh >= 4.9 samples only OCC and discrete surfaces anyway):
  // SurfacesList is reported as "cannot be sampled" by the Distance field.
  return ctx;
}

}  // namespace sm::interp
