// UGRID 1.0 netCDF writer (see ugrid_writer.h). The file is built in memory by netCDF
// itself (nc_create_mem / nc_close_memio) and its bytes then go through
// base::OutputFile like every other output, so a failed or interrupted write never
// leaves a partial file, and links, FIFOs and devices are respected.
#include "io/ugrid_writer.h"

#include <fmt/format.h>
#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <mutex>
#include <set>
#include <utility>

#include "base/netcdf_lock.h"
#include "base/output_file.h"
#include "io/boundary_edges.h"
#include "exact/predicates.h"
#include "geo/sphere.h"

namespace sm::io {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;   // MeshModel nodes, smaller first

Edge edge_key(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Boundary kinds as the file's flag values.
constexpr int kMainland = 1, kIsland = 2, kOpen = 3;

// A CF flag meaning: one word (letters, digits, underscores).
std::string flag_word(const std::string& name, int tag) {
  if (name.empty()) return fmt::format("group_{}", tag);
  std::string w = name;
  for (char& c : w)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return w;
}

// What the file holds, gathered from the mesh model before netCDF is called.
struct Ugrid {
  std::vector<std::uint32_t> nodes;     // file node -> MeshModel node
  std::vector<int> face_nodes;          // max_face_nodes per face, 0-based file nodes, -1 fill
  std::size_t max_face_nodes = 3;
  std::vector<int> edge_nodes;          // 2 per boundary edge
  std::vector<int> edge_kind, edge_physical;
  std::vector<int> face_part;           // per face, when partitioned
  std::vector<std::pair<int, std::string>> curve_groups;   // dim-1 physical groups (tag, flag word)
};

Ugrid gather(const MeshModel& m, const OceanGridOptions& opt, const std::vector<std::vector<int>>* element_part) {
  Ugrid u;
  std::vector<const EntityMesh*> faces;
  for (const EntityMesh& e : m.entities)
    if (e.dim == 2 && (e.type == ElementType::Triangle3 || e.type == ElementType::Quad4)) faces.push_back(&e);
  std::stable_sort(faces.begin(), faces.end(),
                   [](const EntityMesh* a, const EntityMesh* b) { return a->tag < b->tag; });
  for (const EntityMesh* f : faces)
    if (f->type == ElementType::Quad4) u.max_face_nodes = 4;

  // File nodes: those the faces use, in the mesh model's order.
  std::vector<int> file_id(m.xyz.size(), -1);
  for (const EntityMesh* f : faces)
    for (std::uint32_t v : f->connectivity) file_id[v] = 0;
  for (std::uint32_t v = 0; v < m.xyz.size(); ++v)
    if (file_id[v] == 0) {
      file_id[v] = static_cast<int>(u.nodes.size());
      u.nodes.push_back(v);
    }

  // Faces, anticlockwise seen from outside the sphere (or from +z on a plane).
  for (const EntityMesh* f : faces) {
    const std::size_t k = static_cast<std::size_t>(nodes_per_element(f->type));
    for (std::size_t i = 0; i + k <= f->connectivity.size(); i += k) {
      std::vector<std::uint32_t> v(f->connectivity.begin() + static_cast<std::ptrdiff_t>(i),
                                   f->connectivity.begin() + static_cast<std::ptrdiff_t>(i + k));
      const Vec3 a = m.xyz[v[0]], b = m.xyz[v[1]], c = m.xyz[v[2]];
      const Sign s = opt.lonlat ? orient3d(a, b, c, opt.centre) : orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y});
      if (s == Sign::Negative) std::reverse(v.begin() + 1, v.end());
      for (std::size_t j = 0; j < u.max_face_nodes; ++j) u.face_nodes.push_back(j < k ? file_id[v[j]] : -1);
      if (element_part) u.face_part.push_back((*element_part)[static_cast<std::size_t>(f - m.entities.data())][i / k]);
    }
  }

