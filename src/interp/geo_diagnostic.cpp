// Kernel geometry errors worded through the diagnostic table (see geo_diagnostic.h): the
// values each shape states are listed in geo/error_ids.def.
#include "interp/geo_diagnostic.h"

#include <cstdlib>
#include <type_traits>
#include <vector>

namespace sm::interp {

using geo::GeoErrorId;
using lang::Diag;

namespace {

/// The kind and its message for `args`, checked against the kind's format at compile time.
template <class... Args>
GeoDiagnostic worded(std::type_identity_t<lang::DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), lang::format_diag<Args...>(kind, args...)};
}

// The error's values by position; a value the kernel left out reads as 0 or "" (a kernel
// bug, visible in the message rather than undefined).
struct GeoValues {
  const geo::GeoError& e;
  int tag(std::size_t i) const { return i < e.tags.size() ? e.tags[i] : 0; }
  int abs_tag(std::size_t i) const { return std::abs(tag(i)); }
  int id(std::size_t i) const { return i < e.ids.size() ? e.ids[i] : 0; }
  double number(std::size_t i) const { return i < e.numbers.size() ? e.numbers[i] : 0.0; }
  std::string word(std::size_t i) const { return i < e.words.size() ? e.words[i] : std::string(); }
  std::string entity() const { return geo::to_string(e.entity); }
};

}  // namespace

