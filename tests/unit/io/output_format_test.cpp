// io/output_format: the table of output formats every writer caller reads.
#include "io/output_format.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <string>

using namespace sm::io;

TEST_CASE("output formats: one row per name, each with a writer, MSH first") {
  std::set<std::string_view> names;
  for (const OutputFormat& f : output_formats()) {
    CAPTURE(f.name);
    CHECK(names.insert(f.name).second);
    CHECK((f.write != nullptr));
    REQUIRE(!f.extension.empty());
    CHECK(f.extension.front() == '.');
    CHECK(find_output_format(f.name) == &f);
    // A name that implies an MSH version is an MSH format.
    if (f.msh_file_version != 0) CHECK(f.mesh_format == 1);
  }
  CHECK(output_formats().front().name == "msh");
  CHECK(find_output_format("stl") == nullptr);
  CHECK(find_output_format("") == nullptr);
}

TEST_CASE("output formats: Mesh.Format numbers and extensions pick the first row that has them") {
  CHECK(output_format_of_number(1)->name == "msh");
  CHECK(output_format_of_number(16)->name == "vtk");
  CHECK(output_format_of_number(0) == nullptr);
  CHECK(output_format_of_number(10) == nullptr);   // auto: by the extension
  CHECK(output_format_of_extension(".msh")->name == "msh");
  CHECK(output_format_of_extension(".14")->name == "fort14");
  CHECK(output_format_of_extension(".gr3")->name == "gr3");
  CHECK(output_format_of_extension("") == nullptr);
  CHECK(output_format_of_extension(".txt") == nullptr);
  CHECK(output_format_extensions() == ".msh, .vtk, .svg, .png, .14, .gr3 or .nc");
  CHECK(output_format_names() == "msh, msh2, msh22, msh4, msh41, vtk, svg, png, fort14, gr3, ugrid");
}

TEST_CASE("output formats: what each can hold") {
  const OutputFormat& msh = *find_output_format("msh41");
  CHECK((msh.holds_quads && msh.holds_partitions && msh.holds_node_data));
  CHECK(find_output_format("vtk")->holds_partitions);     // cell and point arrays
  CHECK(find_output_format("ugrid")->holds_partitions);
  CHECK_FALSE(find_output_format("msh22")->holds_partitions);   // its partition tags are not written
  CHECK_FALSE(find_output_format("fort14")->holds_partitions);
  CHECK_FALSE(find_output_format("gr3")->holds_partitions);
  CHECK_FALSE(find_output_format("svg")->holds_partitions);
  CHECK_FALSE(find_output_format("fort14")->holds_quads);   // ADCIRC: triangles only
  CHECK_FALSE(find_output_format("png")->holds_node_data);
}

TEST_CASE("output formats: split partition files are named as Gmsh names them") {
  CHECK(partition_file_name("out/gulf.msh", 3) == "out/gulf_3.msh");
  CHECK(partition_file_name("a.b/gulf", 1) == "a.b/gulf_1.msh");
  CHECK(partition_file_name("gulf.mesh.msh", 12) == "gulf.mesh_12.msh");
}

TEST_CASE("output formats: the help lists every name, rows sharing a note together, within the width") {
  const std::string help = output_format_help(22, 100);
  CHECK(help == "output format: msh, msh2, msh22, msh4, msh41, vtk, svg or png (a picture),\n"
                "                      fort14 (ADCIRC), gr3 (SCHISM hgrid.gr3 + hgrid.ll), ugrid (UGRID netCDF)");
  for (const OutputFormat& f : output_formats()) CHECK(help.find(f.name) != std::string::npos);
  // Narrower: more lines, none past the width (a line starts after the 22 columns of the flag).
  const std::string narrow = output_format_help(22, 60);
  std::size_t start = 0, lines = 0;
  while (start <= narrow.size()) {
    const std::size_t end = std::min(narrow.find('\n', start), narrow.size());
    CHECK((lines == 0 ? 22 : 0) + (end - start) <= 60);   // continuation lines hold their indent
    ++lines;
    start = end + 1;
  }
  CHECK(lines > 2);
}
