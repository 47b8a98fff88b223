// Entity lists of Restrict and Constant: which model entities an option set
// names (PointsList, CurvesList, SurfacesList, VolumesList).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "field/field.h"
#include "field/options.h"

namespace sm::field {

class EntityLists {
 public:
  explicit EntityLists(const Options& o) {
    const char* names[4] = {"PointsList", "CurvesList", "SurfacesList", "VolumesList"};
    for (int d = 0; d < 4; ++d) {
      for (double v : o.list(names[d])) tags_[static_cast<std::size_t>(d)].push_back(static_cast<int>(v));
      std::sort(tags_[static_cast<std::size_t>(d)].begin(), tags_[static_cast<std::size_t>(d)].end());
    }
  }

  bool contains(const EntityRef& e) const {
    if (e.dim < 0 || e.dim > 3) return false;
    const auto& t = tags_[static_cast<std::size_t>(e.dim)];
    return std::binary_search(t.begin(), t.end(), e.tag);
  }

 private:
  std::array<std::vector<int>, 4> tags_;
};

}  // namespace sm::field
