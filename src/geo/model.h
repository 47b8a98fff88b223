// The boundary representation (paper section 2): model vertices, curves, curve loops, plane
// surfaces, surface geometries (PolarSphere, lon/lat Sphere), physical groups, with Gmsh
// 4.8.4's tag rules. The interpreter fills it statement by statement; the mesher reads it.
#pragma once

#include "geo/curve.h"
#include "geo/error.h"
#include "geo/extrude.h"
#include "geo/surface_filling.h"
#include "geo/surface_geometry.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sm::geo {

/// Gmsh's "no prescribed size" (MAX_LC): a missing or zero lc.
inline constexpr double kMaxLc = 1e22;

struct ModelVertex {
  int tag = 0;
  Vec3 xyz;            // position in space (on the geometry when geometry != 0)
  int geometry = 0;    // surface geometry tag the point was defined on, 0: Euclidean
  Vec2 uv;             // its parameters on that geometry
  double lc = kMaxLc;  // prescribed mesh size
};

struct ModelCurve {
  int tag = 0;
  CurveKind kind = CurveKind::Line;
  std::vector<int> points;            // control vertex tags, as written
  std::optional<Vec3> plane_normal;   // Circle/Ellipse Plane{} clause
  int geometry = 0;                   // all control points on this geometry (else 0)
  int begin = 0, end = 0;             // bounding vertices (first / last control point)
  std::optional<Curve> shape;         // the evaluator, rebuilt whenever a point moves
  /// A discrete curve (`Merge` of a mesh file: Gmsh's discreteEdge): a polyline through
  /// its mesh nodes, begin, `inner`, end, whose mesh is those nodes (never remeshed).
  bool discrete = false;
  std::vector<Vec3> inner;
  /// A discrete curve given a geometry by `CreateGeometry;` (Gmsh's discreteEdge with its
  /// parametrisation): the same polyline, now meshed by the 1D mesher as any curve.
  bool has_geometry = false;

  bool periodic() const { return begin == end; }
};

struct ModelCurveLoop {
  int tag = 0;
  std::vector<int> curves;   // signed curve tags, in chained order
  bool reordered = false;    // Gmsh-style reordering changed the written order
  /// Gmsh 4.8.4 creates a curve loop without checking that it closes (Geo/Geo.cpp's
  /// SortEdgesInLoop stops when it has placed every curve): such a loop is kept, as
  /// written, with why it does not close; a surface bounded by it is that error.
  std::optional<GeoError> unclosed;
};

struct ModelSurface {
  int tag = 0;
  bool filling = false;              // "Surface" (transfinite patch) rather than "Plane Surface"
  int sphere_centre = 0;             // filling: "In Sphere{c}" point tag, 0 if none
  std::vector<int> loops;            // signed loop tags: [0] outer boundary, then holes
  std::size_t listed_outer = 0;      // where the script listed loops[0] (see add_plane_surface)
  int geometry = 0;                  // parametric on this surface geometry (0: planar)
  std::vector<int> embedded_points;  // Point{...} In Surface{tag}
  std::vector<int> embedded_curves;  // Curve{...} In Surface{tag}
};

/// "Surface Loop(t) = {surfaces};"
struct ModelSurfaceLoop {
  int tag = 0;
  std::vector<int> surfaces;   // signed surface tags as written
};

/// "Volume(t) = {surface loops};" or a volume swept by Extrude (surfaces: its boundary,
/// signed by orientation, as Gmsh lists it; loops empty).
struct ModelVolume {
  int tag = 0;
  std::vector<int> loops;
  std::vector<int> surfaces;
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;   // signed for curves/surfaces (orientation in MSH 2)
};

struct DimTag {
  int dim = 0;
  int tag = 0;   // signed for curves where orientation matters
  friend bool operator==(DimTag a, DimTag b) { return a.dim == b.dim && a.tag == b.tag; }
};

struct BoundingBox {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  bool empty() const { return lo.x > hi.x; }
  double diagonal() const { return empty() ? 0.0 : norm(hi - lo); }
  void add(Vec3 p);
};

