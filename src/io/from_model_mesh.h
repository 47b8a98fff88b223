// The mesh of a model (mesh/model_mesh.h) as the writers' neutral MeshModel: nodes
// classified on model points, curves and surfaces as Gmsh classifies them, elements per
// entity, physical groups of the model, parametric coordinates (curve t, surface u v).
#pragma once

#include "geo/model.h"
#include "io/mesh_model.h"
#include "mesh/model_mesh.h"

namespace sm::io {

/// Every model point (a Point1 element on its node), every curve (its interior nodes with
/// their t, Line2 elements from begin to end) and every surface (interior nodes with
/// (u,v) when known, Triangle3 elements; none before 2D meshing), in tag order, with the
/// model's physical groups. Which entities a file then holds is the writer's rule
/// (Gmsh's: only those in physical groups when there are any, unless SaveAll).
MeshModel from_model_mesh(const geo::Model& model, const ModelMesh& mesh);

}  // namespace sm::io
