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

const char* to_string(EntityKind k) {
  switch (k) {
    case EntityKind::Point: return "point";
    case EntityKind::Curve: return "curve";
    case EntityKind::Surface: return "surface";
    case EntityKind::Volume: return "volume";
    case EntityKind::CurveLoop: return "curve loop";
    case EntityKind::SurfaceGeometry: return "surface geometry";
    case EntityKind::Physical: return "physical group";
    case EntityKind::None: return "none";
  }
  return "?";
}

GeoError make_error(GeoErrorKind kind, EntityKind entity, std::vector<int> tags, std::string message) {
  GeoError e;
  e.kind = kind;
  e.entity = entity;
  e.tags = std::move(tags);
  e.message = std::move(message);
  return e;
}

}  // namespace sm::geo