/// Geometry.* options the kernel needs (plain data: the interpreter copies them in).
struct ModelOptions {
  double tolerance = 1e-8;     // Geometry.Tolerance: relative to the bounding box diagonal
  bool old_new_reg = true;     // Geometry.OldNewReg: newl/newc/newll/news return newreg
  bool auto_coherence = true;  // Geometry.AutoCoherence: Coherence after every transform
  bool old_ruled_surface = false;  // Geometry.OldRuledSurface: Gmsh's old 3-sided patch
};

enum class PhysicalOp { Assign, Add, Remove };

class Model {
 public:
  ModelOptions& options() { return options_; }
  const ModelOptions& options() const { return options_; }

  // ---- surface geometries ("PolarSphere(g) = {c, p};", "Sphere(g) = {c, p};") ----
  /// Radius |p - c|; both points must exist and be Euclidean. Makes g the current geometry.
  GeoStatus add_polar_sphere(int tag, int centre_point, int pole_point);
  GeoStatus add_lonlat_sphere(int tag, int centre_point, int pole_point);
  /// "Coordinates Surface g;"
  GeoStatus set_current_geometry(int tag);
  /// "Euclidian Coordinates;"
  void set_euclidean() {
    current_geometry_ = 0;
    touch();
  }
  int current_geometry() const { return current_geometry_; }
  const SurfaceGeometry* geometry(int tag) const;
  const std::map<int, SurfaceGeometry>& geometries() const { return geometries_; }

  // ---- entities ----
  /// "Point(t) = {x, y, z, lc};": with a current geometry, (x, y) are its (u, v) and z is
  /// ignored. lc <= 0 means no size (kMaxLc).
  GeoStatus add_point(int tag, Vec3 coords, double lc = 0);
  GeoStatus add_point_on_geometry(int tag, int geometry, Vec2 uv, double lc = 0);
  /// Line, Spline, BSpline, Bezier (>= 2 points), Circle (3), Ellipse (3 or 4).
  GeoStatus add_curve(int tag, CurveKind kind, const std::vector<int>& points,
                      std::optional<Vec3> plane_normal = std::nullopt);
  /// A discrete curve (ModelCurve::discrete) from point `begin` through `inner` to point
  /// `end` (the mesh nodes of a merged file's curve, in order; begin == end: closed).
  GeoStatus add_discrete_curve(int tag, int begin, int end, std::vector<Vec3> inner);
  /// `CreateGeometry;` on discrete curve `tag`: its polyline becomes its geometry
  /// (ModelCurve::has_geometry), so that the 1D mesher remeshes it.
  GeoStatus give_geometry_to_discrete_curve(int tag);
  /// `CreateGeometry;` on a flat discrete surface: plane surface `tag` bounded by `loops`
  /// (each a closed chain of discrete curves, in any order and orientation: the surface's
  /// mesh boundary), held in loops of hidden tags as a duplicated surface's are; the
  /// enclosing loop becomes the outer one as in add_plane_surface.
  GeoStatus add_surface_of_discrete_mesh(int tag, const std::vector<std::vector<int>>& loops);
  /// "Curve Loop(t) = {...};": must close; reordered as Gmsh does when the signs are
  /// consistent; a loop may hold several closed chains (Gmsh's "subloops").
  GeoStatus add_curve_loop(int tag, const std::vector<int>& curves);
  /// "Plane Surface(t) = {outer, holes...};": every hole inside the outer loop, no curve
  /// shared between loops; parametric on a geometry when all boundary curves lie on it.
  GeoStatus add_plane_surface(int tag, const std::vector<int>& loops);
  /// "Surface(t) = {loop} <In Sphere{c}>;": a transfinite patch on a loop of 3 or 4 curves.
  /// On a surface geometry (all its curves on it) it is parametrised by that geometry, as
  /// in Gmsh.
  GeoStatus add_surface_filling(int tag, const std::vector<int>& loops,
                                std::optional<int> sphere_centre = std::nullopt);
  /// The point at (u,v) of a filling surface or of a surface on a geometry.
  GeoResult<Vec3> surface_point(int tag, Vec2 uv) const;
  /// The transfinite patch of filling surface `s` (its first loop, Gmsh's sphere guess
  /// when no "In Sphere" is given): valid while the model's curves are unchanged.
  TransfinitePatch filling_patch(const ModelSurface& s) const;
  /// Where curve `curve` meets the filling surface `surface`: the curve's parameter, or
  /// nothing when Gmsh's search (Newton from u = v = t = 0.5, Geo/Geo.cpp's
  /// IntersectCurvesWithSurface) does not converge.
  GeoResult<std::optional<double>> intersect_curve_surface(int curve, int surface) const;
  /// "Surface Loop(t) = {...};" (every surface must exist) and "Volume(t) = {loops};" (every
  /// loop must exist): kept so that scripts evaluate; nothing meshes volumes (geo/extrude.cpp).
  GeoStatus add_surface_loop(int tag, const std::vector<int>& surfaces);
  GeoStatus add_volume(int tag, const std::vector<int>& loops);
  /// "Extrude {...} {entities}" as Gmsh 4.8.4 does it (geo/extrude.cpp): per entity its top,
  /// then with a body its body and lateral entities (spec.return_lateral); tags signed.
  GeoResult<std::vector<DimTag>> extrude(const std::vector<DimTag>& entities, const ExtrudeSpec& spec);
  /// The extrusion record of (dim, tag), or null.
  const Extrusion* extrusion(int dim, int tag) const;
  const std::map<int, ModelVolume>& volumes() const { return volumes_; }
  const std::map<int, ModelSurfaceLoop>& surface_loops() const { return surface_loops_; }
  /// "Physical Point|Curve|Surface(tag | "name" | "name", tag) =|+=|-= {...};". Returns
  /// the group's tag (Gmsh's auto-tag: 1 + the largest physical tag, all dimensions).
  GeoResult<int> add_physical(int dim, std::optional<int> tag, const std::string& name,
                              const std::vector<int>& entities, PhysicalOp op = PhysicalOp::Assign);
  /// "Delete Physicals;": every group goes; newreg and the next auto tag keep counting from
  /// the largest physical tag used so far, as in Gmsh.
  void clear_physicals() {
    physicals_.clear();
    touch();
  }
  /// "Point{...} In Surface{s};" (dim 0) and "Curve{...} In Surface{s};" (dim 1).
  GeoStatus embed(int dim, const std::vector<int>& tags, int surface);
  /// "MeshSize{points} = lc;"
  GeoStatus set_mesh_size(const std::vector<int>& points, double lc);

