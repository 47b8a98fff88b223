// The mesh of a geometry model as the meshers build it (paper section 3): one node per
// model vertex, per curve its ordered nodes with parameters, later per surface its
// triangles. Shared end points are meshed once; writers go through io/from_model_mesh.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "mesh/periodic_link.h"

namespace sm {

/// One mesh node: its position in space and, on a surface geometry, its (u,v).
struct MeshNode {
  Vec3 xyz;
  Vec2 uv;
  bool has_uv = false;
};

/// The 1D mesh of one model curve, from its begin vertex to its end vertex (equal for a
/// closed curve). nodes.front()/back() are the model vertices' nodes; t increases
/// strictly from 0 to 1.
struct CurveMesh {
  int tag = 0;
  std::vector<std::uint32_t> nodes;   // indices into ModelMesh::nodes
  std::vector<double> t;              // curve parameter of each node
  /// Only on the coarse meshes made for the element budget (Mesh1dOptions::coarse_check):
  /// the 1D size at each node, which the face's estimate extends from the boundary in
  /// place of the coarse edge lengths.
  std::vector<double> h;
  std::size_t num_edges() const { return nodes.empty() ? 0 : nodes.size() - 1; }
};

/// Triangles and quadrangles of one model surface (filled by the 2D meshers; quadrangles
/// from a transfinite or recombined surface, mesh/recombine.h), all oriented alike.
struct SurfaceMesh {
  int tag = 0;
  std::vector<std::uint32_t> interior_nodes;          // nodes classified on the surface
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> quads;
};

struct ModelMesh {
  std::vector<MeshNode> nodes;
  std::map<int, std::uint32_t> vertex_node;   // model vertex tag -> its node
  std::map<int, CurveMesh> curves;            // curve tag -> its mesh
  std::map<int, SurfaceMesh> surfaces;
  int dim = 0;                                // highest dimension meshed
  std::vector<PeriodicLink> periodic;         // points, curves, then surfaces, in tag order

  std::uint32_t add_node(Vec3 xyz) {
    nodes.push_back({xyz, {}, false});
    return static_cast<std::uint32_t>(nodes.size() - 1);
  }
  std::uint32_t add_node(Vec3 xyz, Vec2 uv) {
    nodes.push_back({xyz, uv, true});
    return static_cast<std::uint32_t>(nodes.size() - 1);
  }
  std::size_t num_curve_edges() const;
  /// The nodes of curve |signed_tag|'s mesh in the direction of the sign (reversed for a
  /// negative tag); empty when the curve has no mesh.
  std::vector<std::uint32_t> curve_nodes(int signed_tag) const;
};

}  // namespace sm
