// Typed errors of the geometry kernel: which message shape (GeoErrorId, geo/error_ids.def),
// the entity tags involved (the interpreter maps them back to the statements that created
// them) and the other values the message states; never thrown, never worded here: the
// interpreter words them through the diagnostic table (interp/geo_diagnostic.cpp).
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace sm::geo {

enum class GeoErrorKind {
  MissingEntity,      // a referenced point/curve/loop/surface/geometry does not exist
  DuplicateTag,       // an entity with this tag already exists in its dimension
  InvalidTag,         // tags must be > 0
  TooFewPoints,       // e.g. a line with one point
  SelfReference,      // a curve using the same point twice in a row (zero-length piece)
  CoincidentPoints,   // arc end points coincide with the centre, ...
  NotCocircular,      // circle start/end radii differ by more than Gmsh's 10%
  DegenerateArc,      // arc/ellipse whose plane or axes cannot be determined
  LoopNotClosed,      // a curve loop that does not close or is not in order
  LoopEmpty,
  HoleOutside,        // a hole of a plane surface is not inside its outer loop
  SharedBoundary,     // a hole shares a curve with the outer loop or another hole
  BadArgument,        // anything else malformed (wrong counts, zero axis, ...)
};

/// One message shape of a geometry error (geo/error_ids.def says which values it states).
enum class GeoErrorId {
#define SM_GEO_ERROR(id, kind) id,
#include "geo/error_ids.def"
#undef SM_GEO_ERROR
};

/// The kind a shape belongs to.
GeoErrorKind kind_of(GeoErrorId id);

const char* to_string(GeoErrorKind k);

/// What a tag in an error names (the first four are Gmsh's entity dimensions).
enum class EntityKind {
  Point = 0, Curve = 1, Surface = 2, Volume = 3, CurveLoop, SurfaceGeometry, Physical, SurfaceLoop, None
};

const char* to_string(EntityKind k);

struct GeoError {
  GeoErrorId id = GeoErrorId::RotationAxisZero;
  GeoErrorKind kind = GeoErrorKind::BadArgument;   // kind_of(id)
  EntityKind entity = EntityKind::None;   // what tags[0] is
  std::vector<int> tags;                  // that entity first, then others involved (signed for curves)
  std::vector<int> ids;                   // other integers the message states (points, counts, dimensions)
  std::vector<double> numbers;            // measured or given values (radii, angles, sizes)
  std::vector<std::string> words;         // kernel names the message states (a curve's kind, a role)
};

/// Kernel words for code that cannot reach the diagnostic table: the kind's name, the
/// entity and the tags ("loop-not-closed: curve loop 3 (3, 7)"). The script's user reads
/// the interpreter's sentence instead.
std::string summary(const GeoError& e);

/// Either a value or a GeoError: the kernel's return type for operations that can fail.
template <class T>
class GeoResult {
 public:
  GeoResult(T value) : v_(std::move(value)) {}                // NOLINT: implicit on purpose
  GeoResult(GeoError error) : v_(std::move(error)) {}         // NOLINT
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<0>(v_); }
  const T& value() const { return std::get<0>(v_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const GeoError& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, GeoError> v_;
};

/// Success or a GeoError, for operations without a value.
class GeoStatus {
 public:
  GeoStatus() = default;
  GeoStatus(GeoError error) : ok_(false), error_(std::move(error)) {}   // NOLINT
  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const GeoError& error() const { return error_; }

 private:
  bool ok_ = true;
  GeoError error_;
};

GeoError make_error(GeoErrorId id, EntityKind entity, std::vector<int> tags, std::vector<int> ids = {},
                    std::vector<double> numbers = {}, std::vector<std::string> words = {});

}  // namespace sm::geo
