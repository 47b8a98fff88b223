// METIS partitions of a grid and the partitioned entities built from them (MSH 4.1's
// $PartitionedEntities): each element in one part, balance, the cut, interfaces between
// parts, nodes owned once, one file per part.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>

#include "io/mesh_partition.h"
#include "io/msh_writer.h"
#include "io/partitioned_model.h"
#include "io/test_meshes.h"

namespace {

sm::io::MeshPartition partition_of(const sm::io::MeshModel& m, int parts, int algorithm = 1) {
  sm::io::MeshPartitionOptions opt;
  opt.parts = parts;
  opt.algorithm = algorithm;
  sm::io::MeshPartition p;
  sm::io::PartitionError error;
  REQUIRE(sm::io::partition_mesh(m, opt, &p, &error));
  CHECK(error.problem == sm::io::PartitionProblem::None);
  return p;
}

std::set<std::uint32_t> side(std::uint32_t a, std::uint32_t b) { return {a, b}; }

}  // namespace

TEST_CASE("mesh partition: every element in a part, within 3% and the cut counted") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(16);   // 512 triangles
  for (int algorithm : {1, 2}) {
    CAPTURE(algorithm);
    const sm::io::MeshPartition p = partition_of(m, 4, algorithm);
    CHECK(p.parts == 4);
    const std::vector<int>& tri = p.element_part.back();   // the surface
    REQUIRE(tri.size() == 512);
    std::map<int, int> count;
    for (int q : tri) ++count[q];
    CHECK(count.size() == 4);
    for (const auto& [q, n] : count) {
      CHECK(q >= 1);
      CHECK(q <= 4);
      CHECK(n <= 1.03 * 128);
    }
    CHECK(p.imbalance <= 1.03);
    CHECK(p.part_elements.size() == 4);
    // The cut: pairs of triangles sharing a side in different parts.
    const sm::io::EntityMesh& s = m.entities.back();
    std::map<std::set<std::uint32_t>, std::vector<int>> parts_on;
    for (std::size_t k = 0; k < tri.size(); ++k)
      for (int j = 0; j < 3; ++j)
        parts_on[side(s.connectivity[3 * k + j], s.connectivity[3 * k + (j + 1) % 3])].push_back(tri[k]);
    std::uint64_t cut = 0;
    for (const auto& [e, qs] : parts_on) cut += qs.size() == 2 && qs[0] != qs[1];
    CHECK(p.edge_cut == cut);
    CHECK(cut > 0);
    // A line takes the part of the triangle it is a side of; a node the smallest part
    // of the elements using it.
    for (std::size_t i = 0; i < 4; ++i) {
      const sm::io::EntityMesh& c = m.entities[4 + i];
      for (std::size_t k = 0; k < p.element_part[4 + i].size(); ++k) {
        const std::vector<int>& qs = parts_on.at(side(c.connectivity[2 * k], c.connectivity[2 * k + 1]));
        REQUIRE(qs.size() == 1);
        CHECK(p.element_part[4 + i][k] == qs[0]);
      }
    }
    for (std::size_t k = 0; k < tri.size(); ++k)
      for (int j = 0; j < 3; ++j) CHECK(p.node_part[s.connectivity[3 * k + j]] <= tri[k]);
    // The same answer every time (METIS seeded).
    CHECK(partition_of(m, 4, algorithm).element_part == p.element_part);
  }
}

TEST_CASE("mesh partition: one part, too many parts, nothing to partition") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(2);
  const sm::io::MeshPartition one = partition_of(m, 1);
  CHECK(std::all_of(one.element_part.back().begin(), one.element_part.back().end(), [](int q) { return q == 1; }));
  CHECK(one.edge_cut == 0);
  sm::io::MeshPartitionOptions opt;
  opt.parts = 9;   // 8 triangles
  sm::io::MeshPartition p;
  sm::io::PartitionError error;
  CHECK_FALSE(sm::io::partition_mesh(m, opt, &p, &error));
  CHECK(error.problem == sm::io::PartitionProblem::PartCount);
  CHECK(error.elements == 8);
  sm::io::MeshModel lines = m;
  lines.entities.pop_back();
  opt.parts = 2;
  CHECK_FALSE(sm::io::partition_mesh(lines, opt, &p, &error));
  CHECK(error.problem == sm::io::PartitionProblem::NoElements);
}

