// ADCIRC fort.14 and SCHISM hgrid.gr3 / hgrid.ll writers and reader.
#include "io/ocean_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <numeric>

#include "geo/sphere.h"
#include "base/output_file.h"

namespace sm::io {
namespace {

enum class Flavour { Adcirc, Schism };

// Nodes used by the surface elements (triangles, and SCHISM's quadrangles), numbered
// from 1 in entity order.
struct Numbering {
  std::vector<std::uint32_t> order;  // output position -> MeshModel node
  std::vector<std::uint32_t> id;     // MeshModel node -> 1-based id (0: not written)
  std::vector<const EntityMesh*> surfaces;
};

Numbering number(const MeshModel& m) {
  Numbering n;
  const std::vector<std::size_t> order = entity_order(m);
  std::vector<char> used(m.xyz.size(), 0);
  for (std::size_t i : order)
    if (m.entities[i].type == ElementType::Triangle3 || m.entities[i].type == ElementType::Quad4) {
      n.surfaces.push_back(&m.entities[i]);
      for (std::uint32_t v : m.entities[i].connectivity) used[v] = 1;
    }
  n.id.assign(m.xyz.size(), 0);
  for (std::size_t i : order)
    for (std::uint32_t v : m.entities[i].nodes)
      if (used[v] && !n.id[v]) {
        n.order.push_back(v);
        n.id[v] = static_cast<std::uint32_t>(n.order.size());
      }
  return n;
}

std::string write(const MeshModel& m, const OceanGridOptions& opt, Flavour flavour, bool force_lonlat) {
  const Numbering n = number(m);
  const geo::PolarSphere sphere(opt.centre, opt.radius);
  std::size_t ne = 0;
  for (const EntityMesh* s : n.surfaces) ne += s->connectivity.size() / nodes_per_element(s->type);
  std::string out = opt.title + "\n";
  out += fmt::format("{} {}\n", ne, n.order.size());
  for (std::uint32_t v : n.order) {
    double x = m.xyz[v].x, y = m.xyz[v].y;
    if (opt.lonlat || force_lonlat) {
      const geo::LonLat ll = sphere.to_lonlat(m.xyz[v]);
      x = ll.lon, y = ll.lat;
    }
    const double h = opt.depth.empty() ? 0.0 : opt.depth[v];
    fmt::format_to(std::back_inserter(out), "{} {:.15g} {:.15g} {:.15g}\n", n.id[v], x, y, h);
  }
  std::size_t e = 0;
  // SCHISM reads "id nodes n1 .. n(nodes)" with 3 or 4 nodes (its mixed grids).
  for (const EntityMesh* s : n.surfaces) {
    const std::size_t npe = static_cast<std::size_t>(nodes_per_element(s->type));
    for (std::size_t k = 0; k + npe <= s->connectivity.size(); k += npe) {
      fmt::format_to(std::back_inserter(out), "{} {}", ++e, npe);
      for (std::size_t j = 0; j < npe; ++j)
        fmt::format_to(std::back_inserter(out), " {}", n.id[s->connectivity[k + j]]);
      out += '\n';
    }
  }

  using Kind = BoundaryString::Kind;
  std::vector<const BoundaryString*> open, land;
  for (const BoundaryString& b : opt.boundaries) (b.kind == Kind::Open ? open : land).push_back(&b);
  auto listed = [&](const BoundaryString& b) {
    const bool close = flavour == Flavour::Adcirc && b.kind == Kind::Island && !b.nodes.empty();
    return b.nodes.size() + (close ? 1 : 0);
  };
  std::size_t neta = 0, nvel = 0;
  for (auto* b : open) neta += listed(*b);
  for (auto* b : land) nvel += listed(*b);
  out += fmt::format("{} = Number of open boundaries\n", open.size());
  out += fmt::format("{} = Total number of open boundary nodes\n", neta);
  for (std::size_t k = 0; k < open.size(); ++k) {
    if (flavour == Flavour::Adcirc)
      out += fmt::format("{} 0 = Number of nodes for open boundary {}\n", listed(*open[k]), k + 1);
    else
      out += fmt::format("{} = Number of nodes for open boundary {}\n", listed(*open[k]), k + 1);
    for (std::uint32_t v : open[k]->nodes) out += fmt::format("{}\n", n.id[v]);
  }
  out += fmt::format("{} = Number of land boundaries\n", land.size());
  out += fmt::format("{} = Total number of land boundary nodes\n", nvel);
  for (std::size_t k = 0; k < land.size(); ++k) {
    const bool island = land[k]->kind == Kind::Island;
    const int type = flavour == Flavour::Adcirc ? (island ? 21 : 20) : (island ? 1 : 0);
    out += fmt::format("{} {} = Number of nodes for land boundary {}\n", listed(*land[k]), type, k + 1);
    for (std::uint32_t v : land[k]->nodes) out += fmt::format("{}\n", n.id[v]);
    if (flavour == Flavour::Adcirc && island && !land[k]->nodes.empty())
      out += fmt::format("{}\n", n.id[land[k]->nodes.front()]);
  }
  return out;
}

// Checks what the writers cannot represent before any file is created: ADCIRC's fort.14
// holds triangles only.
std::string check(const MeshModel& m, const OceanGridOptions& opt, Flavour flavour) {
  if (std::string why = validate_mesh_model(m); !why.empty()) return "invalid mesh: " + why;
  if (flavour == Flavour::Adcirc)
    for (std::size_t i : entity_order(m)) {
      const EntityMesh& e = m.entities[i];
      if (e.type == ElementType::Quad4 && !e.connectivity.empty())
        return fmt::format("fort.14 (ADCIRC) holds triangles only, and surface {} has {} quadrangles: write "
                           "hgrid.gr3 (SCHISM reads quadrangles), MSH or VTK, or mesh it without Recombine",
                           e.tag, e.connectivity.size() / 4);
    }
  if (!opt.depth.empty() && opt.depth.size() != m.xyz.size())
    return fmt::format("depth has {} values for {} nodes", opt.depth.size(), m.xyz.size());
  const Numbering n = number(m);
  if (n.surfaces.empty()) return "the mesh has no triangles (mesh it with -2 first)";
  for (const BoundaryString& b : opt.boundaries)
    for (std::uint32_t v : b.nodes)
      if (v >= m.xyz.size() || !n.id[v]) return fmt::format("boundary node {} is not a node of the triangles", v);
  return {};
}

bool save_text(const std::string& path, const std::string& text, std::string* error) {
  base::OutputFile file;
  if (!file.open(path) || !file.write(text) || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

// Line-oriented reader: every record's leading numbers, the rest (comments
// such as "= Number of open boundaries") ignored.
class Lines {
 public:
  explicit Lines(const std::string& t) : text_(t) {}
  // Reads the line's leading numbers: at least `want`, at most `most`.
  bool next(std::vector<double>& nums, std::size_t want, std::string* error, std::size_t most = 0) {
    most = std::max(most, want);
    if (pos_ >= text_.size()) return ++line_, fail(error, "unexpected end of file");
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    const char* p = text_.data() + pos_;
    const char* e = text_.data() + end;
    pos_ = end + 1;
    ++line_;
    nums.clear();
    while (nums.size() < most) {
      while (p < e && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
      double v;
      const auto r = std::from_chars(p, e, v);
      if (r.ec != std::errc()) break;
      nums.push_back(v);
      p = r.ptr;
    }
    if (nums.size() < want) return fail(error, fmt::format("expected {} numbers", want));
    return true;
  }
  bool skip(std::string* error) {
    if (pos_ >= text_.size()) return ++line_, fail(error, "unexpected end of file");
    std::size_t end = text_.find('\n', pos_);
    pos_ = end == std::string::npos ? text_.size() : end + 1;
    ++line_;
    return true;
  }
  bool fail(std::string* error, const std::string& what) const {
    *error = fmt::format("line {}: {}", line_, what);
    return false;
  }

 private:
  const std::string& text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace

std::string fort14_to_string(const MeshModel& mesh, const OceanGridOptions& opt) {
  return write(mesh, opt, Flavour::Adcirc, false);
}

std::string gr3_to_string(const MeshModel& mesh, const OceanGridOptions& opt) {
  return write(mesh, opt, Flavour::Schism, false);
}

bool save_fort14(const MeshModel& mesh, const OceanGridOptions& opt, const std::string& path, std::string* error) {
  if (std::string why = check(mesh, opt, Flavour::Adcirc); !why.empty()) {
    *error = why;
    return false;
  }
  return save_text(path, fort14_to_string(mesh, opt), error);
}

bool save_schism(const MeshModel& mesh, const OceanGridOptions& opt, const std::string& gr3_path, std::string* error) {
  if (std::string why = check(mesh, opt, Flavour::Schism); !why.empty()) {
    *error = why;
    return false;
  }
  const std::size_t slash = gr3_path.find_last_of('/');
  const std::string ll_path = (slash == std::string::npos ? "" : gr3_path.substr(0, slash + 1)) + "hgrid.ll";
  // Both files or neither: SCHISM reads them as one grid, so a new hgrid.gr3 beside an
  // old hgrid.ll would be a wrong grid that loads.
  base::OutputFile gr3, ll;
  const bool opened = gr3.open(gr3_path) && ll.open(ll_path);
  const bool written = opened && gr3.write(write(mesh, opt, Flavour::Schism, false)) &&
                       ll.write(write(mesh, opt, Flavour::Schism, true));
  base::OutputFile* const both[] = {&gr3, &ll};
  std::size_t failed = 0;
  if (written && base::commit_together(both, &failed)) return true;
  if (!written) failed = gr3.error().empty() ? 1 : 0;
  *error = failed == 0 ? gr3.error() : "hgrid.ll beside it: " + ll.error();
  gr3.abandon();
  ll.abandon();
  return false;
}

bool parse_ocean_grid(const std::string& text, OceanGrid* g, std::string* error) {
  Lines in(text);
  std::vector<double> v;
  if (!in.skip(error) || !in.next(v, 2, error)) return false;
  const double ne = v[0], np = v[1];
  if (ne < 0 || np < 0 || ne > 1e9 || np > 1e9) return in.fail(error, "absurd element or node count");
  const std::size_t n_nodes = static_cast<std::size_t>(np), n_elems = static_cast<std::size_t>(ne);
  g->xy.resize(n_nodes);
  g->depth.resize(n_nodes);
  for (std::size_t i = 0; i < n_nodes; ++i) {
    if (!in.next(v, 4, error)) return false;
    if (v[0] != double(i + 1)) return in.fail(error, "node ids must run 1..NP in order");
    g->xy[i] = {v[1], v[2]};
    g->depth[i] = v[3];
  }
  for (std::size_t i = 0; i < n_elems; ++i) {
    if (!in.next(v, 5, error, 6)) return false;
    if (v[1] != 3 && v[1] != 4) return in.fail(error, "only triangles and quadrangles are supported");
    const int npe = static_cast<int>(v[1]);
    if (static_cast<int>(v.size()) < 2 + npe) return in.fail(error, "a quadrangle needs 4 nodes");
    std::vector<std::uint32_t>& into = npe == 3 ? g->triangles : g->quads;
    for (int k = 2; k < 2 + npe; ++k) {
      if (v[k] < 1 || v[k] > np) return in.fail(error, "element node out of range");
      into.push_back(static_cast<std::uint32_t>(v[k] - 1));
    }
  }
  for (auto* strings : {&g->open, &g->land}) {
    if (!in.next(v, 1, error)) return false;
    const double count = v[0];
    if (!in.next(v, 1, error)) return false;
    if (count < 0 || count > np) return in.fail(error, "absurd boundary count");
    for (int k = 0; k < static_cast<int>(count); ++k) {
      // "count [type] = comment": the type (IBTYPE or land flag) is optional
      if (!in.next(v, 1, error, 2)) return false;
      OceanGrid::String s;
      const double nodes = v[0];
      s.type = strings == &g->land && v.size() > 1 ? static_cast<int>(v[1]) : -1;
      if (nodes < 0 || nodes > np + 1) return in.fail(error, "absurd boundary node count");
      for (int j = 0; j < static_cast<int>(nodes); ++j) {
        if (!in.next(v, 1, error)) return false;
        if (v[0] < 1 || v[0] > np) return in.fail(error, "boundary node out of range");
        s.nodes.push_back(static_cast<std::uint32_t>(v[0] - 1));
      }
      strings->push_back(std::move(s));
    }
  }
  return true;
}

}  // namespace sm::io
