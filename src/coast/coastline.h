// The neutral coastline structure every reader returns (paper section 2.2), and the
// typed error the coast kernel reports instead of printing or aborting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "geo/sphere.h"

namespace sm::coast {

/// One shoreline ring or polyline in geographic degrees.
/// - closed rings do NOT repeat their first point;
/// - longitudes are contiguous (consecutive points never differ by more than 180 degrees),
///   so a ring that crosses the dateline runs past +-180;
/// - wraps_pole: a closed ring round a pole (Antarctica), closed on the sphere only: its
///   longitudes wind by +-360 degrees from the last point back to the first.
struct Ring {
  std::vector<geo::LonLat> pts;
  std::int64_t id = -1;            // id in the source (GSHHS id, segment number, shape id)
  int level = 1;                   // GSHHS level: 1 land, 2 lake, 3 island in lake, ... 5/6 Antarctica
  bool closed = true;
  bool wraps_pole = false;
  std::size_t record = 0;          // 0-based record / segment / shape index in the file
  int part = 0;                    // part index inside a multi-part shapefile record
  double area_km2 = std::numeric_limits<double>::quiet_NaN();  // from the file when it says
};

/// A lon/lat box in degrees: lon range may run past +-180 (west < east always).
struct LonLatBox {
  double west = -180, east = 180, south = -90, north = 90;
};

struct Coastline {
  std::string file;
  std::vector<Ring> rings;
  /// The region the data was cut to, when the file says (GMT -R in the text header).
  std::optional<LonLatBox> region;
};

/// A located error: file (or stage), record, and where on the Earth when known.
struct CoastError {
  std::string file;
  std::int64_t record = -1;        // -1: not tied to one record
  std::string message;
  std::optional<geo::LonLat> where;
  /// The import option at fault ("Dams", "SeaAt"), so that the interpreter can point at
  /// the line that set it; empty for errors of the data.
  std::string option = {};

  std::string to_string() const;
};

/// Either a value or a CoastError (no exceptions cross the kernel boundary).
template <class T>
class Result {
 public:
  Result(T value) : v_(std::move(value)) {}                 // NOLINT: implicit on purpose
  Result(CoastError err) : v_(std::move(err)) {}            // NOLINT
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<0>(v_); }
  const T& value() const { return std::get<0>(v_); }
  T& operator*() { return value(); }
  T* operator->() { return &value(); }
  const CoastError& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, CoastError> v_;
};

/// Longitude difference b - a wrapped to (-180, 180].
double wrap_delta(double a, double b);
/// Make a ring's longitudes contiguous (each step wrapped into (-180, 180]) and shift the
/// whole ring by a multiple of 360 so its mid-longitude lies in [-180, 180).
void unwrap_longitudes(std::vector<geo::LonLat>& pts);
/// Total longitude winding of a closed ring, closing edge included (0 or +-360 degrees).
double longitude_winding(const std::vector<geo::LonLat>& pts);
/// True when a and b are the same point of the sphere (lon taken modulo 360; poles).
bool same_point(geo::LonLat a, geo::LonLat b);
/// Turns raw point lists into the Ring convention: unwraps longitudes, drops a repeated
/// closing point of a closed ring, and sets wraps_pole from the winding.
void normalise_ring(Ring& r);

}  // namespace sm::coast
