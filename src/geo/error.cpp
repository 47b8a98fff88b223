// The geometry errors' kinds by shape, and their kernel-side names (geo::summary).
#include "geo/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
    case EntityKind::SurfaceLoop: return "surface loop";
    case EntityKind::None: return "none";
  }
  return "?";
}

GeoErrorKind kind_of(GeoErrorId id) {
  switch (id) {
#define SM_GEO_ERROR(name, kind) \
  case GeoErrorId::name: return GeoErrorKind::kind;
#include "geo/error_ids.def"
#undef SM_GEO_ERROR
  }
  return GeoErrorKind::BadArgument;
}

std::string summary(const GeoError& e) {
  std::string s = to_string(e.kind);
  if (e.entity != EntityKind::None && !e.tags.empty()) s += fmt::format(": {} {}", to_string(e.entity), e.tags[0]);
  if (e.tags.size() > 1) s += fmt::format(" ({})", fmt::join(e.tags, ", "));
  return s;
}

GeoError make_error(GeoErrorId id, EntityKind entity, std::vector<int> tags, std::vector<int> ids,
                    std::vector<double> numbers, std::vector<std::string> words) {
  GeoError e;
  e.id = id;
  e.kind = kind_of(id);
  e.entity = entity;
  e.tags = std::move(tags);
  e.ids = std::move(ids);
  e.numbers = std::move(numbers);
  e.words = std::move(words);
  return e;
}

}  // namespace sm::geo
