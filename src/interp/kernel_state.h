// What a script builds in the kernel: the geometry model, the size-field
// definitions, coastline import definitions, and where each entity came from
// (so that kernel errors, which carry tags, point at script lines). The
// interpreter owns one; each builtins family (geometry.cpp, fields.cpp,
// coastline.cpp, mesh_commands.cpp) fills its part.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "base/progress.h"
#include "field/field_set.h"
#include "geo/model.h"
#include "interp/stage_clock.h"
#include "interp/value.h"
#include "lang/source.h"
#include "io/mesh_partition.h"
#include "mesh/discrete_mesh.h"
#include "mesh/mesh_constraints.h"
#include "mesh/model_mesh.h"

namespace sm::interp {

/// The entities one coastline import created (kernel/coastline.cpp).
struct CoastlineImport;

/// `Coastline[n] = Format; Coastline[n].Option = value;` (native extension),
/// kept as written until `Coastline{n}` imports it.
struct CoastlineDef {
  std::string format;                                   // GSHHS, Shapefile, LonLatText, Loops2
  std::map<std::string, Value, std::less<>> options;    // as set by the script
  std::map<std::string, lang::SourceRange, std::less<>> option_at;
  lang::SourceRange defined_at;
  /// Set by the first `Coastline{n}`: the entities the import created (coastline.cpp).
  std::shared_ptr<const CoastlineImport> imported;
};

/// Fields built for FieldValue/FieldArgmin (kernel/field_eval.cpp).
struct FieldCache;

struct KernelState {
  geo::Model model;
  /// `Transfinite ...;` and `Recombine ...;` as set so far (kernel/mesh_constraints.cpp);
  /// Mesh.RecombineAll and Mesh.RecombinationAlgorithm are added when meshing.
  MeshConstraints constraints;
  /// The discrete entities of merged mesh files (kernel/merge.cpp): their surfaces'
  /// elements, and which node tags the model's discrete points and curves stand on.
  DiscreteEntities discrete;
  field::FieldSet fields;
  std::optional<int> background_field;                  // `Background Field = n;`
  std::map<int, lang::SourceRange> field_defined_at;    // Field[n] = ... statement
  lang::SourceRange background_field_at;                 // the `Background Field = n;` statement
  /// `BoundaryLayer Field = n;` (or a list): each field id with its statement, in order
  /// (Gmsh adds them up; an id named again is kept once).
  std::vector<std::pair<int, lang::SourceRange>> boundary_layer_fields;
  /// (field id, canonical option name) -> the `Field[n].Option = v;` statement that set it.
  std::map<std::pair<int, std::string>, lang::SourceRange> field_option_at;
  std::shared_ptr<FieldCache> field_cache;               // dropped when a Field statement runs
  /// The field builds' gmsh-compat notes already reported (field, option, entity, tag): a
  /// field is built again for the mesher (with the 1D mesh nodes) and must not warn twice.
  std::set<std::string> field_compat_reported;
  std::map<int, CoastlineDef> coastlines;
  /// `Plugin(GSHHS).Option = value;` as set so far (plugin_gshhs.cpp), name -> value.
  std::map<std::string, Value, std::less<>> gshhs_plugin_options;
  /// Option name (canonical) -> the last assignment that set it, for errors found when
  /// the option is used (Mesh.DepthField naming a field that was never defined).
  std::map<std::string, lang::SourceRange, std::less<>> option_set_at;
  /// (dim, tag) -> the statement that created the entity (provenance).
  std::map<std::pair<int, int>, lang::SourceRange> created_at;
  /// The mesh of the last `Mesh n;` (kernel/mesh_commands.cpp), what `Save` writes.
  std::shared_ptr<const ModelMesh> mesh;
  /// Mesh.NbPartitions' partition of `mesh`, made when it was meshed; null without.
  std::shared_ptr<const io::MeshPartition> partition;
  io::MeshPartitionOptions partition_options;   ///< what `partition` was made with
  /// Statistics of the last `Mesh 2;` (for `--stats FILE.json` and the end of the run's
  /// account, mesh_commands.h); has_mesh_stats is false before.
  MeshStats mesh_stats;
  bool has_mesh_stats = false;
  /// The 1D figures of the last `Mesh 1;` (or -1), when that was the last mesh made;
  /// has_curve_stats and has_mesh_stats are never both true.
  CurveStats curve_stats;
  bool has_curve_stats = false;
  /// Where the run's wall time went (interp/stage_clock.h): the script's evaluation, the
  /// import, the field set-up by kind, 1D, 2D, the statistics, the writing. Mutable:
  /// building fields from a const state still spends time that the account charges.
  mutable StageClock clock;
  /// The 2D mesher's own stages (boundary, refine, ...) summed over the run's `Mesh 2`s:
  /// the account shows them in place of its one "2D" stage.
  std::vector<StageTime> mesh2d_parts;
  /// Where long kernel stages report (the CLI's stderr display); null: nobody listens.
  /// Kernel calls take it through progress_sink() (interp/progress_sink.h).
  Progress* progress = nullptr;
};

}  // namespace sm::interp
