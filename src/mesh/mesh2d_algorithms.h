// The 2D algorithms, one row each: the name (the command line's -algo, the Python
// module's algo=), Gmsh's Mesh.Algorithm number, the mesher that runs (Mesh2dAlgorithm)
// and what it is. The command line, the interpreter's Mesh.Algorithm, the Python module
// and the generated --help of docs/interpreter.md all read this table. Gmsh's other
// numbers (bamg 7, pack 9, ...) are absent: the kernel does not have them,
// and each front end refuses them by saying what it has.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "mesh/mesh2d_options.h"

namespace sm {

struct Mesh2dAlgorithmRow {
  std::string_view name;
  int number;                   // Mesh.Algorithm
  Mesh2dAlgorithm algorithm;
  std::string_view help;        // shown after the number where a list of numbers is given
  std::string_view note = {};   // what the name does beyond its mesher (-algo's help)
};

inline constexpr std::array<Mesh2dAlgorithmRow, 6> kMesh2dAlgorithms = {{
    {"meshadapt", 1, Mesh2dAlgorithm::MeshAdapt, "meshadapt"},
    {"auto", 2, Mesh2dAlgorithm::Automatic, "automatic"},
    // Gmsh's "initial mesh only": the boundary's constrained triangulation, no node inserted.
    {"initial2d", 3, Mesh2dAlgorithm::InitialOnly, "initial mesh only", "the boundary's triangulation only"},
    {"del2d", 5, Mesh2dAlgorithm::Del2d, "del2d"},
    {"front2d", 6, Mesh2dAlgorithm::Frontal, "front2d"},
    // Gmsh's Frontal-Delaunay for Quads: our frontal mesher, its triangles paired where
    // the surface is recombined (as Gmsh pairs them only there too); Gmsh's cross-field
    // aligned right triangles are not made (docs/kernel.md).
    {"delquad", 8, Mesh2dAlgorithm::Frontal, "front2d for quadrangles", "front2d recombined where Recombine asks"},
}};

/// The row of a name or of a Mesh.Algorithm number; nullptr when there is none.
const Mesh2dAlgorithmRow* mesh2d_algorithm_named(std::string_view name);
const Mesh2dAlgorithmRow* mesh2d_algorithm_numbered(int number);

/// The names joined by ", " with `last` before the last one ("meshadapt, auto, initial2d,
/// del2d, front2d and delquad" for last = " and ").
std::string mesh2d_algorithm_names(std::string_view last);

/// The numbers with their help, as a refusal lists them: "1 (meshadapt), 2 (automatic),
/// 3 (initial mesh only), 5 (del2d), 6 (front2d) or 8 (front2d for quadrangles)".
std::string mesh2d_algorithm_numbers();

/// The help of -algo: "meshadapt, auto, initial2d, del2d, front2d, delquad (Mesh.Algorithm;
/// initial2d: the boundary's triangulation only; delquad: front2d recombined where
/// Recombine asks)".
std::string mesh2d_algorithm_help();

}  // namespace sm
