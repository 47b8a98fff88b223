// Every formula of the sphere (paper section 2.1, docs/geometry.md): Gmsh's
// PolarSphere map, the paper's plane stereographic projection, the lon/lat Sphere map,
// conformal factors, metrics, and GeographicLib distances / geocentric conversions.
#pragma once

#include "base/vec.h"
#include "geo/jet.h"

namespace sm::geo {

/// Geographic coordinates in degrees.
struct LonLat {
  double lon = 0, lat = 0;
};

/// Metres: the mean Earth radius used by Gmsh's old Plugin(GSHHS) ("radius" option).
inline constexpr double kEarthRadius = 6371009.0;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

/// Symmetric 2x2 metric tensor M = J^T J of a parametrisation: |dX|^2 = du^T M du.
struct Metric2 {
  double a = 0, b = 0, c = 0;  // [[a, b], [b, c]]
};

/// Second derivatives of a surface map at one (u,v).
struct SecondDerivs {
  Vec3 uu, uv, vv;
};

/// Gmsh's PolarSphere map (docs/geometry.md): stereographic projection from the SOUTH
/// pole of the sphere onto its equatorial plane, scaled to the unit sphere and rotated by
/// 180 degrees about the polar axis (the sign flip):
///   X(u,v) = o + r (-2u, -2v, 1 - u^2 - v^2) / (1 + u^2 + v^2)
/// The north pole (0,0,r) maps to (0,0), the equator to the unit circle, the south pole
/// (the single singular point) to infinity. Conformal with factor lambda = 2r/(1+u^2+v^2).
class PolarSphere {
 public:
  PolarSphere(Vec3 centre, double radius);

  Vec3 centre() const { return centre_; }
  double radius() const { return radius_; }

  Vec3 point(Vec2 uv) const;
  /// Inverse map; x is first projected radially onto the sphere. The centre itself and the
  /// south pole have no parameter: they give NaN/inf components.
  Vec2 param(Vec3 x) const;
  /// Conformal factor: |dX| = lambda |du|.
  double lambda(Vec2 uv) const;
  void tangents(Vec2 uv, Vec3& du, Vec3& dv) const;
  SecondDerivs second_derivatives(Vec2 uv) const;
  /// A curve (u(t), v(t)) with its derivatives mapped to the sphere (chain rule), computing
  /// the map's derivatives once: the hot path of coastline evaluation.
  Jet3 map(const Jet2& c) const;
  /// M = lambda^2 I (conformal).
  Metric2 metric(Vec2 uv) const;
  /// Outward unit normal at X(u,v).
  Vec3 normal(Vec2 uv) const;

  /// Spherical (not ellipsoidal) lon/lat in degrees relative to this sphere's centre, with
  /// the sphere's axis as the polar axis: X = o + r(cos lat cos lon, cos lat sin lon, sin lat).
  Vec3 from_lonlat(LonLat ll) const;
  /// Longitude in (-180, 180], latitude from the direction of x - o (any distance from o).
  LonLat to_lonlat(Vec3 x) const;
  Vec2 param_from_lonlat(LonLat ll) const;
  LonLat lonlat_from_param(Vec2 uv) const;

  /// The singular point of the map (the south pole o - r e_z).
  Vec3 singular_point() const { return centre_ + Vec3{0, 0, -radius_}; }

 private:
  Vec3 centre_;
  double radius_;
};

/// The paper's own stereographic convention (section 2.1): projection from the south pole
/// onto the tangent plane z = R at the north pole, no sign flip, metric scaling:
///   xi = 2R x/(R+z), eta = 2R y/(R+z);   X = 4R^2 (xi, eta, R(4R^2 - rho^2)/(4R^2)) / (4R^2 + rho^2)
/// (the paper's printed inverse has a typo in the z component; this is the exact inverse).
/// This is what Gmsh's LonLat field calls FromStereo=1 and Plugin(GSHHS) WritePolarSphere=-2.
/// Relation to PolarSphere of the same radius centred at the origin:
///   (xi, eta) = -2R (u, v),   lambda_plane = lambda_polar / (2R) = 4R^2 / (4R^2 + rho^2).
class StereoPlane {
 public:
  explicit StereoPlane(double radius);

  double radius() const { return radius_; }
  Vec3 point(Vec2 xi) const;
  Vec2 param(Vec3 x) const;  // x projected radially onto the sphere first
  double lambda(Vec2 xi) const;
  void tangents(Vec2 xi, Vec3& dxi, Vec3& deta) const;

  /// Conversions between the two stereographic conventions (same radius).
  Vec2 from_polar(Vec2 uv) const { return -2.0 * radius_ * uv; }
  Vec2 to_polar(Vec2 xi) const { return xi / (-2.0 * radius_); }

 private:
  double radius_;
};

/// Gmsh's lon/lat Sphere geometry (docs/geometry.md), parameters (lon, lat) in RADIANS:
///   X = c + r (cos lat cos lon, cos lat sin lon, sin lat).
/// Not conformal: M = J^T J = diag(r^2 cos^2 lat, r^2); singular at both poles.
class Sphere {
 public:
  Sphere(Vec3 centre, double radius);

  Vec3 centre() const { return centre_; }
  double radius() const { return radius_; }
  Vec3 point(Vec2 lonlat_rad) const;
  /// Inverse, lon in (-pi, pi], lat in [-pi/2, pi/2].
  Vec2 param(Vec3 x) const;
  void tangents(Vec2 lonlat_rad, Vec3& dlon, Vec3& dlat) const;
  SecondDerivs second_derivatives(Vec2 lonlat_rad) const;
  Metric2 metric(Vec2 lonlat_rad) const;

 private:
  Vec3 centre_;
  double radius_;
};

/// Great-circle distance on a sphere of the given radius (same units as radius); the
/// atan2 form, accurate for antipodal and very close points alike.
double great_circle_distance(LonLat a, LonLat b, double radius);
/// Geodesic distance on the WGS84 ellipsoid in metres (GeographicLib, Karney's algorithm).
double geodesic_distance_wgs84(LonLat a, LonLat b);
/// Geodesic distance on a sphere through GeographicLib (flattening 0): used to check
/// great_circle_distance independently.
double geodesic_distance_sphere(LonLat a, LonLat b, double radius);

/// Geodetic lon/lat (degrees) and height (m) on WGS84 <-> Earth-centred Earth-fixed XYZ (m).
Vec3 geocentric_wgs84(LonLat ll, double height = 0);
LonLat geodetic_wgs84(Vec3 ecef, double* height = nullptr);

/// Spherical lon/lat on the sphere of radius `radius` centred at the origin: the convention
/// of Plugin(GSHHS) and of every .geo coastline script (data lon/lat are used as spherical).
Vec3 sphere_from_lonlat(LonLat ll, double radius);
LonLat lonlat_from_sphere(Vec3 x);

}  // namespace sm::geo
