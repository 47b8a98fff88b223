// Min and Max fields (paper section 3.1: the final size is the minimum of the
// criteria sizes) and the argmin report of Min.
#include "field/min_max.h"

#include <algorithm>
#include <vector>

#include "field/bounded_field.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

class ExtremumField final : public CompositeField {
 public:
  ExtremumField(std::vector<std::pair<int, FieldPtr>> in, bool is_min) : in_(std::move(in)), is_min_(is_min) {
    for (const auto& [id, f] : in_) lowers_.push_back(is_min_ ? dynamic_cast<const MinInput*>(f.get()) : nullptr);
    // Without argmin the order of a Min's inputs does not change its value (NaN never
    // enters h: every update is a `<`), so the inputs whose search stops sooner under a
    // smaller h (a Threshold of a Distance: the nearest coast point sought only as far as
    // could still lower h) come after the others, each group in list order.
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t n = 0; n < in_.size(); ++n)
        if ((lowers_[n] && lowers_[n]->prunes()) == (pass == 1)) min_order_.push_back(n);
  }

  bool is_min() const { return is_min_; }

  void run_argmin(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h,
                  std::span<int> which) const {
    std::fill(h.begin(), h.end(), is_min_ ? kMaxLc : -kMaxLc);
    if (!which.empty()) std::fill(which.begin(), which.end(), -1);
    std::vector<double> tmp;  // sized when an input is evaluated whole (a Min of lowering inputs needs none)
    for (std::size_t k = 0; k < in_.size(); ++k) {
      const std::size_t n = is_min_ && which.empty() ? min_order_[k] : k;
      const auto& [id, f] = in_[n];
      // An input that can skip the points where it cannot be the smallest does so
      // (without argmin: there a tie must still be seen).
      if (lowers_[n] && which.empty()) {
        lowers_[n]->lower(on, pts, h);
        continue;
      }
      tmp.resize(pts.size());
      eval_input(*f, on, pts, tmp);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const bool better = is_min_ ? tmp[i] < h[i] : tmp[i] > h[i];
        if (better || (!which.empty() && which[i] < 0 && tmp[i] == h[i])) {
          h[i] = tmp[i];
          if (!which.empty()) which[i] = id;
        }
      }
    }
  }

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    run_argmin(on, pts, h, {});
  }

 private:
  std::vector<std::pair<int, FieldPtr>> in_;
  std::vector<const MinInput*> lowers_;  // per input: itself, when it is one
  std::vector<std::size_t> min_order_;    // the inputs in the order a Min without argmin asks them
  bool is_min_;
};

FieldPtr make_min(const BuildInputs& in) {
  return std::make_shared<ExtremumField>(in.inputs("FieldsList"), true);
}

FieldPtr make_max(const BuildInputs& in) {
  return std::make_shared<ExtremumField>(in.inputs("FieldsList"), false);
}

}  // namespace

bool eval_argmin(const SizeField& f, const EntityRef* on, std::span<const Vec3> pts,
                 std::span<double> h, std::span<int> which) {
  const auto* m = dynamic_cast<const ExtremumField*>(&f);
  if (!m || !m->is_min()) return false;
  m->run_argmin(on, pts, h, which);
  return true;
}

KindSpec min_kind() {
  return {"Min",
          "Minimum of the listed fields (1e22 when the list is empty); eval_argmin() reports "
          "which input attains it.",
          {list_opt("FieldsList", "ids of the fields to combine", {}, OptionRole::FieldRefList)},
          make_min};
}

KindSpec max_kind() {
  return {"Max", "Maximum of the listed fields (-1e22 when the list is empty).",
          {list_opt("FieldsList", "ids of the fields to combine", {}, OptionRole::FieldRefList)},
          make_max};
}

}  // namespace sm::field
