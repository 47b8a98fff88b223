// `import stereomesh`: runs a .geo script and meshes it in the Python process, as
// `stereomesh -2 x.geo` does, and hands the mesh over as numpy arrays instead of a file:
//   m = stereomesh.run("x.geo", setnumber={"CoastAccuracy": 10e3}, algo="front2d", threads=2)
//   m.nodes_lonlat, m.nodes_xyz, m.triangles, m.quads, m.boundary_edges, m.boundary_physical,
//   m.depth, m.size, m.partition, m.node_partition (Mesh.NbPartitions), m.stats (dict),
//   m.diagnostics (list of dicts), m.printed (Printf text)
// A script or meshing error raises stereomesh.ScriptError (file, line, column, message).
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/share_dir.h"
#include "geo/sphere.h"
#include "interp/interpreter.h"
#include "interp/kernel_state.h"
#include "interp/kernel/mesh_commands.h"
#include "interp/kernel/node_data_export.h"
#include "io/boundary_edges.h"
#include "io/from_model_mesh.h"
#include "mesh/mesh2d_algorithms.h"

namespace py = pybind11;

namespace {

using namespace sm;


// What run() returns: plain attributes, numpy arrays for the mesh.
struct Mesh {
  py::object nodes_xyz, nodes_lonlat, triangles, quads, boundary_edges, boundary_physical, depth, size;
  py::object partition, node_partition;
  py::object stats, diagnostics;
  std::string printed;
};

py::dict diagnostic_dict(const lang::SourceManager& sources, const lang::Diagnostic& d) {
  py::dict out;
  out["severity"] = std::string(lang::severity_name(d.severity));
  out["kind"] = std::string(lang::diag_info(d.kind).kebab);
  out["message"] = d.message;
  if (d.range.valid()) {
    const lang::LineCol lc = sources.line_col(d.range.begin_loc());
    out["file"] = sources.path(d.range.file);
    out["line"] = lc.line;
    out["column"] = lc.col;
  } else {
    out["file"] = py::none();
    out["line"] = py::none();
    out["column"] = py::none();
  }
  // One change among many of its statement (a coastline repair): its place and figure,
  // as --diagnostics FILE writes them.
  if (d.item.has_lonlat) {
    out["lon"] = d.item.lon;
    out["lat"] = d.item.lat;
  }
  if (!d.item.what.empty()) out["what"] = d.item.what;
  if (!d.item.figure.empty()) out["figure"] = d.item.figure;
  return out;
}

py::array_t<double> column(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

[[noreturn]] void raise_script_error(const py::object& error_type, const lang::SourceManager& sources,
                                     const lang::Diagnostics& diags, const py::list& all) {
  py::dict first;
  for (const lang::Diagnostic& d : diags.all())
    if (d.severity == lang::Severity::Error) {
      first = diagnostic_dict(sources, d);
      break;
    }
  if (first.empty()) first = py::dict(py::arg("message") = "the run failed", py::arg("file") = py::none(),
                                      py::arg("line") = py::none(), py::arg("column") = py::none());
  const py::object err = error_type(first["message"], first["file"], first["line"], first["column"], all);
  PyErr_SetObject(error_type.ptr(), err.ptr());
  throw py::error_already_set();
}

Mesh run(const py::object& error_type, const std::string& path, const std::map<std::string, double>& setnumber,
         const std::map<std::string, std::string>& setstring, const std::optional<std::string>& algo,
         std::optional<int> threads, int dim) {
  interp::RunSettings settings;
  // The stdlib beside this module (build/python/../share/stereomesh, or the prefix's share/).
  static const int anchor = 0;
  if (const auto share = base::find_share_dir(base::object_path_of(&anchor)); !share.empty())
    settings.stdlib_dir = (share / "stdlib").string();
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  std::ostringstream printed;
  interp::Interpreter in(sources, diags, printed, settings);
  in.options().set_number("General.Verbosity", 1);   // the diagnostics come back as a list
  auto refuse = [&](const std::string& why) {
    PyErr_SetString(PyExc_ValueError, why.c_str());
    throw py::error_already_set();
  };
  for (const auto& [name, v] : setnumber)
    if (auto why = in.preset_number(name, v); !why.empty()) refuse("setnumber: " + why.message);
  for (const auto& [name, v] : setstring)
    if (auto why = in.preset_string(name, v); !why.empty()) refuse("setstring: " + why.message);
  if (algo) {
    // The names of the command line's -algo (mesh/mesh2d_algorithms.h).
    const Mesh2dAlgorithmRow* row = mesh2d_algorithm_named(*algo);
    if (!row) refuse("unknown algorithm '" + *algo + "': " + mesh2d_algorithm_names(" or "));
    in.options().set_number("Mesh.Algorithm", row->number);
  }
  if (threads) in.options().set_number("General.NumThreads", *threads);
  if (dim < 0 || dim > 2) refuse("dim must be 0, 1 or 2");

  // The script, the meshing and the statistics are C++ alone (Printf goes to `printed`,
  // nothing calls back into Python): the GIL is released for them, so that other Python
  // threads, and other run() calls, go on meanwhile. Each run has its own interpreter.
  bool ok = false;
  std::string stats_json;
  {
    py::gil_scoped_release nogil;
    ok = in.run_file(path) != interp::RunStatus::Errors;
    if (ok && !in.stopped() && in.exit_request() < 0 && dim >= 1) ok = interp::mesh_after_scripts(in, dim);
    stats_json = ok ? interp::finish_run(in, false) : std::string{};
  }
  py::list all;
  for (const lang::Diagnostic& d : diags.all()) all.append(diagnostic_dict(sources, d));
  if (!ok || diags.error_count() > 0) raise_script_error(error_type, sources, diags, all);

  Mesh m;
  m.printed = printed.str();
  m.diagnostics = all;
  m.stats = stats_json.empty() ? py::object(py::none()) : py::module_::import("json").attr("loads")(stats_json);
  const interp::KernelState& k = in.kernel();
  const ModelMesh empty;
  io::MeshModel mm = io::from_model_mesh(k.model, k.mesh ? *k.mesh : empty);
  // Mesh.NbPartitions' parts of each surface's triangles, by (dim, tag).
  std::map<std::pair<int, int>, std::vector<int>> parts_of;
  if (k.partition)
    for (std::size_t i = 0; i < k.partition->entities.size(); ++i)
      if (k.partition->entities[i].first == 2) parts_of[k.partition->entities[i]] = k.partition->element_part[i];
  // The mesh and only the mesh, numbered as every file (io/from_model_mesh.h): node i
  // here is node i + 1 of the .msh, fort.14 and hgrid.gr3 and node i of VTK and UGRID.
  const auto n = static_cast<py::ssize_t>(mm.xyz.size());
  py::array_t<double> xyz({n, py::ssize_t{3}});
  auto x = xyz.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Vec3 p = mm.xyz[static_cast<std::size_t>(i)];
    x(i, 0) = p.x, x(i, 1) = p.y, x(i, 2) = p.z;
  }
  m.nodes_xyz = xyz;
  m.nodes_lonlat = py::none();
  for (const auto& [tag, g] : k.model.geometries()) {
    const geo::PolarSphere sphere(g.centre(), g.radius());
    py::array_t<double> ll({n, py::ssize_t{2}});
    auto l = ll.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
      const geo::LonLat p = sphere.to_lonlat(mm.xyz[static_cast<std::size_t>(i)]);
      l(i, 0) = p.lon, l(i, 1) = p.lat;
    }
    m.nodes_lonlat = ll;
    break;
  }
  std::vector<std::int64_t> tri;
  std::vector<std::int32_t> tri_part;
  for (const io::EntityMesh& e : mm.entities)
    if (e.dim == 2 && e.type == io::ElementType::Triangle3) {
      for (std::uint32_t v : e.connectivity) tri.push_back(v);
      if (const auto it = parts_of.find({2, e.tag}); it != parts_of.end())
        tri_part.insert(tri_part.end(), it->second.begin(), it->second.end());
    }
  py::array_t<std::int64_t> t({static_cast<py::ssize_t>(tri.size() / 3), py::ssize_t{3}});
  std::copy(tri.begin(), tri.end(), t.mutable_data());
  m.triangles = t;
  std::vector<std::int64_t> quad;
  for (const io::EntityMesh& e : mm.entities)
    if (e.dim == 2 && e.type == io::ElementType::Quad4)
      quad.insert(quad.end(), e.connectivity.begin(), e.connectivity.end());
  py::array_t<std::int64_t> qa({static_cast<py::ssize_t>(quad.size() / 4), py::ssize_t{4}});
  std::copy(quad.begin(), quad.end(), qa.mutable_data());
  m.quads = qa;
  // The partition of each triangle, and of each node the smallest of its triangles' (as
  // the VTK and UGRID partition arrays); None without Mesh.NbPartitions.
  m.partition = py::none();
  m.node_partition = py::none();
  if (k.partition && tri_part.size() * 3 == tri.size()) {
    py::array_t<std::int32_t> tp(static_cast<py::ssize_t>(tri_part.size()));
    std::copy(tri_part.begin(), tri_part.end(), tp.mutable_data());
    std::vector<std::int32_t> node_part(mm.xyz.size(), 0);
    for (std::size_t i = 0; i < tri.size(); ++i) {
      std::int32_t& p = node_part[static_cast<std::size_t>(tri[i])];
      if (p == 0 || tri_part[i / 3] < p) p = tri_part[i / 3];
    }
    py::array_t<std::int32_t> np_(static_cast<py::ssize_t>(node_part.size()));
    std::copy(node_part.begin(), node_part.end(), np_.mutable_data());
    m.partition = tp;
    m.node_partition = np_;
  }
  const std::vector<io::BoundaryEdge> edges = io::boundary_edges(mm);
  py::array_t<std::int64_t> be({static_cast<py::ssize_t>(edges.size()), py::ssize_t{2}});
  py::array_t<std::int64_t> bp(static_cast<py::ssize_t>(edges.size()));
  for (std::size_t i = 0; i < edges.size(); ++i) {
    be.mutable_data()[2 * i] = edges[i].a;
    be.mutable_data()[2 * i + 1] = edges[i].b;
    bp.mutable_data()[i] = edges[i].physical;
  }
  m.boundary_edges = be;
  m.boundary_physical = bp;
  // Depth with Mesh.DepthField, size where a size field exists; else None.
  m.depth = py::none();
  m.size = py::none();
  if (k.mesh) {
    std::vector<io::NodeData> values;
    if (in.options().number("Mesh.DepthField") > 0 && interp::node_data_named(in, mm, {"depth"}, values).empty())
      m.depth = column(values.front().values);
    if (interp::node_data_named(in, mm, {"size"}, values).empty() && !values.empty())
      m.size = column(values.front().values);
  }
  return m;
}

}  // namespace

