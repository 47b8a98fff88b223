// io/msh_writer on several threads: the ASCII text is formatted in chunks of fixed bounds
// and appended in order, so every version and variant is the same bytes for any count.
#include <doctest/doctest.h>

#include <string>

#include <fmt/format.h>

#include "io/msh_writer.h"
#include "io/test_meshes.h"

TEST_CASE("msh threads: 2.2 and 4.1, ASCII and binary, parametric: the same bytes for 1, 2, 3 and 5 threads") {
  // 151^2 nodes and 45,000 triangles: several chunks of 16,384 lines each.
  const sm::io::MeshModel m = sm::io::testing::grid_square(150);
  for (int version : {22, 41})
    for (bool binary : {false, true})
      for (bool parametric : {false, true}) {
        if (version == 22 && parametric) continue;
        CAPTURE(version);
        CAPTURE(binary);
        CAPTURE(parametric);
        sm::io::MshOptions o;
        o.version = version;
        o.binary = binary;
        o.save_parametric = parametric;
        o.threads = 1;
        const std::string one = sm::io::msh_to_string(m, o);
        CHECK(one.size() > 1000000);
        for (int threads : {2, 3, 5}) {
          o.threads = threads;
          CHECK(sm::io::msh_to_string(m, o) == one);
        }
        if (binary) continue;
        // The lines themselves: the last element (the physical curves' 600 lines, then the
        // triangles; the points are in no group) and a surface node's coordinates.
        const std::size_t last_elm = 4 * 150 + 2 * 150 * 150;
        CHECK(one.find(fmt::format("\n{} ", last_elm)) != std::string::npos);
        CHECK(one.find(fmt::format("{:.16g} {:.16g} 0", 149.0 / 150, 149.0 / 150)) != std::string::npos);
      }
}

TEST_CASE("msh threads: blocks of several waves (written while the next is formatted) the same bytes for 1, 2, 3") {
  // 331^2 nodes and 217,800 triangles: 14 chunks of 16,384 elements, more than one wave of
  // 4 chunks a thread at 2 and 3 threads, so waves are written beside the next one's making.
  const sm::io::MeshModel m = sm::io::testing::grid_square(330);
  for (int version : {22, 41}) {
    CAPTURE(version);
    sm::io::MshOptions o;
    o.version = version;
    o.threads = 1;
    const std::string one = sm::io::msh_to_string(m, o);
    for (int threads : {2, 3}) {
      CAPTURE(threads);
      o.threads = threads;
      CHECK(sm::io::msh_to_string(m, o) == one);
    }
  }
}

TEST_CASE("msh threads: thousands of small blocks (a world's coast curves) grouped, with large ones between, the "
          "same bytes for 1, 2 and 3 threads") {
  // 6000 curves of 7 nodes and 6 lines each, curve 3000 with 40,000 nodes (its own
  // chunks amid the groups of small blocks), each curve owning its nodes.
  sm::io::MeshModel m;
  for (int c = 1; c <= 6000; ++c) {
    sm::io::EntityMesh e;
    e.dim = 1, e.tag = c, e.type = sm::io::ElementType::Line2;
    const std::uint32_t n = c == 3000 ? 40000 : 7;
    for (std::uint32_t k = 0; k < n; ++k) {
      e.nodes.push_back(static_cast<std::uint32_t>(m.xyz.size()));
      m.xyz.push_back({c + k / 3.0, c * 0.1 - k / 7.0, 0});
      if (k > 0) e.connectivity.insert(e.connectivity.end(), {e.nodes[k - 1], e.nodes[k]});
    }
    m.entities.push_back(std::move(e));
  }
  sm::io::MshOptions o;
  o.version = 41;
  o.threads = 1;
  const std::string one = sm::io::msh_to_string(m, o);
  CHECK(one.find("\n1 3000 0 40000\n") != std::string::npos);   // the large block's header
  CHECK(one.find("\n1 5999 1 6\n") != std::string::npos);       // a small one's element header
  for (int threads : {2, 3}) {
    CAPTURE(threads);
    o.threads = threads;
    CHECK(sm::io::msh_to_string(m, o) == one);
  }
}
