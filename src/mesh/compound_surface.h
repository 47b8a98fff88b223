// `Compound Surface{...};` (Gmsh 4.8.4's compound meshing constraint, Geo/GFace.cpp's
// meshCompound): the surfaces are meshed as one, across the curves they share, and with
// Mesh.CompoundClassify = 1 (the default) each element is put back on the original
// surface it lies in, so physical groups of the originals keep their elements.
//
// Gmsh meshes each surface, glues the meshes into a discrete surface, reparametrises it
// and meshes that. Here the surfaces must lie in one plane (or on one surface geometry,
// in its (u,v) plane; a filling `Surface` whose boundary is in that plane is the plane
// region it bounds): their union is one plane surface, bounded by the curves that
// only one of them has, with the holes and embedded entities of all. The shared curves
// are meshed as free curves (Gmsh writes their meshes too) and constrain nothing.
#pragma once

#include <string>
#include <vector>

#include "geo/model.h"
#include "mesh/mesh_error.h"
#include "mesh/model_mesh.h"

namespace sm {

struct CompoundSurfacePlan {
  /// The model to mesh: each combined group's surfaces replaced by their union.
  geo::Model model;
  struct Group {
    int union_tag = 0;            // the union's tag in `model`
    std::vector<int> surfaces;    // the originals, as in the script's model
    int geometry = 0;             // their surface geometry (0: a Euclidean plane)
    Vec3 normal{0, 0, 1};         // Euclidean: the plane's unit normal
  };
  std::vector<Group> groups;
  /// A group meshed surface by surface instead: its surfaces, and why not as one (a
  /// phrase of check_union's or the geometry's: "the surfaces are not in one plane ...").
  struct Declined {
    std::vector<int> surfaces;
    std::string why;
  };
  std::vector<Declined> declined;
  bool empty() const { return groups.empty(); }
};

/// The plan for `Compound Surface` groups (tags as written; missing surfaces skipped).
CompoundSurfacePlan plan_compound_surfaces(const geo::Model& model, const std::vector<std::vector<int>>& groups);

/// After meshing plan.model into `mesh`: each union's triangles, quadrangles and interior
/// nodes classified on the original surface holding the element's centroid (the node),
/// the union's own entry removed, so that `mesh` matches the script's model.
void classify_compound_elements(const geo::Model& model, const CompoundSurfacePlan& plan, ModelMesh& mesh);

/// An error of the mesher on a union names the first of the script's surfaces as its entity
/// U (whose statement the interpreter can show); MeshError::surface stays U, which the
/// worded error names through the text overload.
void name_compound_unions(const CompoundSurfacePlan& plan, MeshError& error);
/// "surface U" in a warning's or worded error's text becomes "the union of Compound Surface{a, b}".
void name_compound_unions(const CompoundSurfacePlan& plan, std::string& text);
/// The union's originals when `surface` is a union of the plan, else null.
const std::vector<int>* compound_union_of(const CompoundSurfacePlan& plan, int surface);

}  // namespace sm