PYBIND11_MODULE(stereomesh, mod) {
  mod.doc() = "stereomesh: Gmsh-compatible .geo scripts meshed on the sphere, the mesh as numpy arrays";
  mod.attr("__version__") = STEREOMESH_VERSION;
  // ScriptError(message, file, line, column, diagnostics): a RuntimeError with the place.
  py::dict ns;
  py::exec(R"(
class ScriptError(RuntimeError):
    """A .geo script or its meshing failed: the first error's message and place, and every
    diagnostic of the run (dicts with severity, kind, message, file, line, column)."""
    def __init__(self, message, file, line, column, diagnostics):
        place = f"{file}:{line}:{column}: " if file is not None else ""
        super().__init__(place + message)
        self.message, self.file, self.line, self.column = message, file, line, column
        self.diagnostics = diagnostics
)",
           py::globals(), ns);
  py::object error_type = ns["ScriptError"];
  error_type.attr("__module__") = "stereomesh";
  mod.attr("ScriptError") = error_type;

  py::class_<Mesh>(mod, "Mesh", "A mesh made by stereomesh.run")
      .def_readonly("nodes_xyz", &Mesh::nodes_xyz, "(N, 3) float64: node coordinates as meshed")
      .def_readonly("nodes_lonlat", &Mesh::nodes_lonlat, "(N, 2) float64 lon/lat degrees on a sphere, else None")
      .def_readonly("triangles", &Mesh::triangles, "(T, 3) int64: 0-based node indices")
      .def_readonly("quads", &Mesh::quads, "(Q, 4) int64: 0-based node indices of the quadrangles (Recombine)")
      .def_readonly("boundary_edges", &Mesh::boundary_edges, "(E, 2) int64: the mesh boundary's edges")
      .def_readonly("boundary_physical", &Mesh::boundary_physical, "(E,) int64: physical curve group (0: none)")
      .def_readonly("depth", &Mesh::depth, "(N,) float64 from Mesh.DepthField, else None")
      .def_readonly("size", &Mesh::size, "(N,) float64 target size at the nodes, else None")
      .def_readonly("partition", &Mesh::partition,
                    "(T,) int32 partition 1..N of each triangle with Mesh.NbPartitions (METIS), else None")
      .def_readonly("node_partition", &Mesh::node_partition,
                    "(N,) int32 the smallest partition of each node's triangles, else None")
      .def_readonly("stats", &Mesh::stats, "the statistics of --stats as a dict (None without a 2D mesh)")
      .def_readonly("diagnostics", &Mesh::diagnostics,
                    "warnings and notes: dicts (severity, kind, message, file, line, column)")
      .def_readonly("printed", &Mesh::printed, "what the script's Printf wrote")
      .def("__repr__", [](const Mesh& m) {
        return "<stereomesh.Mesh: " + std::to_string(py::len(m.nodes_xyz)) + " nodes, " +
               std::to_string(py::len(m.triangles)) + " triangles>";
      });

  mod.def(
      "run",
      [error_type](const std::string& path, const std::map<std::string, double>& setnumber,
                   const std::map<std::string, std::string>& setstring, const std::optional<std::string>& algo,
                   std::optional<int> threads, int dim) {
        return run(error_type, path, setnumber, setstring, algo, threads, dim);
      },
      py::arg("path"), py::arg("setnumber") = std::map<std::string, double>{},
      py::arg("setstring") = std::map<std::string, std::string>{}, py::arg("algo") = py::none(),
      py::arg("threads") = py::none(), py::arg("dim") = 2,
      ("Runs the .geo script at `path` (setnumber / setstring as -setnumber / -setstring; algo as -algo: " +
       mesh2d_algorithm_names(", ") +
       "; threads as -nt) and meshes it up to `dim` (0: evaluate only), as `stereomesh -2` does. Returns a Mesh; "
       "raises ScriptError on a script or meshing error.")
          .c_str());
  // The names run() takes as algo, with their Mesh.Algorithm (mesh/mesh2d_algorithms.h).
  py::dict algorithms;
  for (const Mesh2dAlgorithmRow& r : kMesh2dAlgorithms) algorithms[py::str(std::string(r.name))] = r.number;
  mod.attr("algorithms") = algorithms;
}
