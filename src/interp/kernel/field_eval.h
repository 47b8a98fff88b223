// Building the script's size fields from the interpreter: located diagnostics
// for kernel field errors, the FieldValue/FieldArgmin cache, and the
// Background Field the mesher asks for.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/vec.h"
#include "field/depth_clamp.h"
#include "field/error.h"
#include "interp/kernel/field_context.h"
#include "interp/options.h"
#include "field/field_set.h"
#include "lang/source.h"

namespace sm::io {
struct MeshModel;
}

namespace sm::interp {

class Interpreter;
struct KernelState;

/// make_build_context on the kernel's model, with what only the interpreter knows
/// (the curves of each imported coastline).
field::BuildContext kernel_build_context(const KernelState& k, const CurveMeshNodes* mesh_nodes);

/// Reports a kernel field error as a runtime error located at `at`, with notes
/// at the `Field[n] = ...` and `Field[n].Option = ...` statements involved
/// (every field of a cycle, the option naming a missing field, ...).
[[noreturn]] void fail_field_error(Interpreter& in, const field::FieldError& e, lang::SourceRange at);

/// A field option's type as the diagnostics name it: 'a number', 'a string', 'a list in braces'.
std::string_view option_type_phrase(field::OptionType t);

/// Field `root` and every field it references, built from the current
/// definitions and model. Cached until a Field statement runs or the model
/// changes; build errors are reported at `use`.
const field::BuiltFields& built_fields(Interpreter& in, int root, lang::SourceRange use);

/// Drops every cached build (each Field statement calls it).
void invalidate_field_cache(Interpreter& in);

/// The size field of `Background Field = n;` for the mesher, or nullptr when
/// there is none (no statement, or n <= 0 as in Gmsh). A missing field or a
/// cycle is an error located at the Background Field statement. With
/// `mesh_nodes` (the 1D mesh, for 2D meshing) Distance samples meshed curves
/// as Gmsh does; that build is not cached.
field::FieldPtr background_size_field(Interpreter& in, const CurveMeshNodes* mesh_nodes = nullptr);

/// The depth of Mesh.DepthField (> 0: the caller checks) at `xyz` into `depth`, built
/// with its errors located at the option's assignment (the field may have changed since
/// the mesh was made); nothing (empty()) or why not.
/// With `edges` (node index pairs of the elements' edges), sampled as Mesh.DepthSampling
/// says: 1 averages the grid cells within half the mean incident edge of each node.
/// `report`, if given, is set when the field is a grid depth (Bathymetry, Output "depth").
OptionRefusal depth_at(Interpreter& in, std::span<const Vec3> xyz,
                       const std::vector<std::array<std::uint32_t, 2>>& edges, std::vector<double>& depth,
                       std::optional<field::DepthClampReport>* report = nullptr);

/// depth_at on the nodes of a mesh to write, with the edges of its surface elements.
OptionRefusal depth_at(Interpreter& in, const io::MeshModel& mm, std::vector<double>& depth);

/// Why Mesh.DepthSampling cannot be used with `depth` (Mesh.DepthField's field), or nothing.
OptionRefusal check_depth_sampling(Interpreter& in, const field::SizeField& depth);

}  // namespace sm::interp