  // Kinds from the model's boundary strings: an edge between consecutive nodes of an
  // open string is open; one with both nodes on an island loop is island; the rest of
  // the boundary is mainland.
  std::set<Edge> open;
  std::vector<char> on_island(m.xyz.size(), 0);
  for (const BoundaryString& s : opt.boundaries) {
    if (s.kind == BoundaryString::Kind::Open)
      for (std::size_t i = 0; i + 1 < s.nodes.size(); ++i) open.insert(edge_key(s.nodes[i], s.nodes[i + 1]));
    if (s.kind == BoundaryString::Kind::Island)
      for (std::uint32_t v : s.nodes) on_island[v] = 1;
  }
  std::set<int> used_groups;
  bool any_ungrouped = false;
  for (const BoundaryEdge& e : boundary_edges(m)) {
    u.edge_nodes.push_back(file_id[e.a]);
    u.edge_nodes.push_back(file_id[e.b]);
    u.edge_kind.push_back(open.count(edge_key(e.a, e.b)) ? kOpen
                                                         : (on_island[e.a] && on_island[e.b] ? kIsland : kMainland));
    u.edge_physical.push_back(e.physical);
    if (e.physical) used_groups.insert(e.physical); else any_ungrouped = true;
  }
  if (any_ungrouped) u.curve_groups.emplace_back(0, "none");
  for (const PhysicalGroup& g : m.physicals)
    if (g.dim == 1 && used_groups.count(g.tag)) u.curve_groups.emplace_back(g.tag, flag_word(g.name, g.tag));
  for (int g : used_groups)   // groups the model lists without a PhysicalGroup entry
    if (std::none_of(u.curve_groups.begin(), u.curve_groups.end(), [&](const auto& p) { return p.first == g; }))
      u.curve_groups.emplace_back(g, flag_word("", g));
  std::sort(u.curve_groups.begin(), u.curve_groups.end());
  return u;
}

// netCDF calls in sequence: the first failure is kept and the rest are skipped.
class NcFile {
 public:
  explicit NcFile(std::size_t size_hint) {
    check(nc_create_mem("stereomesh.nc", NC_64BIT_OFFSET, size_hint, &id_), "create");
    open_ = error_.empty();
  }
  ~NcFile() {
    if (open_) {
      NC_memio io{};
      if (nc_close_memio(id_, &io) == NC_NOERR) std::free(io.memory);
    }
  }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;

  int dim(const char* name, std::size_t n) {
    int d = -1;
    check(nc_def_dim(id_, name, n, &d), name);
    return d;
  }
  int var(const char* name, nc_type type, std::initializer_list<int> dims) {
    int v = -1;
    const std::vector<int> ds(dims);
    check(nc_def_var(id_, name, type, static_cast<int>(ds.size()), ds.data(), &v), name);
    return v;
  }
  void text(int var, const char* name, const std::string& value) {
    check(nc_put_att_text(id_, var, name, value.size(), value.c_str()), name);
  }
  void ints(int var, const char* name, const std::vector<int>& values) {
    check(nc_put_att_int(id_, var, name, NC_INT, values.size(), values.data()), name);
  }
  void doubles(int var, const char* name, const std::vector<double>& values) {
    check(nc_put_att_double(id_, var, name, NC_DOUBLE, values.size(), values.data()), name);
  }
  void end_definitions() { check(nc_enddef(id_), "enddef"); }
  void put(int var, const std::vector<double>& v) {
    if (!v.empty()) check(nc_put_var_double(id_, var, v.data()), "data");
  }
  void put(int var, const std::vector<int>& v) {
    if (!v.empty()) check(nc_put_var_int(id_, var, v.data()), "data");
  }
  /// Closes the file and returns its bytes ("" with error() on failure).
  std::string close() {
    NC_memio io{};
    if (open_) {
      open_ = false;
      check(nc_close_memio(id_, &io), "close");
    }
    std::string bytes;
    if (error_.empty() && io.memory) bytes.assign(static_cast<const char*>(io.memory), io.size);
    std::free(io.memory);
    return bytes;
  }
  const std::string& error() const { return error_; }

 private:
  void check(int status, const char* what) {
    if (status == NC_NOERR || !error_.empty()) return;
    error_ = fmt::format("netCDF ({}): {}", what, nc_strerror(status));
  }
  int id_ = -1;
  bool open_ = false;
  std::string error_;
};

// The file's variables, defined before its values are written.
struct UgridVars {
  int vx = -1, vy = -1;
  int cart[3] = {-1, -1, -1};   // Earth-centred x, y, z (lon/lat files)
  int vdepth = -1;
  std::vector<std::pair<int, const NodeData*>> extra;   // Mesh.NodeData's fields
  int vpart = -1, vf = -1, ve = -1, vkind = -1, vphys = -1;
};

// The mesh topology variable (UGRID's dummy variable naming the others).
void define_topology(NcFile& nc, bool has_edges) {
  const int topo = nc.var("mesh2d", NC_INT, {});
  nc.text(topo, "cf_role", "mesh_topology");
  nc.text(topo, "long_name", "Topology data of 2D mesh");
  nc.ints(topo, "topology_dimension", {2});
  nc.text(topo, "node_coordinates", "mesh2d_node_x mesh2d_node_y");
  nc.text(topo, "node_dimension", "mesh2d_nNodes");
  nc.text(topo, "face_node_connectivity", "mesh2d_face_nodes");
  nc.text(topo, "face_dimension", "mesh2d_nFaces");
  if (has_edges) {
    nc.text(topo, "edge_node_connectivity", "mesh2d_edge_nodes");
    nc.text(topo, "edge_dimension", "mesh2d_nEdges");
  }
}

