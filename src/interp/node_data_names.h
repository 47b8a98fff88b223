// The values Mesh.NodeData may name ("depth,size,criterion"), read where the option is set
// (options.cpp: a bad name is an error at the assignment) and where the values are computed
// (kernel/node_data_export.cpp).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace sm::interp {

inline constexpr std::array<std::string_view, 3> kNodeDataNames = {"depth", "size", "criterion"};

/// The names of a Mesh.NodeData value in order, each once (spaces around commas allowed);
/// empty with *unknown set to the first name not in kNodeDataNames when there is one (the
/// caller words it: NodeDataUnknownValue of lang/diag_kinds.def).
inline std::vector<std::string> split_node_data_names(std::string_view v, std::string* unknown) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= v.size()) {
    std::size_t end = v.find(',', start);
    if (end == std::string_view::npos) end = v.size();
    std::string_view w = v.substr(start, end - start);
    while (!w.empty() && w.front() == ' ') w.remove_prefix(1);
    while (!w.empty() && w.back() == ' ') w.remove_suffix(1);
    if (!w.empty()) {
      bool known = false;
      for (std::string_view k : kNodeDataNames) known |= k == w;
      if (!known) {
        *unknown = std::string(w);
        return {};
      }
      bool seen = false;
      for (const std::string& n : names) seen |= n == w;
      if (!seen) names.emplace_back(w);
    }
    start = end + 1;
  }
  return names;
}

}  // namespace sm::interp