TEST_CASE("partitioned model: pieces, interfaces and partition points, each node owned once") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(12);
  const sm::io::MeshPartition p = partition_of(m, 3);
  const sm::io::MeshModel pm = sm::io::partitioned_model(m, p);
  CHECK(sm::io::validate_mesh_model(pm).empty());
  CHECK(pm.num_partitions == 3);
  std::map<std::set<std::uint32_t>, int> tri_part;   // triangle -> its piece's part
  std::size_t interfaces = 0, points = 0;
  for (const sm::io::EntityMesh& e : pm.entities) {
    if (e.partitions.empty()) {
      CHECK(e.connectivity.empty());   // the model's entities hold no element any more
      continue;
    }
    CHECK(std::is_sorted(e.partitions.begin(), e.partitions.end()));
    if (e.dim == 2) {
      REQUIRE(e.partitions.size() == 1);
      CHECK(e.parent_dim == 2);
      CHECK(e.parent_tag == 1);
      CHECK(e.physical_tags == std::vector<int>{7});   // the parent's groups
      CHECK(e.tag > 1);
      for (std::size_t k = 0; k < e.connectivity.size(); k += 3)
        CHECK(tri_part.emplace(std::set<std::uint32_t>(&e.connectivity[k], &e.connectivity[k] + 3), e.partitions[0])
                  .second);
    }
    if (e.dim == 1 && e.partitions.size() == 2) {
      ++interfaces;
      CHECK(e.parent_dim == 2);
      CHECK(e.physical_tags.empty());
      CHECK(e.tag > 4);
    }
    if (e.dim == 0 && e.partitions.size() >= 2) ++points;
  }
  CHECK(tri_part.size() == 288);   // every triangle, once
  CHECK(interfaces >= 2);          // 3 parts of a square meet along at least 2 curves
  CHECK(points >= 1);
  // An interface line is a side of one triangle of each of its two parts.
  for (const sm::io::EntityMesh& e : pm.entities) {
    if (e.dim != 1 || e.partitions.size() != 2) continue;
    for (std::size_t k = 0; k < e.connectivity.size(); k += 2) {
      std::set<int> around;
      for (const auto& [t, q] : tri_part)
        if (t.count(e.connectivity[k]) && t.count(e.connectivity[k + 1])) around.insert(q);
      CHECK(around == std::set<int>(e.partitions.begin(), e.partitions.end()));
    }
  }
  // Written with $PartitionedEntities after $Entities, the model's boxes kept.
  const std::string msh = sm::io::msh_to_string(pm, {});
  CHECK(msh.find("$Entities\n") < msh.find("$PartitionedEntities\n3\n0\n"));
  CHECK(msh.find("$EndPartitionedEntities\n") < msh.find("$Nodes\n"));
  CHECK(msh.find("\n1 0 0 0 1 1 0 1 7 4 1 2 3 4 \n") != std::string::npos);   // surface 1: its box, group, curves
}

TEST_CASE("partitioned model: one part's file holds that part's triangles and the model's entities") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(10);
  const sm::io::MeshPartition p = partition_of(m, 4, 2);
  const sm::io::MeshModel pm = sm::io::partitioned_model(m, p);
  std::size_t total = 0;
  for (int k = 1; k <= 4; ++k) {
    CAPTURE(k);
    const sm::io::MeshModel piece = sm::io::partition_piece(pm, k);
    CHECK(sm::io::validate_mesh_model(piece).empty());
    std::size_t model_entities = 0, triangles = 0;
    for (const sm::io::EntityMesh& e : piece.entities) {
      if (e.partitions.empty()) {
        ++model_entities;
        CHECK(e.nodes.empty());
        continue;
      }
      CHECK(std::find(e.partitions.begin(), e.partitions.end(), k) != e.partitions.end());
      if (e.dim == 2) triangles += e.connectivity.size() / 3;
    }
    CHECK(model_entities == 9);
    CHECK(triangles == p.part_elements[k - 1]);
    total += triangles;
  }
  CHECK(total == 200);
}