  // ---- editing ----
  /// "<Recursive> Delete {...}": an entity used by a higher-dimensional one is skipped
  /// (returned in `skipped`), as in Gmsh; Recursive also deletes the sub-entities that are
  /// no longer used.
  GeoStatus remove(const std::vector<DimTag>& entities, bool recursive, std::vector<DimTag>* skipped = nullptr);
  /// "Coherence;": merges points closer than tolerance x bounding-box diagonal (the lowest
  /// tag survives), then curves with the same kind and control points. Returns the number
  /// of entities merged.
  int coherence(std::map<int, int>* curves_merged = nullptr);
  /// "Duplicata{...}": copies with new tags taken in Gmsh's order (see model_edit.cpp),
  /// sharing copied points between copied curves; a missing entity is skipped with a
  /// compat note. Returns the new entities; `copied`, when given, receives (dim, source
  /// tag, copy tag) of every curve and surface made, the curves of copied surfaces too
  /// (what Geometry.CopyMeshingMethod copies the meshing constraints along).
  GeoResult<std::vector<DimTag>> duplicate(const std::vector<DimTag>& entities,
                                           std::vector<std::array<int, 3>>* copied = nullptr);
  GeoStatus translate(const std::vector<DimTag>& entities, Vec3 d);
  GeoStatus rotate(const std::vector<DimTag>& entities, Vec3 axis, Vec3 point, double angle);
  GeoStatus dilate(const std::vector<DimTag>& entities, Vec3 centre, Vec3 factors);
  /// Mirror in the plane a x + b y + c z + d = 0.
  GeoStatus symmetry(const std::vector<DimTag>& entities, double a, double b, double c, double d);
  /// "Split Curve{c} Point{...};": pieces between the listed control points (others are
  /// skipped with a compat note, as Gmsh skips them); a closed curve's pieces start at the
  /// first listed point met after its start point, in the curve's order. The curve is
  /// replaced by its pieces, also inside curve loops. Returns the new curve tags.
  GeoResult<std::vector<int>> split_curve(int curve, const std::vector<int>& points);

