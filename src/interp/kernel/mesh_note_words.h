// The 2D mesher's warnings (mesh/mesh_note.h) as diagnostics: one kind of
// lang/diag_kinds.def per note kind and shape, at the Mesh statement, with the surfaces of
// a Compound Surface named as the script wrote them.
#pragma once

#include <string>

#include "lang/diagnostics.h"
#include "mesh/compound_surface.h"
#include "mesh/mesh_note.h"

namespace sm::interp {

/// "lon X, lat Y" on a sphere geometry, else "(x, y, z)".
std::string place_words(const MeshPlace& place);

/// Reports `note` at `at`: mesh-warning, or mesh-quality-floor for the floor's kinds. A
/// surface that is the union of a Compound Surface (in `compounds`) is named "the union
/// of Compound Surface{a, b}".
void report_mesh_note(lang::Diagnostics& diags, lang::SourceRange at, const MeshNote& note,
                      const CompoundSurfacePlan& compounds);

/// Reports a Compound Surface group meshed surface by surface, and why, at `at`.
void report_compound_declined(lang::Diagnostics& diags, lang::SourceRange at,
                              const CompoundSurfacePlan::Declined& declined);

}  // namespace sm::interp
