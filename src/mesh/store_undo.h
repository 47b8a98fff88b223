// An undo journal for a TriangleStore: while one is attached (TriangleStore::undo), the
// first change to a triangle slot or a vertex saves its old contents, so that restore()
// puts the store back as it was without a copy of the whole store. The quality floor's
// put-back (face_floor.cpp) held such a copy, 40 bytes a triangle, and it made the 2D peak
// of the full world at a 1 km coast (docs/benchmarks_scale.md, "Ten million triangles").
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangulation.h"

namespace sm {

class StoreUndo {
 public:
  /// Starts the journal on `m` as it is now and attaches it (m.undo_link.journal = this): from here every
  /// change of m goes through TriangleStore::will_change_tri / will_change_vertex first.
  explicit StoreUndo(TriangleStore& m);
  /// Detaches the journal if still attached.
  ~StoreUndo();
  StoreUndo(const StoreUndo&) = delete;
  StoreUndo& operator=(const StoreUndo&) = delete;

  /// Saves slot t (its three sides and its flags) the first time it is about to change;
  /// slots made after the start are not saved (restore cuts them off).
  void save_tri(const TriangleStore& m, std::uint32_t t);
  /// The same for vertex v (its point and out_side).
  void save_vertex(const TriangleStore& m, std::uint32_t v);

  /// Puts the store back as it was at the start (the arrays' contents; capacities may
  /// differ) and starts the journal again from there, still attached. Checks the result
  /// against the fingerprint taken at the start: a change made without telling the
  /// journal is a bug (SM_ASSERT), never a silently different mesh.
  void restore(TriangleStore& m);

  /// Triangle slots at the start: those from here on are new (never saved).
  std::uint32_t start_slots() const { return slots_; }
  /// Appends every slot below start_slots() changed since the start to `out`, each once,
  /// in the order of their first change (what a scan of the whole store for what changed
  /// may read instead: the quality floor's rounds, quality_floor.cpp).
  void changed_slots(std::vector<std::uint32_t>& out) const;

  /// Entries saved so far (triangles, vertices).
  std::size_t saved_triangles() const { return tris_.size(); }
  std::size_t saved_vertices() const { return verts_.size(); }

 private:
  struct SavedTri {
    std::uint32_t t;
    VertexId corner[3];
    Side twin[3];
    std::uint8_t side_flags[3];
    std::uint8_t tri_flags;
  };
  struct SavedVertex {
    std::uint32_t v;
    Side out_side;
    Vec2 xy;
  };
  void start(const TriangleStore& m);

  TriangleStore& m_;
  std::uint32_t slots_ = 0, vertices_ = 0;
  std::vector<TriId> free_tris_;
  std::vector<std::uint64_t> tri_saved_, vert_saved_;  // one bit a slot / vertex
  std::vector<SavedTri> tris_;
  std::vector<SavedVertex> verts_;
  std::uint64_t fingerprint_ = 0;
};

/// A 64-bit hash of every array of the store (contents, not capacities): equal stores
/// give equal hashes.
std::uint64_t store_fingerprint(const TriangleStore& m);

}  // namespace sm
