// The MSH writer against files written by Gmsh 4.8.4 itself (tests/data/io):
// the same mesh must give the same bytes, in both versions, ASCII and binary.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "io/msh_writer.h"
#include "io/test_meshes.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {


// Rebuilds Gmsh's unit-square mesh from its MSH 4.1 ASCII file (entities,
// node blocks, element blocks), adding one point element per model point as
// Gmsh's mesh has them.
MeshModel load_square() {
  std::istringstream in(sm::testing::read_all(SM_TEST_DATA "/io/sq41.msh"));
  std::string line;
  MeshModel m;
  while (std::getline(in, line) && line != "$Entities") {}
  int np, nc, ns, nv;
  in >> np >> nc >> ns >> nv;
  std::map<std::pair<int, int>, std::size_t> index;
  for (int i = 0; i < np + nc + ns; ++i) {
    EntityMesh e;
    e.dim = i < np ? 0 : i < np + nc ? 1 : 2;
    in >> e.tag;
    double skip;
    for (int k = 0; k < (e.dim == 0 ? 3 : 6); ++k) in >> skip;
    int nphys;
    in >> nphys;
    e.physical_tags.resize(nphys);
    for (int& t : e.physical_tags) in >> t;
    if (e.dim > 0) {
      int nb;
      in >> nb;
      e.boundary.resize(nb);
      for (int& t : e.boundary) in >> t;
    }
    e.type = e.dim == 0 ? ElementType::Point1 : e.dim == 1 ? ElementType::Line2 : ElementType::Triangle3;
    index[{e.dim, e.tag}] = m.entities.size();
    m.entities.push_back(e);
  }
  while (std::getline(in, line) && line != "$Nodes") {}
  std::size_t nblocks, nnodes, lo, hi;
  in >> nblocks >> nnodes >> lo >> hi;
  m.xyz.resize(nnodes);
  for (std::size_t b = 0; b < nblocks; ++b) {
    int dim, tag, param;
    std::size_t n;
    in >> dim >> tag >> param >> n;
    EntityMesh& e = m.entities[index[{dim, tag}]];
    std::vector<std::size_t> tags(n);
    for (auto& t : tags) in >> t;
    for (std::size_t t : tags) {
      in >> m.xyz[t - 1].x >> m.xyz[t - 1].y >> m.xyz[t - 1].z;
      e.nodes.push_back(static_cast<std::uint32_t>(t - 1));
    }
  }
  while (std::getline(in, line) && line != "$Elements") {}
  in >> nblocks >> nnodes >> lo >> hi;
  for (std::size_t b = 0; b < nblocks; ++b) {
    int dim, tag, type;
    std::size_t n;
    in >> dim >> tag >> type >> n;
    EntityMesh& e = m.entities[index[{dim, tag}]];
    const int npe = nodes_per_element(static_cast<ElementType>(type));
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t elm, v;
      in >> elm;
      for (int j = 0; j < npe; ++j) {
        in >> v;
        e.connectivity.push_back(static_cast<std::uint32_t>(v - 1));
      }
    }
  }
  for (EntityMesh& e : m.entities)
    if (e.dim == 0) e.connectivity = e.nodes;
  m.physicals = {{1, 1, "bnd"}, {2, 7, "dom"}};
  // The ASCII file keeps 16 significant digits; take the exact doubles from
  // Gmsh's binary MSH 2.2 file (records: int tag, 3 doubles), so that the
  // binary outputs can be compared bit for bit too.
  const std::string bin = sm::testing::read_all(SM_TEST_DATA "/io/sq22b.msh");
  std::size_t at = bin.find("$Nodes\n12\n") + 10;
  for (std::size_t k = 0; k < m.xyz.size(); ++k, at += 4 + 24) {
    int tag;
    std::memcpy(&tag, &bin[at], 4);
    std::memcpy(&m.xyz[tag - 1], &bin[at + 4], 24);
  }
  return m;
}

}  // namespace

TEST_CASE("msh: the square's mesh is valid") {
  const MeshModel m = load_square();
  CHECK(validate_mesh_model(m).empty());
  CHECK(m.xyz.size() == 12);
  CHECK(m.element_count() == 4 + 8 + 14);
}

TEST_CASE("msh 4.1 ASCII: byte-identical to Gmsh 4.8.4") {
  CHECK(msh_to_string(load_square(), {41, false}) == sm::testing::read_all(SM_TEST_DATA "/io/sq41.msh"));
}

TEST_CASE("msh 4.1 binary: byte-identical to Gmsh 4.8.4") {
  CHECK(msh_to_string(load_square(), {41, true}) == sm::testing::read_all(SM_TEST_DATA "/io/sq41b.msh"));
}

TEST_CASE("msh 2.2 ASCII and binary: byte-identical to Gmsh 4.8.4") {
  CHECK(msh_to_string(load_square(), {22, false}) == sm::testing::read_all(SM_TEST_DATA "/io/sq22.msh"));
  CHECK(msh_to_string(load_square(), {22, true}) == sm::testing::read_all(SM_TEST_DATA "/io/sq22b.msh"));
}

TEST_CASE("msh 2.2 SaveAll: every entity, physical tags written as 0") {
  CHECK(msh_to_string(load_square(), {22, false, true}) == sm::testing::read_all(SM_TEST_DATA "/io/sq22all.msh"));
}

TEST_CASE("msh: a point entity may have tag 0 (Gmsh writes and reads it), no other entity may") {
  MeshModel m = load_square();
  REQUIRE(m.entities[0].dim == 0);
  m.entities[0].tag = 0;
  CHECK(validate_mesh_model(m).empty());
  MeshModel curve0 = load_square();
  for (EntityMesh& e : curve0.entities)
    if (e.dim == 1) {
      e.tag = 0;
      break;
    }
  CHECK(validate_mesh_model(curve0).find("invalid entity (dim 1, tag 0)") != std::string::npos);
}

