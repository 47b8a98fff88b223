// Option registry: 4.8.4 defaults, aliases, validation, suggestions.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "interp/options.h"

using sm::interp::Options;
using sm::lang::Diag;

TEST_CASE("options: defaults from the 4.8.4 manual") {
  Options o;
  CHECK(Options::table().size() > 500);
  CHECK(o.number("Mesh.Algorithm") == 6);
  CHECK(o.number("Mesh.MeshSizeMax") == 1e22);
  CHECK(o.number("Mesh.MshFileVersion") == 4.1);
  CHECK(o.number("General.Verbosity") == 5);
  CHECK(o.number("Geometry.OldNewReg") == 1);
  CHECK(o.number("Geometry.Tolerance") == 1e-8);
  CHECK(o.string("General.Version").empty() == false);
  CHECK(o.color("General.Color.Background")[0] == 255);
}

TEST_CASE("options: CharacteristicLength aliases share storage") {
  Options o;
  CHECK(o.set_number("Mesh.CharacteristicLengthMax", 5).empty());
  CHECK(o.number("Mesh.MeshSizeMax") == 5);
  CHECK(o.set_number("Mesh.MeshSizeFactor", 0.5).empty());
  CHECK(o.number("Mesh.CharacteristicLengthFactor") == 0.5);
  o.reset();
  CHECK(o.number("Mesh.MeshSizeMax") == 1e22);
}

TEST_CASE("options: validation") {
  Options o;
  CHECK(o.set_number("Mesh.Algorithm", 4).kind == Diag::OptionValueNotAllowed);
  CHECK(o.number("Mesh.Algorithm") == 6);
  CHECK(o.set_number("Mesh.Algorithm", 5).empty());
  CHECK_FALSE(o.set_number("Mesh.MeshSizeFactor", 0).empty());
  CHECK_FALSE(o.set_number("Mesh.NbNodes", 3).empty());          // read-only
  CHECK(o.set_number("Mesh.NbNodes", 3, /*internal=*/true).empty());
  CHECK(o.number("Mesh.NbNodes") == 3);
  CHECK_FALSE(o.set_string("Mesh.Algorithm", "x").empty());
  CHECK_FALSE(o.set_number("Mesh.Foo", 1).empty());
  CHECK(o.set_color("Geometry.Color.Points", {1, 2, 3, 255}).empty());
  CHECK_FALSE(o.set_color("Geometry.Color.Points", {1, 2, 300, 255}).empty());
}