  // ---- queries ----
  /// "Boundary{...}" (combined = false) / "CombinedBoundary{...}" (shared entities cancel).
  GeoResult<std::vector<DimTag>> boundary(const std::vector<DimTag>& entities, bool combined) const;
  std::vector<int> tags(int dim) const;   // "Point{:}", "Curve{:}", "Surface{:}"
  /// "Point|Curve|Surface In BoundingBox{xmin, ymin, zmin, xmax, ymax, zmax}": entities
  /// whose bounding box lies inside (bounds included).
  std::vector<int> in_bounding_box(int dim, Vec3 lo, Vec3 hi) const;
  /// Bounding box of a curve (sampled 16 times per polynomial piece) or of a surface's
  /// boundary curves; empty for unknown tags.
  BoundingBox curve_bounding_box(int tag) const;
  BoundingBox surface_bounding_box(int tag) const;
  std::vector<int> loop_tags() const;
  BoundingBox bounding_box() const;

  const ModelVertex* vertex(int tag) const;
  const ModelCurve* curve(int tag) const;   // tag > 0
  const ModelCurveLoop* curve_loop(int tag) const;
  const ModelSurface* surface(int tag) const;
  const PhysicalGroup* physical(int dim, int tag) const;
  /// "Physical Curve{t}" as Gmsh 4.8.4 answers it: the group's entity tags without their
  /// orientation signs (the group keeps the signs for MSH 2 output); empty if no such group.
  /// A group keeps the tags of deleted entities (an entity made again with the tag is in it
  /// again, as in Gmsh); only the existing ones are listed here.
  std::vector<int> physical_entities(int dim, int tag) const;
  /// Whether the entity (dim 0..3, tag > 0) exists.
  bool has(int dim, int tag) const;
  const std::map<int, ModelVertex>& vertices() const { return vertices_; }
  const std::map<int, ModelCurve>& curves() const { return curves_; }
  const std::map<int, ModelCurveLoop>& curve_loops() const { return loops_; }
  const std::map<int, ModelSurface>& surfaces() const { return surfaces_; }
  const std::map<std::pair<int, int>, PhysicalGroup>& physicals() const { return physicals_; }
  /// Changes whenever an entity, geometry or group is added, moved or removed, and two
  /// different states never share a value (copies of one state do): what is built from
  /// the model (size fields) is cached by it instead of hashing the model on each use.
  std::uint64_t revision() const { return revision_; }

  // ---- Gmsh's next-tag variables ----
  int new_point_tag() const { return max_tag_[0] + 1; }                           // newp
  int new_curve_tag() const;                                                    // newl, newc
  int new_loop_tag() const;                                                     // newll
  int new_surface_tag() const;                                                  // news
  int new_reg() const;                                                          // newreg
  int new_surface_loop_tag() const { return max_tag_[kSurfaceLoopSlot] + 1; }   // newsl (OldNewReg 0)
  int new_volume_tag() const { return max_tag_[3] + 1; }                        // newv (OldNewReg 0)
  /// "SetMaxTag Point(n);" etc. (dim 0..3; -1: curve loops).
  void set_max_tag(int dim, int tag);

  // ---- Gmsh-compatible leniencies ----
  /// Where Gmsh accepts a statement that is wrong on its face (a hole listed before its
  /// outer loop, tag 0, a split at a point that is not on the curve...) the kernel does
  /// what Gmsh does and leaves a sentence saying what Gmsh does and what was done; the
  /// interpreter words each (interp/geo_diagnostic.cpp) as a located gmsh-compat warning.
  /// Taking them empties the list. A curve loop that does not close is kept unchecked, as
  /// Gmsh does: its note carries the loop's error.
  enum class CompatNoteId {
    UncheckedLoop,           // unchecked_loop
    TagZero,                 // word: the entity's kind
    MeshSizeOfMissingPoint,  // tags: the point
    LineToItself,            // tags: the line, its point
    EllipseAxisAtCentre,     // tags: the ellipse, the major-axis point, the start point
    ZeroLengthCurve,         // word: the curve's kind; tags: the curve, its begin and end points
    OuterListedLater,        // tags: the surface, the enclosing loop, the loop listed first
    HoleCrossesOuter,        // tags: the surface, the hole's loop, the outer loop
    ExtrudeClosedCurve,      // tags: the curve
    DuplicataOfMissing,      // word: the entity's kind; tags: its tag
    SplitAtOtherPoint,       // tags: the curve, the point
    DiscreteLoopReoriented,  // tags: the loop, the first curve reversed
  };
  struct CompatNote {
    CompatNoteId id = CompatNoteId::UncheckedLoop;
    std::vector<int> tags;
    std::string word;
    std::optional<GeoError> unchecked_loop;
  };
  std::vector<CompatNote> take_compat_notes() { return std::exchange(compat_notes_, {}); }