// The variables at the nodes: coordinates, Cartesian coordinates (lon/lat), depth and
// Mesh.NodeData's fields.
void define_node_vars(NcFile& nc, int d_node, const OceanGridOptions& opt, const std::vector<NodeData>& node_data,
                      UgridVars& v) {
  auto node_var = [&](const char* name, const char* standard, const char* long_name, const char* units) {
    const int var = nc.var(name, NC_DOUBLE, {d_node});
    if (*standard) nc.text(var, "standard_name", standard);
    nc.text(var, "long_name", long_name);
    nc.text(var, "units", units);
    nc.text(var, "mesh", "mesh2d");
    nc.text(var, "location", "node");
    return var;
  };
  v.vx = opt.lonlat ? node_var("mesh2d_node_x", "longitude", "longitude of the mesh nodes", "degrees_east")
                    : node_var("mesh2d_node_x", "projection_x_coordinate", "x of the mesh nodes", "1");
  v.vy = opt.lonlat ? node_var("mesh2d_node_y", "latitude", "latitude of the mesh nodes", "degrees_north")
                    : node_var("mesh2d_node_y", "projection_y_coordinate", "y of the mesh nodes", "1");
  if (opt.lonlat) {
    v.cart[0] = node_var("mesh2d_node_cartesian_x", "", "Cartesian x of the mesh nodes (Earth-centred)", "m");
    v.cart[1] = node_var("mesh2d_node_cartesian_y", "", "Cartesian y of the mesh nodes (Earth-centred)", "m");
    v.cart[2] = node_var("mesh2d_node_cartesian_z", "", "Cartesian z of the mesh nodes (Earth-centred)", "m");
  }
  if (!opt.depth.empty()) {
    v.vdepth =
        node_var("mesh2d_node_depth", "sea_floor_depth_below_geoid", "depth at the mesh nodes (Mesh.DepthField)", "m");
    nc.text(v.vdepth, "positive", "down");
  }
  // Mesh.NodeData's fields; its depth is the one above (the same Mesh.DepthField).
  for (const NodeData& d : node_data) {
    if (d.name == "depth" && v.vdepth >= 0) continue;
    const std::string name = "mesh2d_node_" + d.name;
    v.extra.emplace_back(node_var(name.c_str(), "", d.long_name.c_str(), d.units.c_str()), &d);
  }
}

// The variables of the faces: their partition (when partitioned) and their nodes.
void define_face_vars(NcFile& nc, int d_face, int d_max, const Ugrid& u, UgridVars& v) {
  if (!u.face_part.empty()) {
    v.vpart = nc.var("mesh2d_face_partition", NC_INT, {d_face});
    nc.text(v.vpart, "long_name", "partition of each face (Mesh.NbPartitions, METIS), 1 to the number of partitions");
    nc.text(v.vpart, "mesh", "mesh2d");
    nc.text(v.vpart, "location", "face");
  }
  v.vf = nc.var("mesh2d_face_nodes", NC_INT, {d_face, d_max});
  nc.text(v.vf, "cf_role", "face_node_connectivity");
  nc.text(v.vf, "long_name", "nodes of each face, anticlockwise");
  nc.ints(v.vf, "start_index", {0});
  nc.ints(v.vf, "_FillValue", {-1});
}

// The variables of the boundary edges: nodes, kind (mainland, island, open) and physical
// curve group, its tags and words as flags.
void define_edge_vars(NcFile& nc, int d_edge, int d_two, const Ugrid& u, UgridVars& v) {
  v.ve = nc.var("mesh2d_edge_nodes", NC_INT, {d_edge, d_two});
  nc.text(v.ve, "cf_role", "edge_node_connectivity");
  nc.text(v.ve, "long_name", "nodes of each boundary edge");
  nc.ints(v.ve, "start_index", {0});
  v.vkind = nc.var("mesh2d_edge_type", NC_INT, {d_edge});
  nc.text(v.vkind, "long_name", "kind of boundary edge");
  nc.text(v.vkind, "mesh", "mesh2d");
  nc.text(v.vkind, "location", "edge");
  nc.ints(v.vkind, "flag_values", {kMainland, kIsland, kOpen});
  nc.text(v.vkind, "flag_meanings", "mainland island open");
  v.vphys = nc.var("mesh2d_edge_physical", NC_INT, {d_edge});
  nc.text(v.vphys, "long_name", "physical curve group of the boundary edge (0: none)");
  nc.text(v.vphys, "mesh", "mesh2d");
  nc.text(v.vphys, "location", "edge");
  std::vector<int> tags;
  std::string words;
  for (const auto& [tag, word] : u.curve_groups) {
    tags.push_back(tag);
    words += (words.empty() ? "" : " ") + word;
  }
  if (!tags.empty()) {
    nc.ints(v.vphys, "flag_values", tags);
    nc.text(v.vphys, "flag_meanings", words);
  }
}

