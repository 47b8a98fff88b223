// Small helpers of the writer-facing mesh description.
#include "io/mesh_model.h"

#include "base/check.h"

namespace sm::io {

int nodes_per_element(ElementType type) {
  switch (type) {
    case ElementType::Point1: return 1;
    case ElementType::Line2: return 2;
    case ElementType::Triangle3: return 3;
    case ElementType::Quad4: return 4;
  }
  SM_ASSERT(false, "unknown element type");
  return 0;
}

std::size_t MeshModel::element_count() const {
  std::size_t n = 0;
  for (const EntityMesh& e : entities) n += e.connectivity.size() / nodes_per_element(e.type);
  return n;
}

}  // namespace sm::io
