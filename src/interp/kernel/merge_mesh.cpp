// `Merge "file.msh";` (as Gmsh 4.8.4 reads it, then CreateTopology): the file's
// elements become discrete entities of the model (mesh/discrete_mesh.h), by their
// elementary tags. A point element is a model point on its node; a curve's line elements,
// one chain, are a discrete curve between the points on its end nodes (new points where
// the file has none, as CreateTopology makes them), from the smaller tag's; a surface's triangles and quadrangles
// are a discrete surface, meshed as it is. The file's physical groups of points and
// curves are added to the model's (those of surfaces are not supported yet). Later statements use these points and
// curves as any others.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/provenance.h"
#include "io/msh_reader.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// The node tags of one curve's line elements as one chain from an end (a node used once)
// to the other, or round a loop; empty when the elements are not one chain.
std::vector<std::uint64_t> chain_of(const io::MshBlock& b) {
  const std::size_t n = b.nodes.size() / 2;
  std::map<std::uint64_t, std::vector<std::size_t>> at;   // node -> its elements
  for (std::size_t e = 0; e < n; ++e) {
    if (b.nodes[2 * e] == b.nodes[2 * e + 1]) return {};
    at[b.nodes[2 * e]].push_back(e), at[b.nodes[2 * e + 1]].push_back(e);
  }
  std::uint64_t start = b.nodes[0];
  for (const auto& [node, es] : at) {
    if (es.size() > 2) return {};   // a branch
    if (es.size() == 1 && b.nodes[2 * es[0]] == node) start = node;   // an end its element leaves
  }
  std::vector<std::uint64_t> chain{start};
  std::vector<char> used(n, 0);
  // Each step uses one element: at most n steps.
  for (std::size_t step = 0; step < n; ++step) {
    const std::vector<std::size_t>& es = at[chain.back()];
    const auto next = std::find_if(es.begin(), es.end(), [&](std::size_t e) { return !used[e]; });
    if (next == es.end()) return {};
    used[*next] = 1;
    chain.push_back(b.nodes[2 * *next] == chain.back() ? b.nodes[2 * *next + 1] : b.nodes[2 * *next]);
  }
  return chain;
}

[[noreturn]] void fail_merge(Interpreter& in, SourceRange at, const std::string& name, const std::string& why) {
  in.fail(at, Diag::CannotMerge, name, why);
}

void add_points(Interpreter& in, const io::MshFile& f, SourceRange at, const std::string& name) {
  KernelState& k = in.kernel();
  for (const io::MshBlock& b : f.blocks) {
    if (b.dim != 0) continue;
    if (b.nodes.size() != 1)
      fail_merge(in, at, name, fmt::format("point {} has {} point elements: a point has one", b.tag, b.nodes.size()));
    const geo::GeoStatus st = k.model.add_point(b.tag, f.nodes.at(b.nodes[0]));
    if (!st) fail_geo(in, at, st.error());
    record_created(k, 0, b.tag, at);
    k.discrete.vertex_node[b.tag] = b.nodes[0];
  }
}

// The model point on node `tag`: the file's, or a new one (CreateTopology's).
int point_on(Interpreter& in, const io::MshFile& f, std::uint64_t tag, SourceRange at) {
  KernelState& k = in.kernel();
  for (const auto& [v, node] : k.discrete.vertex_node)
    if (node == tag) return v;
  const int v = k.model.new_point_tag();
  const geo::GeoStatus st = k.model.add_point(v, f.nodes.at(tag));
  if (!st) fail_geo(in, at, st.error());
  record_created(k, 0, v, at);
  k.discrete.vertex_node[v] = tag;
  return v;
}