TEST_CASE("msh: invalid models are rejected before anything is written") {
  MeshModel m = load_square();
  m.entities[0].nodes.push_back(m.entities[5].nodes[0]);  // a node owned twice
  CHECK(validate_mesh_model(m).find("owned by two entities") != std::string::npos);
  MeshModel bad = load_square();
  for (int k = 0; k < 3; ++k) bad.entities.back().connectivity.push_back(999);
  CHECK(validate_mesh_model(bad).find("out of range") != std::string::npos);
  std::string error;
  const sm::testing::ScratchDir scratch;
  const std::string path = scratch / "invalid.msh";
  CHECK_FALSE(save_msh(bad, {}, path, &error));
  CHECK(error.find("invalid mesh") != std::string::npos);
  CHECK(::access(path.c_str(), F_OK) != 0);
}

TEST_CASE("msh: atomic save replaces the file, a failed save leaves it intact") {
  const MeshModel m = load_square();
  const sm::testing::ScratchDir scratch;
  const std::string dir = scratch.path.string();
  const std::string path = dir + "/sq.msh";
  std::string error;
  REQUIRE(save_msh(m, {}, path, &error));
  CHECK(sm::testing::read_all(path) == sm::testing::read_all(SM_TEST_DATA "/io/sq41.msh"));
  // A missing directory: the reason (callers name the file), nothing created.
  CHECK_FALSE(save_msh(m, {}, dir + "/no/such/dir/sq.msh", &error));
  CHECK(error == "No such file or directory");
  if (::geteuid() != 0) {  // root ignores directory permissions
    ::chmod(dir.c_str(), 0555);
    CHECK_FALSE(save_msh(m, {22, false}, path, &error));
    ::chmod(dir.c_str(), 0755);
  }
  CHECK(sm::testing::read_all(path) == sm::testing::read_all(SM_TEST_DATA "/io/sq41.msh"));
}


TEST_CASE("msh: every variant loads in Gmsh 4.8.4 with the same counts") {
  if (std::system("/usr/bin/python3 -c 'import gmsh' >/dev/null 2>&1") != 0) {
    MESSAGE("python3-gmsh not installed: skipped");
    return;
  }
  const MeshModel m = sm::io::testing::grid_square(40);
  REQUIRE(validate_mesh_model(m).empty());
  const sm::testing::ScratchDir scratch;
  const std::string script = scratch / "load.py";
  // One Python run loads every variant (starting Gmsh's module costs most of the time).
  std::ofstream(script) << "import sys, gmsh\n"
                           "gmsh.initialize(['x', '-v', '0'])\n"
                           "for path in sys.argv[1:]:\n"
                           "    gmsh.clear()\n"
                           "    gmsh.open(path)\n"
                           "    tags, _, _ = gmsh.model.mesh.getNodes()\n"
                           "    types, etags, _ = gmsh.model.mesh.getElements(2)\n"
                           "    names = [gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()]\n"
                           "    print(path, len(tags), sum(len(e) for e in etags), ','.join(names))\n";
  std::string paths, want;
  for (int version : {22, 41})
    for (bool binary : {false, true})
      for (bool parametric : {false, true}) {
        if (version == 22 && parametric) continue;
        const std::string path = scratch / fmt::format("grid_{}_{}_{}.msh", version, binary, parametric);
        std::string error;
        REQUIRE(save_msh(m, {version, binary, false, parametric}, path, &error));
        paths += " " + path;
        want += path + " 1681 3200 coast,ocean\n";
      }
  const std::string out = scratch / "load.txt";
  REQUIRE(std::system(("/usr/bin/python3 " + script + paths + " > " + out).c_str()) == 0);
  CHECK(sm::testing::read_all(out) == want);
}

TEST_CASE("msh 4.1: a surface with triangles and quadrangles is one entity, one node block, two element blocks") {
  sm::io::MeshModel m = sm::io::testing::grid_square(2);
  // The first row of cells as quadrangles: a second record of surface 1, no nodes.
  sm::io::EntityMesh& tri = m.entities.back();
  sm::io::EntityMesh quad;
  quad.dim = 2, quad.tag = 1, quad.type = sm::io::ElementType::Quad4, quad.physical_tags = tri.physical_tags;
  quad.boundary = tri.boundary;
  quad.connectivity = {0, 1, 4, 3, 1, 2, 5, 4};
  tri.connectivity.erase(tri.connectivity.begin(), tri.connectivity.begin() + 12);
  m.entities.push_back(quad);
  CHECK(sm::io::validate_mesh_model(m).empty());
  sm::io::MshOptions o;
  const std::string s = sm::io::msh_to_string(m, o);
  // $Entities: 4 points, 4 curves, 1 surface.
  CHECK(s.find("$Entities\n4 4 1 0\n") != std::string::npos);
  // Element blocks (the physical entities): 4 curves, the surface's triangles and its quadrangles.
  CHECK(s.find("$Elements\n6 ") != std::string::npos);
  CHECK(s.find("\n2 1 2 4\n") != std::string::npos);   // 4 triangles
  CHECK(s.find("\n2 1 3 2\n") != std::string::npos);   // 2 quadrangles
  // One node block for the surface (its one interior node).
  CHECK(s.find("\n2 1 0 1\n") != std::string::npos);
  CHECK(s.find("\n2 1 0 0\n") == std::string::npos);
  // A second block that owns nodes is refused.
  m.entities.back().nodes = {4};
  CHECK_FALSE(sm::io::validate_mesh_model(m).empty());
}