// The values at the nodes, in file node order.
void write_node_values(NcFile& nc, const MeshModel& mesh, const OceanGridOptions& opt, const Ugrid& u,
                       const UgridVars& v) {
  const std::size_t nn = u.nodes.size();
  std::vector<double> x(nn), y(nn);
  const geo::PolarSphere sphere(opt.centre, opt.radius);
  for (std::size_t i = 0; i < nn; ++i) {
    const Vec3 p = mesh.xyz[u.nodes[i]];
    if (opt.lonlat) {
      const geo::LonLat ll = sphere.to_lonlat(p);
      x[i] = ll.lon, y[i] = ll.lat;
    } else {
      x[i] = p.x, y[i] = p.y;
    }
  }
  nc.put(v.vx, x);
  nc.put(v.vy, y);
  if (opt.lonlat) {
    for (int k = 0; k < 3; ++k) {
      for (std::size_t i = 0; i < nn; ++i) {
        const Vec3 p = mesh.xyz[u.nodes[i]] - opt.centre;
        x[i] = k == 0 ? p.x : (k == 1 ? p.y : p.z);
      }
      nc.put(v.cart[k], x);
    }
  }
  if (v.vdepth >= 0) {
    for (std::size_t i = 0; i < nn; ++i) x[i] = opt.depth[u.nodes[i]];
    nc.put(v.vdepth, x);
  }
  for (const auto& [var, d] : v.extra) {
    for (std::size_t i = 0; i < nn; ++i) x[i] = d->values[u.nodes[i]];
    nc.put(var, x);
  }
}

}  // namespace

std::string ugrid_to_bytes(const MeshModel& mesh, const OceanGridOptions& opt, std::string* error,
                           const std::vector<NodeData>& node_data,
                           const std::vector<std::vector<int>>* element_part) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = why;
    return {};
  }
  const std::lock_guard<std::mutex> lock(base::netcdf_lock());   // libnetcdf is not thread-safe
  const Ugrid u = gather(mesh, opt, element_part);
  if (u.nodes.empty()) {
    *error = "no 2D mesh to write (mesh with -2 or 'Mesh 2;' first)";
    return {};
  }
  if (!opt.depth.empty() && opt.depth.size() != mesh.xyz.size()) {
    *error = "the depths do not match the nodes";
    return {};
  }
  const std::size_t nn = u.nodes.size(), nf = u.face_nodes.size() / u.max_face_nodes, ne = u.edge_kind.size();
  NcFile nc(0);
  const int d_node = nc.dim("mesh2d_nNodes", nn), d_face = nc.dim("mesh2d_nFaces", nf);
  const int d_max = nc.dim("mesh2d_nMax_face_nodes", u.max_face_nodes), d_two = nc.dim("Two", 2);
  const int d_edge = ne ? nc.dim("mesh2d_nEdges", ne) : -1;
  UgridVars v;
  define_topology(nc, ne != 0);
  define_node_vars(nc, d_node, opt, node_data, v);
  define_face_vars(nc, d_face, d_max, u, v);
  if (ne) define_edge_vars(nc, d_edge, d_two, u, v);
  nc.text(NC_GLOBAL, "Conventions", "CF-1.8 UGRID-1.0");
  nc.text(NC_GLOBAL, "title", opt.title);
  nc.text(NC_GLOBAL, "source", "stereomesh");
  if (opt.lonlat) nc.doubles(NC_GLOBAL, "sphere_radius", {opt.radius});
  nc.end_definitions();

  write_node_values(nc, mesh, opt, u, v);
  nc.put(v.vf, u.face_nodes);
  if (v.vpart >= 0) nc.put(v.vpart, u.face_part);
  if (ne) {
    nc.put(v.ve, u.edge_nodes);
    nc.put(v.vkind, u.edge_kind);
    nc.put(v.vphys, u.edge_physical);
  }
  std::string bytes = nc.close();
  if (bytes.empty()) *error = nc.error().empty() ? "netCDF wrote nothing" : nc.error();
  return bytes;
}

bool save_ugrid(const MeshModel& mesh, const OceanGridOptions& opt, const std::vector<NodeData>& node_data,
                const std::vector<std::vector<int>>* element_part, const std::string& path, std::string* error) {
  const std::string bytes = ugrid_to_bytes(mesh, opt, error, node_data, element_part);
  if (bytes.empty()) return false;
  base::OutputFile out;
  if (!out.open(path) || !out.write(bytes) || !out.commit()) {
    *error = out.error();
    return false;
  }
  return true;
}

}  // namespace sm::io
