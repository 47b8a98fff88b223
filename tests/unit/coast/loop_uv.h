// A CoastModel loop as one (u,v) polygon: its curves' points in order, the point each
// curve shares with the next left out (a one-curve loop is a whole periodic ring).
#pragma once

#include <cstdint>
#include <vector>

#include "base/vec.h"
#include "coast/import.h"

namespace sm::testing {

inline std::vector<Vec2> loop_uv(const sm::coast::CoastModel& m, std::uint32_t l) {
  std::vector<Vec2> p;
  const auto& loop = m.loops[l];
  for (std::uint32_t c : loop.curves) {
    const auto& uv = m.curves[c].uv;
    p.insert(p.end(), uv.begin(), loop.curves.size() > 1 ? uv.end() - 1 : uv.end());
  }
  return p;
}

}  // namespace sm::testing
