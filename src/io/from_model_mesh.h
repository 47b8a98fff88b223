// The mesh of a model (mesh/model_mesh.h) as the writers' neutral MeshModel: nodes
// classified on model points, curves and surfaces as Gmsh classifies them, elements per
// entity, physical groups of the model, parametric coordinates (curve t, surface u v).
#pragma once

#include <cstdint>
#include <vector>

#include "geo/model.h"
#include "io/mesh_model.h"
#include "mesh/model_mesh.h"

namespace sm::io {

/// Every model point (a Point1 element on its node), every curve (its interior nodes with
/// their t, Line2 elements from begin to end) and every surface (interior nodes with
/// (u,v) when known, Triangle3 elements; none before 2D meshing), in tag order, with the
/// model's physical groups. Which entities a file then holds is the writer's rule
/// (Gmsh's: only those in physical groups when there are any, unless SaveAll).
///
/// The mesh and only the mesh, the one place every writer and the Python module read it
/// from: once there are 2D elements, a curve of a meshed surface's loops that no 2D
/// element touches (the closed curve of an island smaller than the mesh size, whose hole
/// loop mesh2d left out with a warning) is not in the model, nor are the points at its
/// ends that nothing kept uses, nor their nodes. The nodes are numbered in the one order
/// every file uses: entity order ((dim, tag): points, curves, surfaces; each entity's own
/// nodes in order), which is the MSH writers' numbering, so MeshModel node i is node i + 1
/// of the .msh, fort.14 and hgrid.gr3 and node i of VTK, UGRID and the Python arrays.
/// `node_index`, when given, receives ModelMesh node -> MeshModel node (0xFFFFFFFF: left
/// out), for what is built from the ModelMesh directly (the ocean grids' boundary strings).
/// Without `parametric` the entities get no parametric coordinates (EntityMesh::params
/// empty), for a file that will not hold them (MSH without Mesh.SaveParametric, every
/// other format): 16 bytes a surface node less at the writing's peak.
/// The copies and renumbering of the elements' nodes run on `threads` threads (the same
/// model for every count).
MeshModel from_model_mesh(const geo::Model& model, const ModelMesh& mesh,
                          std::vector<std::uint32_t>* node_index = nullptr, bool parametric = true, int threads = 1);

}  // namespace sm::io
