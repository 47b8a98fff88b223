// The output-format table (see output_format.h): one row per format, the writer of each
// a call into its own file.
#include "io/output_format.h"

#include <fmt/format.h>

#include "io/msh_writer.h"
#include "io/partitioned_model.h"
#include "io/png_writer.h"
#include "io/svg_writer.h"
#include "io/ugrid_writer.h"
#include "io/vtk_writer.h"

namespace sm::io {

namespace {

bool write_msh(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  MshOptions o;
  o.version = s.msh_version;
  o.binary = s.binary;
  o.save_all = s.save_all;
  o.save_parametric = s.save_parametric;
  o.node_data = s.node_data;
  o.threads = s.threads;
  if (!s.partition) return save_msh(m, o, path, error);
  MeshModel partitioned = partitioned_model(m, *s.partition, s.partition_topology);
  if (!s.split_files) return save_msh(partitioned, o, path, error);
  // One part at a time (-part 1000 on the World Ocean ran out of memory when every piece
  // was built first): each piece is built when its file is written and replaced by the
  // next, and the node coordinates pass from piece to piece instead of being copied.
  std::vector<std::string> paths;
  for (int p = 1; p <= s.partition->parts; ++p) paths.push_back(partition_file_name(path, p));
  std::vector<Vec3> xyz = std::move(partitioned.xyz);
  MeshModel piece;
  const auto make = [&](std::size_t k) -> const MeshModel& {
    if (!piece.xyz.empty()) xyz = std::move(piece.xyz);
    piece = MeshModel();
    piece = partition_piece(partitioned, static_cast<int>(k) + 1, std::move(xyz));
    return piece;
  };
  // Node data are per node of the whole mesh: each file's $NodeData holds its own nodes.
  return save_msh_files(make, o, paths, error);
}

// The partition of each node as one more node value, beside Mesh.NodeData's.
std::vector<NodeData> with_node_partition(const OutputSettings& s) {
  std::vector<NodeData> data = s.node_data;
  if (s.partition) {
    NodeData d{"partition", "1", "partition of the node: the smallest of its elements' (Mesh.NbPartitions)", {}};
    d.values.assign(s.partition->node_part.begin(), s.partition->node_part.end());
    data.push_back(std::move(d));
  }
  return data;
}

bool write_vtk(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  VtkOptions o;
  o.binary = s.binary;
  o.save_all = s.save_all;
  o.node_data = with_node_partition(s);
  if (s.partition) o.element_part = &s.partition->element_part;
  return save_vtk(m, o, path, error);
}

bool write_svg(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  return save_svg(m, s.picture, path, error);
}

bool write_png(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  return save_png(m, s.picture, path, error);
}

bool write_fort14(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  return save_fort14(m, s.ocean, path, error);
}

bool write_gr3(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  return save_schism(m, s.ocean, path, error);
}

bool write_ugrid(const MeshModel& m, const OutputSettings& s, const std::string& path, std::string* error) {
  return save_ugrid(m, s.ocean, with_node_partition(s), s.partition ? &s.partition->element_part : nullptr, path,
                    error);
}

using In = OutputInput;

// MSH 4.1 holds everything Gmsh meshes, partitions included (MSH 2.2's partition tags are
// not written); VTK and UGRID a partition per cell and per node;
// the pictures draw any polygon; ADCIRC's fort.14 is triangles only, SCHISM's hgrid.gr3
// takes quadrangles too; UGRID netCDF holds mixed faces and node variables.
// fort.14 and hgrid.gr3 give every node a depth (the last column: depth required).
//  name      ext     default file  Mesh.Format version input       writer        quads  parts  data   note
constexpr OutputFormat kFormats[] = {
    {"msh",    ".msh", "",          1,  0,   In::Mesh,      &write_msh,    true,  true,  true,  "", ""},
    {"msh2",   ".msh", "",          1,  2.2, In::Mesh,      &write_msh,    true,  false, true,  "", ""},
    {"msh22",  ".msh", "",          1,  2.2, In::Mesh,      &write_msh,    true,  false, true,  "", ""},
    {"msh4",   ".msh", "",          1,  4.1, In::Mesh,      &write_msh,    true,  true,  true,  "", ""},
    {"msh41",  ".msh", "",          1,  4.1, In::Mesh,      &write_msh,    true,  true,  true,  "", ""},
    {"vtk",    ".vtk", "",          16, 0,   In::Mesh,      &write_vtk,    true,  true,  true,  "", ""},
    {"svg",    ".svg", "",          0,  0,   In::Picture,   &write_svg,    true,  false, false, "a picture", ""},
    {"png",    ".png", "",          0,  0,   In::Picture,   &write_png,    true,  false, false, "a picture", ""},
    {"fort14", ".14",  "fort.14",   0,  0,   In::OceanGrid, &write_fort14, false, false, false, "ADCIRC", "", true},
    {"gr3",    ".gr3", "hgrid.gr3", 0,  0,   In::OceanGrid, &write_gr3,    true,  false, false,
     "SCHISM hgrid.gr3 + hgrid.ll", "SCHISM's hgrid.gr3 comes with hgrid.ll beside it: give a file name", true},
    {"ugrid",  ".nc",  "",          0,  0,   In::OceanGrid, &write_ugrid,  true,  true,  true,  "UGRID netCDF", ""},
};

}  // namespace

std::span<const OutputFormat> output_formats() { return kFormats; }

std::string partition_file_name(const std::string& path, int part) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return fmt::format("{}_{}.msh", has_ext ? path.substr(0, dot) : path, part);
}

