// The MSH reader against the writer (both versions), and its refusals, each at its line.
#include <doctest/doctest.h>

#include <string>

#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "io/test_meshes.h"

using namespace sm::io;

TEST_CASE("msh reader: what the writer wrote, in MSH 4.1 and 2.2") {
  const MeshModel m = testing::grid_square(3);
  for (int version : {41, 22}) {
    CAPTURE(version);
    MshOptions opt;
    opt.version = version;
    opt.save_all = true;
    const MshReadResult r = read_msh(msh_to_string(m, opt));
    REQUIRE_MESSAGE(r.ok(), r.error);
    CHECK(r.file.version == (version == 41 ? 4.1 : 2.2));
    CHECK(r.file.nodes.size() == 16);
    REQUIRE(r.file.blocks.size() == 9);   // 4 points, 4 curves, 1 surface
    const MshBlock& s = r.file.blocks.back();
    CHECK(s.dim == 2);
    CHECK(s.tag == 1);
    CHECK(s.type == ElementType::Triangle3);
    CHECK(s.nodes.size() == 3 * 18);
    const MshBlock& c = r.file.blocks[4];
    CHECK(c.dim == 1);
    CHECK(c.nodes.size() == 2 * 3);
    // The nodes' places: the first curve's elements run along y = 0.
    for (std::uint64_t n : c.nodes) CHECK(r.file.nodes.at(n).y == 0.0);
  }
  MshOptions opt;   // with its physical groups (not SaveAll): 4.1 keeps them per entity
  const MshReadResult r = read_msh(msh_to_string(m, opt));
  REQUIRE(r.ok());
  CHECK(r.file.physical_names.size() == 2);
  CHECK(r.file.blocks.back().physical_tags == std::vector<int>{7});
}

TEST_CASE("msh reader: refusals name the line") {
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  struct Case {
    std::string text;
    std::size_t line;
    const char* says;
  };
  const Case cases[] = {
      {"$MeshFormat\n2.2 1 8\n$EndMeshFormat\n", 2, "binary"},
      {"$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", 2, "version"},
      {head + "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 1 1 1\n$EndElements\n", 10, "element type 4"},
      {head + "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 1 2 0 1 1 2\n$EndElements\n", 10, "node 2"},
      {head + "$Nodes\n99999\n1 0 0 0\n$EndNodes\n", 5, "count 99999"},
      {head + "$Nodes\n1\n1 0 x 0\n$EndNodes\n", 6, "'x' is not a number"},
      {head + "$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n", 7, "given twice"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    const MshReadResult r = read_msh(c.text);
    REQUIRE_FALSE(r.ok());
    CHECK(r.line == c.line);
    CHECK(r.error.find(c.says) != std::string::npos);
  }
}