 private:
  GeoStatus add_sphere_geometry(int tag, int centre_point, int pole_point, bool polar);
  GeoStatus check_new_tag(EntityKind kind, int tag, bool exists);   // notes a tag 0 it accepts
  GeoResult<Curve> build_shape(const ModelCurve& c) const;
  GeoStatus rebuild_curves_using(const std::vector<int>& moved_points);
  void bump_max(int slot, int tag);
  void on_delete(int slot, int tag);
  std::vector<int> points_of(const std::vector<DimTag>& entities) const;
  GeoStatus transform_points(const std::vector<DimTag>& entities, const std::array<double, 12>& m);
  // How many higher-dimensional references each point, curve and loop has: built once per
  // Delete so that deleting a large model stays O(n log n).
  struct Usage {
    std::map<int, int> point, curve, loop;
  };
  Usage usage() const;
  bool curve_on_surface(const Usage& u, int tag) const;
  void delete_point(int tag);
  void delete_curve(int tag, bool recursive, Usage& u);
  void delete_loop(int tag, bool recursive, Usage& u);
  void delete_surface(int tag, bool recursive, Usage& u);
  void touch();   // a new revision_ from one counter shared by all models
  void note_compat(CompatNoteId id, std::vector<int> tags, std::string word = {}) {
    compat_notes_.push_back({id, std::move(tags), std::move(word), std::nullopt});
  }

  ModelOptions options_;
  std::map<int, ModelVertex> vertices_;
  std::map<int, ModelCurve> curves_;
  std::map<int, ModelCurveLoop> loops_;
  std::map<int, ModelSurface> surfaces_;
  std::map<int, SurfaceGeometry> geometries_;
  std::map<int, ModelSurfaceLoop> surface_loops_;
  std::map<int, ModelVolume> volumes_;
  std::map<std::pair<int, int>, Extrusion> extrusions_;   // (dim, tag) -> how Extrude made it
  // geo/extrude.cpp
  GeoResult<int> extrude_point_entity(int p, const ExtrudeSpec& spec, int* body);
  GeoResult<int> extrude_curve_entity(int c, const ExtrudeSpec& spec, bool final, int* body);
  GeoResult<int> extrude_surface_entity(int s, const ExtrudeSpec& spec, int* volume);
  GeoStatus transform_by(const std::vector<DimTag>& entities, const ExtrudeSpec& spec);
  std::map<std::pair<int, int>, PhysicalGroup> physicals_;   // (dim, tag)
  int current_geometry_ = 0;
  // High-water marks as Gmsh keeps them: slots 0..3 = dims, kLoopSlot = curve loops.
  static constexpr int kLoopSlot = 4;
  static constexpr int kSurfaceLoopSlot = 5;
  std::array<int, 6> max_tag_{0, 0, 0, 0, 0, 0};
  int max_physical_tag_ = 0;   // high-water mark of physical group tags (newreg, auto tags)
  std::uint64_t revision_ = 0;  // 0: the empty model
  std::vector<CompatNote> compat_notes_;   // see take_compat_notes()
  int hidden_loop_tag_ = 0;   // loops of duplicated surfaces: counted down from INT_MAX (see duplicate())
  bool duplicate_took_spare_points_ = false;   // see coherence()
};

/// A curve Gmsh collapses: between two distinct points at the same place (within
/// Geometry.Tolerance), with every control point there too (a zero-length Line, a Spline or B-spline of repeated
/// points). Circles and ellipses never do. The 1D mesh gives it one node and no edge.
bool collapses(const Model& m, const ModelCurve& c);

}  // namespace sm::geo