const OutputFormat* find_output_format(std::string_view name) {
  for (const OutputFormat& f : kFormats)
    if (f.name == name) return &f;
  return nullptr;
}

const OutputFormat* output_format_of_number(int mesh_format) {
  for (const OutputFormat& f : kFormats)
    if (f.mesh_format != 0 && f.mesh_format == mesh_format) return &f;
  return nullptr;
}

const OutputFormat* output_format_of_extension(std::string_view extension) {
  for (const OutputFormat& f : kFormats)
    if (!f.extension.empty() && f.extension == extension) return &f;
  return nullptr;
}

std::string output_format_names() {
  std::string out;
  for (const OutputFormat& f : kFormats) out += fmt::format("{}{}", out.empty() ? "" : ", ", f.name);
  return out;
}

std::string output_format_extensions() {
  std::vector<std::string_view> exts;
  for (const OutputFormat& f : kFormats)
    if (!f.extension.empty() && output_format_of_extension(f.extension) == &f) exts.push_back(f.extension);
  std::string out;
  for (std::size_t i = 0; i < exts.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : i + 1 == exts.size() ? " or " : ", ", exts[i]);
  return out;
}

std::string output_format_help(std::size_t indent, std::size_t width) {
  // Items: a name, or a run of rows sharing a note as "a or b (note)".
  std::vector<std::string> items;
  const std::size_t n = std::size(kFormats);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    const std::string_view note = kFormats[i].note;
    while (!note.empty() && j < n && kFormats[j].note == note) ++j;
    std::string item;
    for (std::size_t k = i; k < j; ++k)
      item += fmt::format("{}{}", k == i ? "" : k + 1 == j ? " or " : ", ", kFormats[k].name);
    if (!note.empty()) item += fmt::format(" ({})", note);
    items.push_back(std::move(item));
    i = j;
  }
  std::string out = "output format:";
  std::size_t column = indent + out.size();
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::string& word = items[i];
    if (i + 1 < items.size()) word += ',';
    if (column + 1 + word.size() > width) {
      out += '\n';
      out.append(indent, ' ');
      column = indent;
    } else {
      out += ' ';
      column += 1;
    }
    out += word;
    column += word.size();
  }
  return out;
}

}  // namespace sm::io
