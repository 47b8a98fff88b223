// Where model entities came from: the (dim, tag) keys of KernelState::created_at, and
// kernel errors turned into located diagnostics with a note at the statement that created
// each entity the error names ("note: curve 7 was created here").
#pragma once

#include <vector>

#include "geo/error.h"
#include "mesh/mesh_error.h"
#include "interp/kernel_state.h"
#include "lang/diagnostics.h"

namespace sm::interp {

class Interpreter;

// Keys of created_at beyond Gmsh's dimensions 0..3.
inline constexpr int kCurveLoopKey = -1;
inline constexpr int kGeometryKey = -2;
inline constexpr int kPhysicalKeyBase = 10;   ///< physical group of dimension d: 10 + d

/// Records (or, for a re-created tag, replaces) the statement that created an entity.
void record_created(KernelState& k, int key_dim, int tag, lang::SourceRange at);

/// "point 3 was created here" notes for the existing entities an error names.
std::vector<lang::DiagNote> provenance_notes(const KernelState& k, const geo::GeoError& e);

/// "curve 7 was created here" / "surface 1 was created here" notes for the entities a
/// mesher error names, in its order.
std::vector<lang::DiagNote> provenance_notes(const KernelState& k, const MeshError& e);

/// Reports a kernel error at `at` (the statement or expression that failed) and stops it.
[[noreturn]] void fail_geo(Interpreter& in, lang::SourceRange at, const geo::GeoError& e);

}  // namespace sm::interp