TEST_CASE("mesh partition: realigned to a mesh model with an entity left out") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(4);
  const sm::io::MeshPartition p = partition_of(m, 2);
  sm::io::MeshModel fewer = m;
  fewer.entities.erase(fewer.entities.begin());   // point 1, as the lon/lat coordinates drop a centre point
  std::swap(fewer.entities[0], fewer.entities[1]);
  const sm::io::MeshPartition a = sm::io::aligned_partition(p, fewer);
  REQUIRE(a.element_part.size() == fewer.entities.size());
  for (std::size_t i = 0; i < fewer.entities.size(); ++i) {
    const auto key = std::make_pair(fewer.entities[i].dim, fewer.entities[i].tag);
    CHECK(a.entities[i] == key);
    const std::size_t row =
        static_cast<std::size_t>(std::find(p.entities.begin(), p.entities.end(), key) - p.entities.begin());
    CHECK(a.element_part[i] == p.element_part[row]);
  }
  CHECK(a.node_part == p.node_part);
}

TEST_CASE("partitioned model: a part in two pieces gives two entities, as Gmsh divides them") {
  // A 3 x 3 grid: rows 0 and 2 in part 1, row 1 in part 2; lines and points take their
  // triangles' parts.
  const int n = 3;
  const sm::io::MeshModel m = sm::io::testing::grid_square(n);
  sm::io::MeshPartition p;
  p.parts = 2;
  const auto row_part = [](int row) { return row == 1 ? 2 : 1; };
  for (const sm::io::EntityMesh& e : m.entities) {
    std::vector<int> parts;
    const int npe = sm::io::nodes_per_element(e.type);
    for (std::size_t k = 0; k < e.connectivity.size(); k += npe) {
      double y = 0;   // the element's row from its mean y
      for (int j = 0; j < npe; ++j) y += m.xyz[e.connectivity[k + j]].y / npe;
      parts.push_back(row_part(std::min(n - 1, static_cast<int>(y * n))));
    }
    p.element_part.push_back(parts);
    p.entities.emplace_back(e.dim, e.tag);
  }
  const sm::io::MeshModel pm = sm::io::partitioned_model(m, p);
  CHECK(sm::io::validate_mesh_model(pm).empty());
  std::map<int, int> surfaces_of_part, interfaces;
  std::map<int, const sm::io::EntityMesh*> by_tag;
  for (const sm::io::EntityMesh& e : pm.entities) {
    if (e.partitions.empty()) continue;
    if (e.dim == 2) ++surfaces_of_part[e.partitions[0]], by_tag[e.tag] = &e;
    if (e.dim == 1 && e.partitions.size() == 2) {
      ++interfaces[e.tag];
      CHECK(e.connectivity.size() == 2 * n);   // one row boundary: n lines, connected
    }
  }
  CHECK(surfaces_of_part == std::map<int, int>{{1, 2}, {2, 1}});
  CHECK(interfaces.size() == 2);
  // Each piece of part 1 is bounded by one interface, the piece of part 2 by both, with
  // opposite signs on the two sides.
  std::map<int, int> sign_sum;
  for (const auto& [tag, s] : by_tag) {
    int count = 0;
    for (int b : s->boundary)
      if (interfaces.count(std::abs(b))) ++count, sign_sum[std::abs(b)] += b > 0 ? 1 : -1;
    CHECK(count == (s->partitions[0] == 1 ? 1 : 2));
  }
  for (const auto& [tag, sum] : sign_sum) CHECK(sum == 0);
  // The right and left curves' part-1 lines are two pieces each.
  std::map<int, int> pieces_of_curve;
  for (const sm::io::EntityMesh& e : pm.entities)
    if (e.dim == 1 && e.partitions == std::vector<int>{1}) ++pieces_of_curve[e.parent_tag];
  CHECK(pieces_of_curve == std::map<int, int>{{1, 1}, {2, 2}, {3, 1}, {4, 2}});
}

TEST_CASE("partitioned model: without topology, the pieces only") {
  const sm::io::MeshModel m = sm::io::testing::grid_square(8);
  const sm::io::MeshPartition p = partition_of(m, 3);
  const sm::io::MeshModel pm = sm::io::partitioned_model(m, p, /*topology=*/false);
  CHECK(sm::io::validate_mesh_model(pm).empty());
  std::size_t triangles = 0;
  for (const sm::io::EntityMesh& e : pm.entities) {
    if (e.partitions.empty()) continue;
    CHECK(e.partitions.size() == 1);   // no interface, no partition point
    CHECK(e.parent_dim == e.dim);
    if (e.dim == 2) triangles += e.connectivity.size() / 3;
  }
  CHECK(triangles == 128);
}
