// Legacy VTK and VTU writers (see vtk_writer.h).
#include "io/vtk_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <numeric>

#include "base/output_file.h"
#include "exact/quality.h"
#include "io/msh_writer.h"
#include "mesh/recombine.h"

namespace sm::io {
namespace {

int vtk_cell_type(ElementType t) {
  switch (t) {
    case ElementType::Point1: return 1;
    case ElementType::Line2: return 3;
    case ElementType::Triangle3: return 5;
    case ElementType::Quad4: return 9;
  }
  return 0;
}

// What gets written: the cells (entity index + element index) and the nodes
// they use, renumbered from 0 in the order of their entities.
struct Selection {
  std::vector<std::pair<std::size_t, std::size_t>> cells;  // (entity, element)
  std::vector<std::uint32_t> nodes;                        // output order -> MeshModel node
  std::vector<std::uint32_t> index;                        // MeshModel node -> output index
};

Selection select(const MeshModel& m, const VtkOptions& opt) {
  Selection s;
  bool has_physicals = false;
  int top = -1;
  for (const EntityMesh& e : m.entities) {
    has_physicals |= !e.physical_tags.empty();
    if (!e.connectivity.empty()) top = std::max(top, e.dim);
  }
  const std::vector<std::size_t> order = entity_order(m);
  std::vector<char> used(m.xyz.size(), 0);
  for (std::size_t i : order) {
    const EntityMesh& e = m.entities[i];
    if (e.dim != top || (has_physicals && !opt.save_all && e.physical_tags.empty())) continue;
    const std::size_t n = e.connectivity.size() / nodes_per_element(e.type);
    for (std::size_t k = 0; k < n; ++k) s.cells.push_back({i, k});
    for (std::uint32_t v : e.connectivity) used[v] = 1;
  }
  s.index.assign(m.xyz.size(), 0);
  for (std::size_t i : order)
    for (std::uint32_t v : m.entities[i].nodes)
      if (used[v]) {
        s.index[v] = static_cast<std::uint32_t>(s.nodes.size());
        s.nodes.push_back(v);
        used[v] = 0;  // a node is owned once; guard against listing it twice
      }
  return s;
}

struct CellArrays {
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  std::vector<double> entity, physical, quality, partition;
};

CellArrays cell_arrays(const MeshModel& m, const Selection& s, const VtkOptions& opt) {
  CellArrays c;
  for (auto [ei, k] : s.cells) {
    const EntityMesh& e = m.entities[ei];
    const int npe = nodes_per_element(e.type);
    const std::uint32_t* v = &e.connectivity[k * npe];
    for (int j = 0; j < npe; ++j) c.connectivity.push_back(s.index[v[j]]);
    c.offsets.push_back(static_cast<std::int64_t>(c.connectivity.size()));
    c.types.push_back(static_cast<std::uint8_t>(vtk_cell_type(e.type)));
    c.entity.push_back(e.tag);
    c.physical.push_back(e.physical_tags.empty() ? 0 : e.physical_tags.front());
    c.quality.push_back(e.type == ElementType::Triangle3 ? rho(m.xyz[v[0]], m.xyz[v[1]], m.xyz[v[2]])
                        : e.type == ElementType::Quad4
                            ? quad_quality(m.xyz[v[0]], m.xyz[v[1]], m.xyz[v[2]], m.xyz[v[3]])
                            : 1.0);
    if (opt.element_part) c.partition.push_back((*opt.element_part)[ei][k]);
  }
  return c;
}

// ---- legacy .vtk ----

template <class T>
void put_be(std::string& out, T v) {  // legacy binary VTK is big-endian
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::little) std::reverse(b, b + sizeof(T));
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

void legacy_scalars(std::string& out, const std::string& name, const std::vector<double>& v, bool binary) {
  out += fmt::format("SCALARS {} double 1\nLOOKUP_TABLE default\n", name);
  if (binary) {
    for (double x : v) put_be(out, x);
    out += "\n";
  } else {
    for (double x : v) fmt::format_to(std::back_inserter(out), "{:.16g}\n", x);
  }
}

std::string legacy(const MeshModel& m, const VtkOptions& opt) {
  const Selection s = select(m, opt);
  const CellArrays c = cell_arrays(m, s, opt);
  std::string out = "# vtk DataFile Version 3.0\nstereomesh mesh\n";
  out += opt.binary ? "BINARY\n" : "ASCII\n";
  out += fmt::format("DATASET UNSTRUCTURED_GRID\nPOINTS {} double\n", s.nodes.size());
  for (std::uint32_t v : s.nodes) {
    const Vec3 x = m.xyz[v];
    if (opt.binary)
      put_be(out, x.x), put_be(out, x.y), put_be(out, x.z);
    else
      fmt::format_to(std::back_inserter(out), "{:.16g} {:.16g} {:.16g}\n", x.x, x.y, x.z);
  }
  if (opt.binary) out += "\n";
  out += fmt::format("CELLS {} {}\n", s.cells.size(), s.cells.size() + c.connectivity.size());
  std::int64_t begin = 0;
  for (std::size_t i = 0; i < s.cells.size(); ++i) {
    const std::int64_t end = c.offsets[i];
    if (opt.binary) {
      put_be<std::int32_t>(out, static_cast<std::int32_t>(end - begin));
      for (std::int64_t j = begin; j < end; ++j)
        put_be<std::int32_t>(out, static_cast<std::int32_t>(c.connectivity[j]));
    } else {
      out += fmt::format("{}", end - begin);
      for (std::int64_t j = begin; j < end; ++j) fmt::format_to(std::back_inserter(out), " {}", c.connectivity[j]);
      out += "\n";
    }
    begin = end;
  }
  if (opt.binary) out += "\n";
  out += fmt::format("CELL_TYPES {}\n", s.cells.size());
  for (std::uint8_t t : c.types) {
    if (opt.binary)
      put_be<std::int32_t>(out, t);
    else
      out += fmt::format("{}\n", t);
  }
  if (opt.binary) out += "\n";
  out += fmt::format("CELL_DATA {}\n", s.cells.size());
  legacy_scalars(out, "entity", c.entity, opt.binary);
  legacy_scalars(out, "physical", c.physical, opt.binary);
  legacy_scalars(out, "quality_rho", c.quality, opt.binary);
  if (!c.partition.empty()) legacy_scalars(out, "partition", c.partition, opt.binary);
  if (!opt.node_data.empty()) {
    out += fmt::format("POINT_DATA {}\n", s.nodes.size());
    for (const NodeData& d : opt.node_data) {
      std::vector<double> v;
      for (std::uint32_t n : s.nodes) v.push_back(d.values[n]);
      legacy_scalars(out, d.name, v, opt.binary);
    }
  }
  return out;
}

// ---- XML .vtu ----

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 | (unsigned char)bytes[i + 2];
    out += k[v >> 18 & 63], out += k[v >> 12 & 63], out += k[v >> 6 & 63], out += k[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16;
    out += k[v >> 18 & 63], out += k[v >> 12 & 63], out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += k[v >> 18 & 63], out += k[v >> 12 & 63], out += k[v >> 6 & 63], out += '=';
  }
  return out;
}

template <class T>
void xml_array(std::string& out, const char* type, const std::string& name, int components,
               const std::vector<T>& v, bool binary) {
  out += fmt::format("        <DataArray type=\"{}\"", type);
  if (!name.empty()) out += fmt::format(" Name=\"{}\"", name);
  if (components > 1) out += fmt::format(" NumberOfComponents=\"{}\"", components);
  out += fmt::format(" format=\"{}\">\n", binary ? "binary" : "ascii");
  if (binary) {
    // VTK's inline binary: base64 of a UInt32 byte count followed by the data
    // (little-endian, as declared in the file header).
    std::string raw(4 + v.size() * sizeof(T), '\0');
    const std::uint32_t n = static_cast<std::uint32_t>(v.size() * sizeof(T));
    std::memcpy(raw.data(), &n, 4);
    if (!v.empty()) std::memcpy(raw.data() + 4, v.data(), v.size() * sizeof(T));
    out += base64(raw);
    out += "\n";
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if constexpr (std::is_floating_point_v<T>)
        fmt::format_to(std::back_inserter(out), "{:.16g}", v[i]);
      else
        fmt::format_to(std::back_inserter(out), "{}", static_cast<std::int64_t>(v[i]));
      out += (i + 1) % 12 == 0 || i + 1 == v.size() ? '\n' : ' ';
    }
  }
  out += "        </DataArray>\n";
}

