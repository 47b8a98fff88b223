// The BoundaryLayer field: the growth of its layers (field::layer_distances), measured
// against Gmsh 4.8.4's layer points, and the checks of its options.
#include "field/boundary_layer.h"

#include <cmath>
#include <vector>

#include <doctest/doctest.h>

#include "field/error.h"
#include "field/field_set.h"

using namespace sm::field;

TEST_CASE("boundary layer: geometric growth up to the thickness") {
  BoundaryLayerParams p;
  p.ratio = 1.4;
  // Gmsh's BL0 benchmark (Size 0.005, Ratio 1.4, Thickness 0.1): its layer points lie
  // 0.005, 0.012, 0.0218, 0.0355, 0.0547, 0.0816 from the wall; the next, 0.1193, is past it.
  const std::vector<double> d = layer_distances(p, 0.005, 0.1);
  const std::vector<double> gmsh = {0.005, 0.012, 0.0218, 0.03552, 0.054728, 0.0816192};
  REQUIRE(d.size() == gmsh.size());
  for (std::size_t i = 0; i < d.size(); ++i) CHECK(d[i] == doctest::Approx(gmsh[i]).epsilon(1e-9));
  // Each layer Ratio times the one below.
  for (std::size_t i = 2; i < d.size(); ++i)
    CHECK((d[i] - d[i - 1]) / (d[i - 1] - d[i - 2]) == doctest::Approx(1.4));
  // A point exactly at the limit is kept (Gmsh stops only beyond it).
  CHECK(layer_distances(p, 0.005, 0.012).size() == 2);
  CHECK(layer_distances(p, 0.005, 0.0119).size() == 1);
  CHECK(layer_distances(p, 0.2, 0.1).empty());
  // Ratio 1: equal layers.
  p.ratio = 1;
  CHECK(layer_distances(p, 0.1, 0.55).size() == 5);
  // Never more than kMaxBoundaryLayers, whatever is asked.
  CHECK(layer_distances(p, 1e-9, 1.0).size() == static_cast<std::size_t>(kMaxBoundaryLayers));
  CHECK(layer_distances(p, 0.0, 1.0).empty());
}

TEST_CASE("boundary layer: Gmsh's beta law") {
  BoundaryLayerParams p;
  p.beta_law = true;
  p.beta = 1.01;
  p.nb_layers = 10;
  // Gmsh's BL4 benchmark (Size 0.005, BetaLaw 1, Beta 1.01, NbLayers 10): the first six
  // points on its side line, from `gmsh -2`: 0.005, 0.0134, 0.0275, 0.0508, 0.0887, 0.1487.
  const std::vector<double> d = layer_distances(p, 0.005, 0.0);
  REQUIRE(d.size() == 10);
  const std::vector<double> gmsh = {0.005, 0.0134, 0.0275, 0.0508, 0.0887, 0.1487};
  for (std::size_t i = 0; i < gmsh.size(); ++i) CHECK(d[i] == doctest::Approx(gmsh[i]).epsilon(2e-3));
  for (std::size_t i = 1; i < d.size(); ++i) CHECK(d[i] > d[i - 1]);
}

TEST_CASE("boundary layer: options, aliases and checks") {
  FieldSet fs;
  fs.define(1, "BoundaryLayer");
  fs.set(1, "EdgesList", std::vector<double>{4, 5});
  fs.set(1, "NodesList", std::vector<double>{8});
  fs.set(1, "hwall_n", 0.02);
  fs.set(1, "ratio", 1.2);
  fs.set(1, "thickness", 0.3);
  fs.set(1, "hfar", 0.5);
  fs.set(1, "FanNodesList", std::vector<double>{3, 7});
  fs.set(1, "FanPointsSizesList", std::vector<double>{2, 9});
  fs.set(1, "hwall_n_nodes", std::vector<double>{8, 0.001});
  fs.set(1, "ExcludedFaceList", std::vector<double>{12});
  BoundaryLayerParams p = boundary_layer_params(fs.options(1), 1);
  CHECK(p.curves == std::vector<int>{4, 5});
  CHECK(p.has_curve(5));
  CHECK(p.is_end_point(8));
  CHECK(p.size == 0.02);
  CHECK(p.ratio == 1.2);
  CHECK(p.thickness == 0.3);
  CHECK(p.size_far == 0.5);
  CHECK(p.excludes(12));
  CHECK(p.fan_size(7, 5) == 9);
  CHECK(p.fan_size(3, 5) == 2);
  CHECK(p.size_at_point(8) == 0.001);
  CHECK(p.size_at_point(9) == 0.02);
  // A fan size list not as long as the fan points: Mesh.BoundaryLayerFanElements.
  fs.set(1, "FanPointsSizesList", std::vector<double>{2});
  CHECK(boundary_layer_params(fs.options(1), 1).fan_size(7, 5) == 5);

  auto refused = [&](const char* option, OptionValue v) {
    FieldSet bad;
    bad.define(2, "BoundaryLayer");
    bad.set(2, option, v);
    try {
      (void)boundary_layer_params(bad.options(2), 2);
    } catch (const FieldError& e) {
      CHECK(e.code() == FieldErrc::BadValue);
      return e.option;
    }
    return std::string("accepted");
  };
  CHECK(refused("Ratio", 0.9) == "Ratio");
  CHECK(refused("Size", -1.0) == "Size");
  CHECK(refused("Thickness", 0.0) == "Thickness");
  CHECK(refused("SizeFar", std::nan("")) == "SizeFar");
  CHECK(refused("CurvesList", std::vector<double>{1.5}) == "CurvesList");
  CHECK(refused("SizesList", std::vector<double>{1, 0.1, 2}) == "SizesList");
  CHECK(refused("FanPointsSizesList", std::vector<double>{-1}) == "FanPointsSizesList");
  // Size 1e-6 growing by 1.0001 over 1: about 9500 layers, past the bound.
  FieldSet many;
  many.define(3, "BoundaryLayer");
  many.set(3, "Size", 1e-6);
  many.set(3, "Ratio", 1.0001);
  many.set(3, "Thickness", 1.0);
  CHECK_THROWS_AS((void)boundary_layer_params(many.options(3), 3), FieldError);
  many.set(3, "Ratio", 1.5);  // 30 layers
  CHECK_NOTHROW((void)boundary_layer_params(many.options(3), 3));
}
