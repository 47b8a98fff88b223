// The table of 2D algorithms (mesh2d_algorithms.h): look-ups and the lists shown to users.
#include "mesh/mesh2d_algorithms.h"

namespace sm {

const Mesh2dAlgorithmRow* mesh2d_algorithm_named(std::string_view name) {
  for (const Mesh2dAlgorithmRow& r : kMesh2dAlgorithms)
    if (r.name == name) return &r;
  return nullptr;
}

const Mesh2dAlgorithmRow* mesh2d_algorithm_numbered(int number) {
  for (const Mesh2dAlgorithmRow& r : kMesh2dAlgorithms)
    if (r.number == number) return &r;
  return nullptr;
}

std::string mesh2d_algorithm_names(std::string_view last) {
  std::string out;
  for (std::size_t i = 0; i < kMesh2dAlgorithms.size(); ++i) {
    if (i > 0) out += i + 1 == kMesh2dAlgorithms.size() ? last : std::string_view(", ");
    out += kMesh2dAlgorithms[i].name;
  }
  return out;
}

std::string mesh2d_algorithm_numbers() {
  std::string out;
  for (std::size_t i = 0; i < kMesh2dAlgorithms.size(); ++i) {
    if (i > 0) out += i + 1 == kMesh2dAlgorithms.size() ? " or " : ", ";
    out += std::to_string(kMesh2dAlgorithms[i].number) + " (" + std::string(kMesh2dAlgorithms[i].help) + ")";
  }
  return out;
}

std::string mesh2d_algorithm_help() {
  std::string out = mesh2d_algorithm_names(", ") + " (Mesh.Algorithm";
  for (const Mesh2dAlgorithmRow& r : kMesh2dAlgorithms)
    if (!r.note.empty()) out += "; " + std::string(r.name) + ": " + std::string(r.note);
  return out + ")";
}

}  // namespace sm
