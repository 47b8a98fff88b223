// Ocean-model grid export (see ocean_grid_export.h). Each face's loops are walked
// curve by curve in the model's own order and orientation, so the strings
// follow the coast as the model does: an outer loop without open curves is one
// mainland string, a hole without open curves an island, and a loop with open
// curves is cut into alternating open and mainland strings that share their
// end nodes; a curve between two meshed faces is in no string (it cuts the loop as an
// open/land switch does). The strings are in the MeshModel's node numbering (node_index).
#include "interp/kernel/ocean_grid_export.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "interp/kernel/field_eval.h"
#include "interp/interpreter.h"
#include "io/ocean_grid.h"

namespace sm::interp {
namespace {

bool is_open_group(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower == "open";
}

// Appends `more` to `chain`, dropping the shared joint node.
void extend(std::vector<std::uint32_t>& chain, const std::vector<std::uint32_t>& more) {
  const std::size_t skip = !chain.empty() && !more.empty() && chain.back() == more.front() ? 1 : 0;
  chain.insert(chain.end(), more.begin() + skip, more.end());
}

std::string boundary_strings(const geo::Model& model, const ModelMesh& mesh,
                             const std::vector<std::uint32_t>& node_index, std::vector<io::BoundaryString>& out) {
  std::set<int> open;
  for (const auto& [key, g] : model.physicals())
    if (g.dim == 1 && is_open_group(g.name))
      for (int c : g.entities) open.insert(std::abs(c));
  using Kind = io::BoundaryString::Kind;
  // ModelMesh nodes -> the MeshModel's (io/from_model_mesh.h): the writers' numbering.
  auto to_model = [&](io::BoundaryString b) {
    for (std::uint32_t& v : b.nodes) v = node_index.at(v);
    return b;
  };
  // A curve in the loops of two meshed surfaces lies between them, not on the mesh's
  // boundary: it is in no string (a loop is cut there as at an open/land switch).
  std::map<int, int> faces_of;
  for (const auto& [tag, s] : model.surfaces()) {
    if (!mesh.surfaces.count(tag)) continue;
    std::set<int> mine;
    for (int l : s.loops)
      if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
        for (int c : loop->curves) mine.insert(std::abs(c));
    for (int c : mine) ++faces_of[c];
  }
  enum class Side { Land, Open, Between };
  auto side = [&](int c) {
    if (faces_of[std::abs(c)] > 1) return Side::Between;
    return open.count(std::abs(c)) ? Side::Open : Side::Land;
  };
  for (const auto& [tag, s] : model.surfaces()) {
    const auto sm = mesh.surfaces.find(tag);
    if (sm == mesh.surfaces.end()) continue;
    // A hole whose 1D mesh encloses nothing (two edges) is not in the mesh:
    // mesh2d left it out with a warning, and it has no boundary string.
    std::set<std::uint32_t> used;
    for (const auto& t : sm->second.triangles) used.insert(t.begin(), t.end());
    for (const auto& q : sm->second.quads) used.insert(q.begin(), q.end());
    for (std::size_t k = 0; k < s.loops.size(); ++k) {
      const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(s.loops[k]));
      if (!loop) return fmt::format("surface {}: curve loop {} is missing", tag, s.loops[k]);
      std::vector<int> curves = loop->curves;
      if (s.loops[k] < 0) {
        std::reverse(curves.begin(), curves.end());
        for (int& c : curves) c = -c;
      }
      const bool all_land = std::all_of(curves.begin(), curves.end(), [&](int c) { return side(c) == Side::Land; });
      if (all_land) {
        // A closed loop: an island lists it without repeating its first node (the writers
        // close it as each format does); a mainland loop (the outer loop of a face without
        // open boundaries: the World Ocean's Antarctic coast) keeps the first node again at
        // the end, so that its closing edge is listed too.
        io::BoundaryString b{k == 0 ? Kind::Mainland : Kind::Island, {}};
        for (int c : curves) extend(b.nodes, mesh.curve_nodes(c));
        if (b.kind == Kind::Island && b.nodes.size() > 1 && b.nodes.front() == b.nodes.back()) b.nodes.pop_back();
        const bool meshed = std::all_of(b.nodes.begin(), b.nodes.end(), [&](std::uint32_t v) { return used.count(v); });
        if (meshed) out.push_back(to_model(std::move(b)));
        continue;
      }
      // Start at an open/land/between switch so that no string wraps round the start.
      std::size_t start = 0;
      while (start < curves.size() && side(curves[start]) == side(curves[(start + curves.size() - 1) % curves.size()]))
        ++start;
      std::size_t i = start % curves.size();
      do {
        const Side here = side(curves[i]);
        io::BoundaryString b{here == Side::Open ? Kind::Open : Kind::Mainland, {}};
        do {
          extend(b.nodes, mesh.curve_nodes(curves[i]));
          i = (i + 1) % curves.size();
        } while (i != start % curves.size() && side(curves[i]) == here);
        if (here != Side::Between) out.push_back(to_model(std::move(b)));
      } while (i != start % curves.size());
    }
  }
  return {};
}

}  // namespace

std::string ocean_grid_options(Interpreter& in, const std::string& path, const io::MeshModel& mm,
                               const std::vector<std::uint32_t>& node_index, io::OceanGridOptions& opt) {
  const KernelState& k = in.kernel();
  if (!k.mesh || k.mesh->surfaces.empty()) return "no 2D mesh to write (mesh with -2 or 'Mesh 2;' first)";
  opt = {};
  opt.title = fmt::format("stereomesh {}", std::filesystem::path(path).filename().string());
  for (const auto& [tag, g] : k.model.geometries()) {
    opt.centre = g.centre();
    opt.radius = g.radius();
    break;
  }
  opt.lonlat = !k.model.geometries().empty();
  if (in.options().number("Mesh.DepthField") > 0)
    if (OptionRefusal r = depth_at(in, mm, opt.depth); !r.empty()) return r.message;
  return boundary_strings(k.model, *k.mesh, node_index, opt.boundaries);
}

}  // namespace sm::interp