std::string xml(const MeshModel& m, const VtkOptions& opt) {
  static_assert(std::endian::native == std::endian::little, "VTU binary output assumes a little-endian host");
  const Selection s = select(m, opt);
  const CellArrays c = cell_arrays(m, s, opt);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
      "  <UnstructuredGrid>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", s.nodes.size(), s.cells.size());
  if (!opt.node_data.empty()) {
    out += "      <PointData>\n";
    for (const NodeData& d : opt.node_data) {
      std::vector<double> v;
      for (std::uint32_t n : s.nodes) v.push_back(d.values[n]);
      xml_array(out, "Float64", d.name, 1, v, opt.binary);
    }
    out += "      </PointData>\n";
  }
  out += "      <CellData>\n";
  xml_array(out, "Float64", "entity", 1, c.entity, opt.binary);
  xml_array(out, "Float64", "physical", 1, c.physical, opt.binary);
  xml_array(out, "Float64", "quality_rho", 1, c.quality, opt.binary);
  if (!c.partition.empty()) xml_array(out, "Float64", "partition", 1, c.partition, opt.binary);
  out += "      </CellData>\n      <Points>\n";
  std::vector<double> xyz;
  for (std::uint32_t v : s.nodes) xyz.insert(xyz.end(), {m.xyz[v].x, m.xyz[v].y, m.xyz[v].z});
  xml_array(out, "Float64", "", 3, xyz, opt.binary);
  out += "      </Points>\n      <Cells>\n";
  xml_array(out, "Int64", "connectivity", 1, c.connectivity, opt.binary);
  xml_array(out, "Int64", "offsets", 1, c.offsets, opt.binary);
  xml_array(out, "UInt8", "types", 1, c.types, opt.binary);
  out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace

std::string vtk_to_string(const MeshModel& mesh, const VtkOptions& opt) {
  return opt.xml ? xml(mesh, opt) : legacy(mesh, opt);
}

bool save_vtk(const MeshModel& mesh, const VtkOptions& opt, const std::string& path, std::string* error) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = "invalid mesh: " + why;
    return false;
  }
  for (const NodeData& d : opt.node_data)
    if (d.values.size() != mesh.xyz.size()) {
      *error = fmt::format("node data '{}' has {} values for {} nodes", d.name,
                           d.values.size(), mesh.xyz.size());
      return false;
    }
  base::OutputFile file;
  if (!file.open(path) || !file.write(vtk_to_string(mesh, opt)) || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

}  // namespace sm::io
