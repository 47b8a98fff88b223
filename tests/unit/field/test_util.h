// Helpers for the field unit tests: build a FieldSet and evaluate one field.
#pragma once

#include <string>
#include <vector>

#include "field/field_set.h"

namespace sm::field::testing {

inline std::vector<double> eval_field(const FieldSet& fs, int id, const std::vector<Vec3>& pts,
                                      const BuildContext& ctx = {}) {
  BuiltFields built = fs.build(id, ctx);
  std::vector<double> h(pts.size());
  built.get(id)->eval(pts, h);
  return h;
}

inline double eval1(const FieldSet& fs, int id, Vec3 p, const BuildContext& ctx = {}) {
  return eval_field(fs, id, {p}, ctx)[0];
}

inline std::string repo_data(const std::string& rel) { return std::string(SM_DATA_DIR) + "/" + rel; }

}  // namespace sm::field::testing
