// Names of the geometry error kinds (stable: tests and diagnostics match on them).
#include "geo/error.h"

namespace sm::geo {

const char* to_string(GeoErrorKind k) {
  switch (k) {
    case GeoErrorKind::MissingEntity: return "missing-entity";
    case GeoErrorKind::DuplicateTag: return "duplicate-tag";
    case GeoErrorKind::InvalidTag: return "invalid-tag";
    case GeoErrorKind::TooFewPoints: return "too-few-points";
    case GeoErrorKind::SelfReference: return "self-reference";
    case GeoErrorKind::CoincidentPoints: return "coincident-points";
    case GeoErrorKind::NotCocircular: return "not-cocircular";
    case GeoErrorKind::DegenerateArc: return "degenerate-arc";
    case GeoErrorKind::LoopNotClosed: return "loop-not-closed";
    case GeoErrorKind::LoopEmpty: return "loop-empty";
    case GeoErrorKind::HoleOutside: return "hole-outside";
    case GeoErrorKind::SharedBoundary: return "shared-boundary";
    case GeoErrorKind::EntityInUse: return "entity-in-use";
    case GeoErrorKind::BadArgument: return "bad-argument";
  }
  return "unknown";
}

GeoError make_error(GeoErrorKind kind, int dim, std::vector<int> tags, std::string message) {
  GeoError e;
  e.kind = kind;
  e.dim = dim;
  e.tags = std::move(tags);
  e.message = std::move(message);
  return e;
}

}  // namespace sm::geo
