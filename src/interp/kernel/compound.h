// The compound statements (compound.cpp): `Compound Curve|Surface{...};` as meshing
// constraints, `Compound Spline|BSpline(t) = {curves} Using n;` as a new curve.
#pragma once

#include <optional>

#include "geo/model.h"
#include "lang/ast.h"

namespace sm::interp {

class Interpreter;

/// `Compound Spline(t) = ...` / `Compound BSpline(t) = ...` (a CurveStmt of those kinds):
/// the new points and curve in the model; the curve made.
std::optional<geo::DimTag> exec_compound_spline(Interpreter& in, const lang::Stmt& s, const lang::CurveStmt& n);

}  // namespace sm::interp
