// The store's undo journal (store_undo.h).
#include "mesh/store_undo.h"

#include <cstring>

#include "base/check.h"

namespace sm {
namespace {

// A hash of the bytes of an array, eight at a time (a multiply and a rotation a word: a
// pass over the store of ten million triangles in a few hundredths of a second), chained
// from `h`.
template <class T>
std::uint64_t hash_array(std::uint64_t h, const std::vector<T>& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(v.data());
  const std::size_t n = v.size() * sizeof(T);
  auto mix = [&h](std::uint64_t w) {
    h = (h ^ w) * 0x9e3779b97f4a7c15ull;
    h = (h << 29) | (h >> 35);
  };
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    mix(w);
  }
  std::uint64_t tail = 0;
  if (i < n) std::memcpy(&tail, p + i, n - i);
  mix(tail);
  mix(v.size());
  return h;
}

bool test_and_set(std::vector<std::uint64_t>& bits, std::uint32_t i) {
  std::uint64_t& word = bits[i >> 6];
  const std::uint64_t bit = std::uint64_t{1} << (i & 63);
  const bool was = (word & bit) != 0;
  word |= bit;
  return was;
}

}  // namespace

std::uint64_t store_fingerprint(const TriangleStore& m) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  h = hash_array(h, m.xy);
  h = hash_array(h, m.out_side);
  h = hash_array(h, m.corner);
  h = hash_array(h, m.twin);
  h = hash_array(h, m.side_flags);
  h = hash_array(h, m.tri_flags);
  return hash_array(h, m.free_tris);
}

StoreUndo::StoreUndo(TriangleStore& m) : m_(m) {
  SM_ASSERT(m.undo_link.journal == nullptr, "a store with two undo journals");
  start(m);
  m.undo_link.journal = this;
}

StoreUndo::~StoreUndo() {
  if (m_.undo_link.journal == this) m_.undo_link.journal = nullptr;
}

void StoreUndo::start(const TriangleStore& m) {
  slots_ = m.num_slots();
  vertices_ = m.num_vertices();
  free_tris_ = m.free_tris;
  tri_saved_.assign((slots_ + 63) / 64, 0);
  vert_saved_.assign((vertices_ + 63) / 64, 0);
  tris_.clear();
  verts_.clear();
  fingerprint_ = store_fingerprint(m);
}

void StoreUndo::save_tri(const TriangleStore& m, std::uint32_t t) {
  if (t >= slots_ || test_and_set(tri_saved_, t)) return;
  SavedTri s{};
  s.t = t;
  for (std::uint32_t e = 0; e < 3; ++e) {
    s.corner[e] = m.corner[3 * t + e];
    s.twin[e] = m.twin[3 * t + e];
    s.side_flags[e] = m.side_flags[3 * t + e];
  }
  s.tri_flags = m.tri_flags[t];
  tris_.push_back(s);
}

void StoreUndo::save_vertex(const TriangleStore& m, std::uint32_t v) {
  if (v >= vertices_ || test_and_set(vert_saved_, v)) return;
  verts_.push_back({v, m.out_side[v], m.xy[v]});
}

void StoreUndo::changed_slots(std::vector<std::uint32_t>& out) const {
  out.reserve(out.size() + tris_.size());
  for (const SavedTri& s : tris_) out.push_back(s.t);
}

void StoreUndo::restore(TriangleStore& m) {
  SM_ASSERT(&m == &m_, "an undo journal restored on another store");
  m.undo_link.journal = nullptr;  // the writes below are the journal's own
  m.xy.resize(vertices_);
  m.out_side.resize(vertices_);
  m.corner.resize(3 * std::size_t{slots_});
  m.twin.resize(3 * std::size_t{slots_});
  m.side_flags.resize(3 * std::size_t{slots_});
  m.tri_flags.resize(slots_);
  for (const SavedTri& s : tris_) {
    for (std::uint32_t e = 0; e < 3; ++e) {
      m.corner[3 * s.t + e] = s.corner[e];
      m.twin[3 * s.t + e] = s.twin[e];
      m.side_flags[3 * s.t + e] = s.side_flags[e];
    }
    m.tri_flags[s.t] = s.tri_flags;
  }
  for (const SavedVertex& s : verts_) {
    m.xy[s.v] = s.xy;
    m.out_side[s.v] = s.out_side;
  }
  m.free_tris = free_tris_;
  SM_ASSERT(store_fingerprint(m) == fingerprint_, "the store changed without telling its undo journal");
  start(m);
  m.undo_link.journal = this;
}

}  // namespace sm