void add_curves(Interpreter& in, const io::MshFile& f, SourceRange at, const std::string& name) {
  KernelState& k = in.kernel();
  for (const io::MshBlock& b : f.blocks) {
    if (b.dim != 1) continue;
    const std::vector<std::uint64_t> chain = chain_of(b);
    if (chain.size() < 2)
      fail_merge(in, at, name,
                 fmt::format("the line elements of curve {} are not one chain (a branch or several pieces): "
                             "stereomesh does not split discrete curves",
                             b.tag));
    int begin = point_on(in, f, chain.front(), at), end = point_on(in, f, chain.back(), at);
    // Gmsh's CreateTopology runs a curve from the end point it made first (the smaller
    // tag) to the other, whatever the order of its elements.
    std::vector<std::uint64_t> nodes = chain;
    if (end < begin) {
      std::reverse(nodes.begin(), nodes.end());
      std::swap(begin, end);
    }
    std::vector<Vec3> inner;
    for (std::size_t i = 1; i + 1 < nodes.size(); ++i) inner.push_back(f.nodes.at(nodes[i]));
    const geo::GeoStatus st = k.model.add_discrete_curve(b.tag, begin, end, std::move(inner));
    if (!st) fail_geo(in, at, st.error());
    record_created(k, 1, b.tag, at);
    k.discrete.curve_nodes[b.tag] = std::move(nodes);
  }
}

void add_surfaces(Interpreter& in, const io::MshFile& f, SourceRange at, const std::string& name) {
  KernelState& k = in.kernel();
  for (const io::MshBlock& b : f.blocks) {
    if (b.dim != 2) continue;
    if (k.model.surface(b.tag) || (k.discrete.surfaces.count(b.tag) && b.type == io::ElementType::Triangle3))
      fail_merge(in, at, name, fmt::format("surface {} exists already", b.tag));
    DiscreteSurface& s = k.discrete.surfaces[b.tag];
    const std::size_t npe = static_cast<std::size_t>(io::nodes_per_element(b.type));
    for (std::size_t e = 0; e + npe <= b.nodes.size(); e += npe) {
      if (npe == 3) s.triangles.push_back({b.nodes[e], b.nodes[e + 1], b.nodes[e + 2]});
      else s.quads.push_back({b.nodes[e], b.nodes[e + 1], b.nodes[e + 2], b.nodes[e + 3]});
    }
  }
}

void add_physicals(Interpreter& in, const io::MshFile& f, SourceRange at, const std::string& name) {
  geo::Model& m = in.kernel().model;
  for (const io::MshBlock& b : f.blocks)
    for (int ph : b.physical_tags) {
      // A discrete surface is no surface of the geometry model, which holds the groups.
      if (b.dim == 2)
        in.fail_fmt(at, Diag::NotSupportedYet,
                    fmt::format("physical group {} of discrete surface {} in '{}'", ph, b.tag, name),
                    ": the groups of merged points and curves are kept, not yet those of surfaces");
      std::string group_name;
      for (const io::PhysicalGroup& g : f.physical_names)
        if (g.dim == b.dim && g.tag == ph) group_name = g.name;
      const geo::PhysicalOp op = m.physical(b.dim, ph) ? geo::PhysicalOp::Add : geo::PhysicalOp::Assign;
      auto r = m.add_physical(b.dim, ph, group_name, {b.tag}, op);
      if (!r) fail_geo(in, at, r.error());
    }
}

}  // namespace

void merge_mesh_file(Interpreter& in, const std::filesystem::path& path, const std::string& name, SourceRange at) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  const io::MshReadResult r = io::read_msh(text.str());
  if (!r.ok()) fail_merge(in, at, name, fmt::format("line {}: {}", r.line, r.error));
  DiscreteEntities& d = in.kernel().discrete;
  for (const auto& [tag, xyz] : r.file.nodes) {
    const auto [it, fresh] = d.nodes.emplace(tag, xyz);
    if (!fresh && !(it->second == xyz))
      fail_merge(in, at, name, fmt::format("node {} is elsewhere in a file merged before", tag));
  }
  add_points(in, r.file, at, name);
  add_curves(in, r.file, at, name);
  add_surfaces(in, r.file, at, name);
  add_physicals(in, r.file, at, name);
}

}  // namespace sm::interp
