// The geometry kernel's errors in the script's words: each geo::GeoErrorId is the diagnostic
// kind Geo<Id> of lang/diag_kinds.def, whose format the error's values fill.
#pragma once

#include <string>

#include "geo/error.h"
#include "geo/model.h"
#include "lang/diag_format.h"

namespace sm::interp {

struct GeoDiagnostic {
  lang::Diag kind;
  std::string message;
};

/// The kind and message of a kernel error (its kebab name is its geo::GeoErrorKind's).
GeoDiagnostic geo_diagnostic(const geo::GeoError& e);

/// The gmsh-compat warning of a kernel note (geo::Model::take_compat_notes).
GeoDiagnostic geo_compat_diagnostic(const geo::Model::CompatNote& note);

}  // namespace sm::interp
