// Typed 32-bit ids for flat arrays: a VertexId cannot be passed where a TriId
// is expected, and kNone marks "no such element" without a sentinel object.
#pragma once

#include <cstdint>
#include <functional>

namespace sm {

/// "No such element" in a plain uint32_t index array (typed ids use Id::kNone).
inline constexpr std::uint32_t kNoIndex = 0xFFFFFFFFu;

template <class Tag>
struct Id {
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t value = kNone;

  constexpr Id() = default;
  constexpr explicit Id(std::uint32_t v) : value(v) {}
  constexpr bool valid() const { return value != kNone; }
  friend constexpr bool operator==(Id a, Id b) { return a.value == b.value; }
  friend constexpr bool operator!=(Id a, Id b) { return a.value != b.value; }
  friend constexpr bool operator<(Id a, Id b) { return a.value < b.value; }
};

using VertexId = Id<struct VertexTag>;
using TriId = Id<struct TriTag>;
using Side = Id<struct SideTag>;  // s = 3*t + e: edge e of triangle t

}  // namespace sm

template <class Tag>
struct std::hash<sm::Id<Tag>> {
  std::size_t operator()(sm::Id<Tag> id) const noexcept { return std::hash<std::uint32_t>{}(id.value); }
};