TEST_CASE("options: each refusal is a kind with its message") {
  Options o;
  const auto refusal = [](const sm::interp::OptionRefusal& r, Diag kind, const char* message) {
    CHECK(r.kind == kind);
    CHECK(r.message == message);
  };
  refusal(o.set_number("Mesh.Foo", 1), Diag::OptionNotKnown, "unknown option 'Mesh.Foo'");
  refusal(o.set_number("Mesh.NodeData", 1), Diag::OptionWrongKind, "option 'Mesh.NodeData' is a string, not a number");
  refusal(o.set_string("Mesh.PictureBox", "x"), Diag::OptionWrongKind,
          "option 'Mesh.PictureBox' is a box {W, E, S, N}, not a string");
  refusal(o.set_box("Mesh.Algorithm", {0, 0, 0, 0}), Diag::OptionWrongKind,
          "option 'Mesh.Algorithm' is a number, not a box");
  refusal(o.set_color("Mesh.Algorithm", {0, 0, 0, 255}), Diag::OptionWrongKind,
          "option 'Mesh.Algorithm' is a number, not a color");
  refusal(o.set_number("Mesh.NbNodes", 3), Diag::OptionReadOnly, "option 'Mesh.NbNodes' is read-only");
  refusal(o.set_number("Mesh.MeshSizeFactor", std::numeric_limits<double>::infinity()), Diag::OptionNotFinite,
          "option 'Mesh.MeshSizeFactor' must be finite");
  refusal(o.set_number("Mesh.MshFileVersion", 5), Diag::OptionValueNotAllowed,
          "invalid value 5 for option 'Mesh.MshFileVersion' (allowed: 1, 2, 2.2, 3, 4, 4.1)");
  refusal(o.set_number("Mesh.PictureWorst", 2.5), Diag::OptionValueNotWhole,
          "invalid value 2.5 for option 'Mesh.PictureWorst' (must be a whole number from 0 to 1000000)");
  refusal(o.set_number("Mesh.MinTimeStep", -1), Diag::OptionValueBelow,
          "invalid value -1 for option 'Mesh.MinTimeStep' (must be >= 0)");
  refusal(o.set_number("Mesh.MaxElements", 0), Diag::OptionValueOutside,
          "invalid value 0 for option 'Mesh.MaxElements' (must be > 0 and <= 1000000000000000)");
  refusal(o.set_color("Geometry.Color.Points", {1, 2, -1, 255}), Diag::OptionColorComponents,
          "color components of 'Geometry.Color.Points' must be in 0..255");
  // A box that frames nothing, in the words the interpreter gives io::PictureBoxProblem.
  const double nan = std::nan("");
  refusal(o.set_box("Mesh.PictureBox", {10, 10, 0, 5}), Diag::PictureBoxNoWidth,
          "Mesh.PictureBox: west and east are both 10: the box has no width");
  refusal(o.set_box("Mesh.PictureBox", {0, 10, nan, 5}), Diag::PictureBoxNotFinite,
          "Mesh.PictureBox: the box {W, E, S, N} must be finite numbers");
  refusal(o.set_box("Mesh.PictureBox", {-400, 10, 0, 5}), Diag::PictureBoxLongitudes,
          "Mesh.PictureBox: longitudes west -400 and east 10 must lie in [-360, 360]");
  refusal(o.set_box("Mesh.PictureBox", {0, 10, -95, 30}), Diag::PictureBoxLatitudes,
          "Mesh.PictureBox: latitudes south -95 and north 30 must lie in [-90, 90]");
  refusal(o.set_box("Mesh.PictureBox", {0, 10, 40, 30.5}), Diag::PictureBoxSouthNorth,
          "Mesh.PictureBox: south 40 must be below north 30.5 (the box is {W, E, S, N})");
  refusal(o.set_box("Mesh.PictureBox", {-300, 200, 0, 1}), Diag::PictureBoxTooWide,
          "Mesh.PictureBox: from west -300 to east 200 is more than 360 degrees");
  refusal(o.set_string("Mesh.NodeData", "depth, slope"), Diag::NodeDataUnknownValue,
          "Mesh.NodeData: unknown value 'slope' (use depth, size or criterion, comma-separated)");
}

TEST_CASE("options: closest name for unknown options") {
  Options o;
  CHECK(o.find("Mesh.Algoritm") == nullptr);
  CHECK(o.closest("Mesh.Algoritm") == "Mesh.Algorithm");
  CHECK(o.closest("Mesh.CharacteristicLenghtMax") == "Mesh.CharacteristicLengthMax");
  CHECK(sm::edit_distance("kitten", "sitting") == 3);
  sm::interp::Color c;
  CHECK(sm::interp::named_color("red", c));
  CHECK(c[0] == 255);
  CHECK_FALSE(sm::interp::named_color("Blurple", c));
}

TEST_CASE("options: the table has unique names and every alias resolves") {
  std::vector<std::string_view> names;
  for (const auto& o : Options::table()) names.push_back(o.name);
  std::sort(names.begin(), names.end());
  CHECK(std::adjacent_find(names.begin(), names.end()) == names.end());
  Options o;
  for (const auto& pair : Options::aliases()) {
    const auto& alias = pair.first;
    const auto& canon = pair.second;
    CAPTURE(alias);
    REQUIRE(o.find(canon) != nullptr);
    CHECK(o.find(alias) == o.find(canon));
    // The manual lists one alias on its own too; the alias wins (the same variable in Gmsh).
    if (alias != "Mesh.MinimumElementsPerTwoPi") CHECK(std::find(names.begin(), names.end(), alias) == names.end());
  }
  o.set_number("Mesh.MinimumCirclePoints", 13);
  CHECK(o.number("Mesh.MinimumCircleNodes") == 13);
  o.set_number("Mesh.MinimumElementsPerTwoPi", 4);
  CHECK(o.number("Mesh.MeshSizeFromCurvature") == 4);
}