GeoDiagnostic geo_diagnostic(const geo::GeoError& e) {
  const GeoValues v{e};
  switch (e.id) {
    case GeoErrorId::UnknownEntity: return worded(Diag::GeoUnknownEntity, v.entity(), v.tag(0));
    case GeoErrorId::UnknownEntityIn:
      return worded(Diag::GeoUnknownEntityIn, v.entity(), v.tag(0), v.word(0), v.tag(1));
    case GeoErrorId::UnknownEntityUsedBy:
      return worded(Diag::GeoUnknownEntityUsedBy, v.entity(), v.tag(0), v.word(0), v.tag(1));
    case GeoErrorId::UnknownEmbedded: return worded(Diag::GeoUnknownEmbedded, v.entity(), v.tag(0), v.tag(1));
    case GeoErrorId::UnknownPartOf:
      return worded(Diag::GeoUnknownPartOf, v.entity(), v.tag(0), v.word(0), v.word(1), v.tag(1));
    case GeoErrorId::UnknownGeometryOfPoint:
      return worded(Diag::GeoUnknownGeometryOfPoint, v.entity(), v.tag(0), v.tag(1));
    case GeoErrorId::UnknownEmbeddingTarget: return worded(Diag::GeoUnknownEmbeddingTarget, v.entity(), v.tag(0));
    case GeoErrorId::UnknownInPhysicalGroup: return worded(Diag::GeoUnknownInPhysicalGroup, v.entity(), v.tag(0));
    case GeoErrorId::UnknownInBoundary: return worded(Diag::GeoUnknownInBoundary, v.entity(), v.tag(0));
    case GeoErrorId::UnknownToIntersect: return worded(Diag::GeoUnknownToIntersect, v.entity(), v.tag(0), v.id(0));
    case GeoErrorId::CannotActOnUnknown:
      return worded(Diag::GeoCannotActOnUnknown, v.word(0), v.entity(), v.abs_tag(0));
    case GeoErrorId::CannotTransformUnknown: return worded(Diag::GeoCannotTransformUnknown, v.abs_tag(0), v.id(0));
    case GeoErrorId::AlreadyExists: return worded(Diag::GeoAlreadyExists, v.entity(), v.tag(0));
    case GeoErrorId::PhysicalAlreadyExists: return worded(Diag::GeoPhysicalAlreadyExists, v.word(0), v.tag(0));
    case GeoErrorId::TagNotPositive: return worded(Diag::GeoTagNotPositive, v.entity(), v.tag(0));
    case GeoErrorId::TagMustBePositive: return worded(Diag::GeoTagMustBePositive, v.entity(), v.tag(0));
    case GeoErrorId::CirclePointCount: return worded(Diag::GeoCirclePointCount, v.tag(0), v.id(0));
    case GeoErrorId::EllipsePointCount: return worded(Diag::GeoEllipsePointCount, v.tag(0), v.id(0));
    case GeoErrorId::CurvePointCount: return worded(Diag::GeoCurvePointCount, v.word(0), v.tag(0), v.id(0));
    case GeoErrorId::PeriodicCurvePointCount: return worded(Diag::GeoPeriodicCurvePointCount, v.word(0), v.tag(0));
    case GeoErrorId::DiscreteCurveClosed: return worded(Diag::GeoDiscreteCurveClosed, v.tag(0), v.tag(1));
    case GeoErrorId::CurveStartsAtEnd: return worded(Diag::GeoCurveStartsAtEnd, v.word(0), v.tag(0), v.tag(1));
    case GeoErrorId::CurvePointTwice: return worded(Diag::GeoCurvePointTwice, v.word(0), v.tag(0), v.tag(1));
    case GeoErrorId::ArcRepeatsPoint: return worded(Diag::GeoArcRepeatsPoint, v.word(0), v.tag(0));
    case GeoErrorId::CircleEndAtCentre: return worded(Diag::GeoCircleEndAtCentre, v.tag(0));
    case GeoErrorId::SphereRadiusZero:
      return worded(Diag::GeoSphereRadiusZero, v.word(0), v.tag(0), v.tag(1), v.tag(2));
    case GeoErrorId::NotCocircular: return worded(Diag::GeoNotCocircular, v.tag(0), v.number(0), v.number(1));
    case GeoErrorId::CirclePlaneUndefined: return worded(Diag::GeoCirclePlaneUndefined, v.tag(0));
    case GeoErrorId::CircleFull: return worded(Diag::GeoCircleFull, v.tag(0));
    case GeoErrorId::EllipseCentrePoint: return worded(Diag::GeoEllipseCentrePoint, v.tag(0));
    case GeoErrorId::EllipseAxisNormal: return worded(Diag::GeoEllipseAxisNormal, v.tag(0));
    case GeoErrorId::EllipseEndsOnAxis: return worded(Diag::GeoEllipseEndsOnAxis, v.tag(0));
    case GeoErrorId::EllipseAxesUndetermined: return worded(Diag::GeoEllipseAxesUndetermined, v.tag(0));
    case GeoErrorId::EllipseNoFit: return worded(Diag::GeoEllipseNoFit, v.tag(0));
    case GeoErrorId::EllipseFull: return worded(Diag::GeoEllipseFull, v.tag(0));
    case GeoErrorId::LoopCurveReversed:
      return worded(Diag::GeoLoopCurveReversed, v.tag(0), v.tag(2), v.id(0), v.tag(1), -v.tag(1));
    case GeoErrorId::LoopDoesNotClose: return worded(Diag::GeoLoopDoesNotClose, v.tag(0), v.tag(1), v.id(0), v.id(1));
    case GeoErrorId::LoopBroken: return worded(Diag::GeoLoopBroken, v.tag(0), v.tag(1), v.id(0));
    case GeoErrorId::LoopEmpty: return worded(Diag::GeoLoopEmpty, v.entity(), v.tag(0));
    case GeoErrorId::NoLoop: return worded(Diag::GeoNoLoop, v.word(0), v.tag(0), v.word(1));
    case GeoErrorId::HoleOutside: return worded(Diag::GeoHoleOutside, v.tag(0), v.tag(1), v.tag(2));
    case GeoErrorId::HoleOutsidePolar:
      return worded(Diag::GeoHoleOutsidePolar, v.tag(0), v.tag(1), v.tag(2), v.id(0));
    case GeoErrorId::LoopTwice: return worded(Diag::GeoLoopTwice, v.tag(0), v.tag(1));
    case GeoErrorId::CurveInTwoLoops:
      return worded(Diag::GeoCurveInTwoLoops, v.tag(0), v.tag(1), v.abs_tag(2), v.abs_tag(3));
    case GeoErrorId::UvCountDiffers: return worded(Diag::GeoUvCountDiffers, v.tag(0));
    case GeoErrorId::ExtrudedArcTooWide: return worded(Diag::GeoExtrudedArcTooWide, v.tag(0), v.number(0));
    case GeoErrorId::ExtrusionAxisZero: return worded(Diag::GeoExtrusionAxisZero);
    case GeoErrorId::CannotExtrudeVolume: return worded(Diag::GeoCannotExtrudeVolume, v.abs_tag(0));
    case GeoErrorId::PointNotFinite: return worded(Diag::GeoPointNotFinite, v.tag(0), v.number(0));
    case GeoErrorId::MeshSizeNotFinite: return worded(Diag::GeoMeshSizeNotFinite, v.number(0));
    case GeoErrorId::PhysicalDimension: return worded(Diag::GeoPhysicalDimension, v.id(0));
    case GeoErrorId::EmbedDimension: return worded(Diag::GeoEmbedDimension);
    case GeoErrorId::BoundaryDimension: return worded(Diag::GeoBoundaryDimension, v.id(0));
    case GeoErrorId::FillingLoopTwice: return worded(Diag::GeoFillingLoopTwice, v.tag(0), v.tag(1));
    case GeoErrorId::FillingCurveCount: return worded(Diag::GeoFillingCurveCount, v.tag(0), v.tag(1), v.id(0));
    case GeoErrorId::PlaneSurfaceNoUv: return worded(Diag::GeoPlaneSurfaceNoUv, v.tag(0));
    case GeoErrorId::RotationAxisZero: return worded(Diag::GeoRotationAxisZero);
    case GeoErrorId::SymmetryPlaneZero: return worded(Diag::GeoSymmetryPlaneZero);
    case GeoErrorId::CannotSplitArc: return worded(Diag::GeoCannotSplitArc, v.word(0), v.tag(0));
  }
  return worded(Diag::GeoUnknownEntity, v.entity(), v.tag(0));   // not reached: every id has its case
}

