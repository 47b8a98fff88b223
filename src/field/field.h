// Size-field interface: the target edge length h(x) at 3D points, evaluated
// in batches (paper section 3.1; Gmsh's Field[n], docs/fields.md).
#pragma once

#include <span>

#include "base/vec.h"

namespace sm::field {

/// Gmsh's "no constraint" size (MAX_LC).
inline constexpr double kMaxLc = 1e22;

/// The model entity being meshed, for Restrict and Constant (dim 0..3).
struct EntityRef {
  int dim = -1;
  int tag = 0;
};

class SizeField {
 public:
  virtual ~SizeField() = default;
  /// Mesh size at each point. Inputs were resolved when the field was built.
  /// Const and free of shared mutable state: safe to call from many threads.
  virtual void eval(std::span<const Vec3> pts, std::span<double> h) const = 0;
  /// Same, knowing which entity the points belong to. Fields that do not
  /// care about entities keep this default; composites forward it to inputs.
  virtual void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const {
    eval(pts, h);
  }
};

/// Evaluates `f` with or without an entity context (helper for composites).
inline void eval_input(const SizeField& f, const EntityRef* on, std::span<const Vec3> pts,
                       std::span<double> h) {
  if (on) {
    f.eval_on(*on, pts, h);
  } else {
    f.eval(pts, h);
  }
}

/// A field whose value depends on the entity context only through its inputs:
/// implement `run` once, both entry points forward to it.
class CompositeField : public SizeField {
 public:
  void eval(std::span<const Vec3> pts, std::span<double> h) const final { run(nullptr, pts, h); }
  void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const final {
    run(&on, pts, h);
  }

 protected:
  virtual void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const = 0;
};

}  // namespace sm::field
