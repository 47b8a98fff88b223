// Size checks on the background field: one pass over the batch, a comparison per value.
#include "field/size_check.h"

#include <cfloat>

#include <fmt/format.h>

#include "field/error.h"

namespace sm::field {
namespace {

class CheckedSizeField final : public SizeField {
 public:
  CheckedSizeField(FieldPtr f, int id, std::string kind) : f_(std::move(f)), id_(id), kind_(std::move(kind)) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    f_->eval(pts, h);
    check(pts, h);
  }
  void eval_on(const EntityRef& on, std::span<const Vec3> pts, std::span<double> h) const override {
    f_->eval_on(on, pts, h);
    check(pts, h);
  }

 private:
  void check(std::span<const Vec3> pts, std::span<double> h) const {
    // Branch-free over the batch (NaN fails both comparisons); the slow path runs once.
    bool bad = false;
    for (const double v : h) bad |= !(v > 0 && v <= DBL_MAX);
    if (!bad) return;
    for (std::size_t i = 0; i < h.size(); ++i) {
      if (h[i] > 0 && h[i] <= DBL_MAX) continue;
      const Vec3 p = pts[i];
      FieldError e(FieldErrc::BadValue,
                   fmt::format("Field[{}] ({}) gives the mesh size {} at ({}, {}, {}): a size must be "
                               "finite and positive", id_, kind_, h[i], p.x, p.y, p.z));
      e.field_id = id_;
      e.name = kind_;
      e.bad = BadValueWhat::Size;
      e.value = h[i];
      e.point = p;
      throw e;
    }
  }

  FieldPtr f_;
  int id_;
  std::string kind_;
};

}  // namespace

FieldPtr checked_size_field(FieldPtr f, int id, std::string kind) {
  if (!f) return f;
  return std::make_shared<CheckedSizeField>(std::move(f), id, std::move(kind));
}

}  // namespace sm::field