GeoDiagnostic geo_compat_diagnostic(const geo::Model::CompatNote& note) {
  using Id = geo::Model::CompatNoteId;
  // A tag the kernel left out reads as 0 (a kernel bug, visible in the message).
  const auto tag = [&note](std::size_t i) { return i < note.tags.size() ? note.tags[i] : 0; };
  switch (note.id) {
    case Id::UncheckedLoop:
      if (note.unchecked_loop)
        return worded(Diag::GmshCompatUncheckedLoop, geo_diagnostic(*note.unchecked_loop).message);
      break;
    case Id::TagZero: return worded(Diag::GmshCompatTagZero, note.word);
    case Id::MeshSizeOfMissingPoint: return worded(Diag::GmshCompatMeshSizeOfMissingPoint, tag(0));
    case Id::LineToItself: return worded(Diag::GmshCompatLineToItself, tag(0), tag(1));
    case Id::EllipseAxisAtCentre: return worded(Diag::GmshCompatEllipseAxisAtCentre, tag(0), tag(1), tag(2));
    case Id::ZeroLengthCurve: return worded(Diag::GmshCompatZeroLengthCurve, note.word, tag(0), tag(1), tag(2));
    case Id::OuterListedLater: return worded(Diag::GmshCompatOuterListedLater, tag(0), tag(1), tag(2));
    case Id::HoleCrossesOuter: return worded(Diag::GmshCompatHoleCrossesOuter, tag(0), tag(1), tag(2));
    case Id::ExtrudeClosedCurve: return worded(Diag::GmshCompatExtrudeClosedCurve, tag(0));
    case Id::DuplicataOfMissing: return worded(Diag::GmshCompatDuplicataOfMissing, note.word, tag(0));
    case Id::SplitAtOtherPoint: return worded(Diag::GmshCompatSplitAtOtherPoint, tag(0), tag(1));
    case Id::DiscreteLoopReoriented: return worded(Diag::GmshCompatDiscreteLoopReoriented, tag(0), tag(1));
  }
  return worded(Diag::GmshCompatUncheckedLoop, std::string("curve loop (no error recorded)"));   // a kernel bug
}

}  // namespace sm::interp
