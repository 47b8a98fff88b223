#include "field/registry.h"

#include <cmath>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/field_set.h"

using namespace sm::field;

TEST_CASE("registry: every field kind listed here is registered, sorted") {
  const char* expected[] = {
      "Ball",       "Bathymetry",      "BoundaryLayer", "Box",      "ChannelWidth", "Constant", "Curvature",
      "Cylinder",   "Distance",        "Gradation",     "Gradient", "Laplacian",    "LonLat",   "MathEval",
      "Max",        "MaxEigenHessian", "Mean",          "Min",      "MinAniso",     "Param",    "Restrict",
      "Structured", "Threshold",       "TimeStep"};
  REQUIRE(kinds().size() == std::size(expected));
  for (std::size_t i = 0; i < kinds().size(); ++i) CHECK(kinds()[i].name == expected[i]);
  for (const KindSpec& k : kinds()) {
    CHECK(static_cast<bool>(k.make));
    CHECK(!k.help.empty());
    for (const OptionSpec& o : k.options) CHECK_MESSAGE(!o.help.empty(), k.name << "." << o.name);
  }
  CHECK(find_kind("Attractor") == find_kind("Distance"));
  CHECK(find_kind("threshold") == nullptr);  // names are case-sensitive, as in Gmsh
}

TEST_CASE("registry: deprecated aliases share the option's storage") {
  FieldSet fs;
  fs.define(1, "Threshold");
  fs.set(1, "LcMin", 0.25);
  CHECK(fs.options(1).number("SizeMin") == 0.25);
  fs.set(1, "SizeMax", 3.0);
  CHECK(fs.options(1).number("LcMax") == 3.0);
  fs.set(1, "IField", 7.0);
  CHECK(fs.options(1).number("InField") == 7.0);
  fs.define(2, "Distance");
  fs.set(2, "NodesList", std::vector<double>{1, 2});
  fs.set(2, "Sampling", 50.0);
  CHECK(fs.options(2).list("PointsList").size() == 2);
  CHECK(fs.options(2).number("NumPointsPerCurve") == 50);
  fs.set(2, "NNodesByEdge", 60.0);
  CHECK(fs.options(2).number("Sampling") == 60);
  fs.set(2, "EdgesList", std::vector<double>{3});
  CHECK(fs.options(2).list("CurvesList") == std::vector<double>{3});
  fs.define(3, "Restrict");
  fs.set(3, "FacesList", std::vector<double>{4});
  CHECK(fs.options(3).list("SurfacesList") == std::vector<double>{4});
}

TEST_CASE("registry: unknown kind and option suggest the closest name") {
  FieldSet fs;
  try {
    fs.define(1, "Treshold");
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::UnknownKind);
    CHECK(e.suggestion == "Threshold");
    CHECK(e.field_id == 1);
  }
  try {
    fs.define(1, "Qwertyuiop");
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::UnknownKind);
    CHECK(e.suggestion.empty());
  }
  fs.define(1, "Threshold");
  try {
    fs.set(1, "DistMn", 0.5);
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::UnknownOption);
    CHECK(e.suggestion == "DistMin");
    CHECK(e.option == "DistMn");
    CHECK(e.field_id == 1);
  }
  try {
    fs.set(1, "DistMin", std::string("0.5"));
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::WrongOptionType);
  }
  try {
    fs.set(1, "InField", 2.5);
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::BadValue);
    CHECK(e.field_id == 1);
  }
  fs.define(2, "Min");
  CHECK_THROWS_AS(fs.set(2, "FieldsList", std::vector<double>{1, std::nan("")}), FieldError);
  // Gmsh 4.8.4 silently ignores a list option set without braces; we refuse.
  CHECK_THROWS_AS(fs.set(2, "FieldsList", 3.0), FieldError);
}

TEST_CASE("registry: markdown lists every kind, option, default and alias") {
  const std::string md = registry_markdown();
  for (const KindSpec& k : kinds()) {
    CHECK(md.find("### " + k.name + "\n") != std::string::npos);
    for (const OptionSpec& o : k.options) CHECK(md.find("`" + o.name + "`") != std::string::npos);
  }
  CHECK(md.find("| `SizeMin` | number | 0.1 | LcMin |") != std::string::npos);
  CHECK(md.find("| `NumPointsPerCurve` | number | 20 | Sampling, NNodesByEdge |") != std::string::npos);
  CHECK(md.find("| `FieldsList` | list of field ids | {} |") != std::string::npos);
}

TEST_CASE("registry: closest_name") {
  CHECK(closest_name("Lapacian", {"Laplacian", "Mean"}) == "Laplacian");
  CHECK(closest_name("mathevall", {"MathEval", "Max"}) == "MathEval");
  CHECK(closest_name("zzz", {"Ball", "Box"}).empty());
}
