// del2d: circumcentre insertion driven by the bucketed work list of
// refine_queue.h. The cavity is the Bowyer-Watson conflict region grown across
// non-constrained edges only, which keeps the triangulation constrained
// Delaunay.
#include "mesh/refine.h"

#include <algorithm>
#include <span>
#include <vector>

#include "mesh/quality.h"
#include "mesh/refine_queue.h"

namespace sm {
namespace {

class Refiner : detail::RefineDriver {
 public:
  Refiner(TriangleStore& m, const RefineOptions& opt, RefineResult& res) : RefineDriver(m, opt, res) {}
  void run();

 private:
  bool consider(std::span<const std::uint32_t> tris);
};

// Queues the triangles whose circumradius exceeds the bound, with the size
// field evaluated once for the whole batch of circumcentres.
bool Refiner::consider(std::span<const std::uint32_t> tris) {
  if (!sample_sizes(tris)) return false;
  const double limit2 = opt_.radius_limit * opt_.radius_limit;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const std::uint32_t t = tris[i];
    const double h = h_[i];
    const double q = norm2(pts_[i] - m_.pos(m_.vertex(TriId{t}, 0))) / (h * h);
    queue_.drop(t);
    if (q > limit2) queue_.push(t, static_cast<float>(q));
  }
  return true;
}

void Refiner::run() {
  queue_.grow(m_.num_slots());
  const std::vector<std::uint32_t> live = live_triangles();
  for (std::size_t i = 0; i < live.size(); i += 4096)
    if (!consider(std::span<const std::uint32_t>(live.data() + i, std::min<std::size_t>(4096, live.size() - i))))
      return finish();
  std::vector<std::uint32_t> new_slot, new_vertex;
  std::uint32_t t;
  while (queue_.pop(m_, t)) {
    if (at_vertex_limit()) break;
    const TriId tt{t};
    const Vec2 cc = circumcentre(m_.pos(m_.vertex(tt, 0)), m_.pos(m_.vertex(tt, 1)), m_.pos(m_.vertex(tt, 2)));
    if (ins_.insert_near(cc, tt) != InsertOutcome::Inserted) {
      ++res_.stats.rejected;
      continue;
    }
    inserted();
    if (!consider(ins_.created())) break;
    if (maybe_sort(new_slot, new_vertex))
      new_slot = {}, new_vertex = {};  // 6 bytes a triangle, not needed until the next sort
  }
  finish();
}

}  // namespace

RefineResult refine_del2d(TriangleStore& m, const RefineOptions& opt) {
  RefineResult res;
  res.error = detail::check_refine_options(opt);
  if (!res.ok()) return res;
  Refiner r(m, opt, res);
  r.run();
  return res;
}

}  // namespace sm
