// Mesh.QualityFloor's value in effect (set where a script, the command line or the Python
// module gives it, else its default on a model on the sphere and off on a flat model), and
// whether front2d applies Gmsh's rule for new points (on a flat model only).
#pragma once

namespace sm::interp {

class Interpreter;
struct KernelState;

/// Whether the model is an ocean model on the sphere: a Coastline import, or a surface on
/// a sphere's chart (PolarSphere, Sphere: ModelSurface::geometry).
bool model_on_sphere(const KernelState& k);

/// The quality floor the mesher lifts triangles to (Mesh2dOptions::quality_floor; 0: off).
/// Mesh.QualityFloor where it was set (Options::was_set), else its default (0.3) on a model
/// on the sphere and 0 on a flat model: the floor splits curve edges, which Gmsh never does,
/// so a flat Gmsh script gets Gmsh's curve meshes (docs/interpreter.md, Quality floor).
double quality_floor_in_effect(Interpreter& in);

/// Whether front2d refuses the points Gmsh 4.8.4 refuses (Mesh2dOptions::gmsh_rejection):
/// on a flat model, so that a Gmsh script gets Gmsh's triangle counts; not on the sphere,
/// whose ocean meshes keep the points (docs/kernel.md, Frontal-Delaunay).
bool gmsh_rejection_in_effect(const KernelState& k);

}  // namespace sm::interp
