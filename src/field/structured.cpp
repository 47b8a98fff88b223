// Structured field: trilinear interpolation on a regular 3D grid read from
// Gmsh's text or binary "Structured" file (docs/fields.md).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <fstream>

#include <fmt/format.h>

#include "field/error.h"
#include "base/file_identity.h"
#include "field/kinds.h"

namespace sm::field {
namespace {

struct Grid3 {
  std::array<double, 3> o{}, d{};
  std::array<int, 3> n{};
  std::vector<double> v;  // index i*ny*nz + j*nz + k: z fastest
};

[[noreturn]] void file_error(const std::filesystem::path& file, const std::string& what) {
  FieldError e(FieldErrc::FileError, fmt::format("{}: {}", file.string(), what));
  e.file = file.string();
  e.reason = what;
  throw e;
}

// The axes of a structured grid are implicit (origin + k * spacing), so they are regular
// by construction; what can break them is a NaN, an infinity or a zero step, named here
// with the axis (x, y, z) and its values.
void check_header(const std::filesystem::path& file, const Grid3& g) {
  for (std::size_t a = 0; a < 3; ++a) {
    const char axis = "xyz"[a];
    if (g.n[a] < 1 || g.n[a] > (1 << 24))
      file_error(file, fmt::format("bad node count {} along axis {}", g.n[a], axis));
    if (!std::isfinite(g.o[a]) || !std::isfinite(g.d[a]))
      file_error(file, fmt::format("axis {} has origin {} and spacing {}: both must be finite", axis, g.o[a], g.d[a]));
    if (g.n[a] > 1 && g.d[a] == 0)
      file_error(file, fmt::format("zero spacing along axis {} with {} nodes", axis, g.n[a]));
  }
}

Grid3 read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) file_error(file, "cannot be read");
  base::note_input_file(file.string());
  Grid3 g;
  for (double& x : g.o) in >> x;
  for (double& x : g.d) in >> x;
  for (int& x : g.n) in >> x;
  if (!in) file_error(file, "bad header (expected Ox Oy Oz, Dx Dy Dz, nx ny nz)");
  check_header(file, g);
  const std::size_t total = static_cast<std::size_t>(g.n[0]) * g.n[1] * g.n[2];
  g.v.resize(total);
  // Tokens go through strtod so that "nan"/"inf" are read (and then rejected
  // with their node) rather than ending the file early.
  std::string tok;
  for (std::size_t k = 0; k < total; ++k) {
    if (!(in >> tok)) file_error(file, fmt::format("expected {} values, found {}", total, k));
    char* end = nullptr;
    g.v[k] = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0')
      file_error(file, fmt::format("value {} ('{}') is not a number", k + 1, tok));
  }
  return g;
}

Grid3 read_binary(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) file_error(file, "cannot be read");
  base::note_input_file(file.string());
  Grid3 g;
  in.read(reinterpret_cast<char*>(g.o.data()), sizeof(double) * 3);
  in.read(reinterpret_cast<char*>(g.d.data()), sizeof(double) * 3);
  std::int32_t n[3];
  in.read(reinterpret_cast<char*>(n), sizeof n);
  if (!in) file_error(file, "too short for the binary header (is it a text file? set TextFormat = 1)");
  for (int a = 0; a < 3; ++a) g.n[static_cast<std::size_t>(a)] = n[a];
  check_header(file, g);
  const std::size_t total = static_cast<std::size_t>(g.n[0]) * g.n[1] * g.n[2];
  g.v.resize(total);
  in.read(reinterpret_cast<char*>(g.v.data()), static_cast<std::streamsize>(total * sizeof(double)));
  if (!in) file_error(file, fmt::format("binary data holds fewer than {} values", total));
  return g;
}

class StructuredField final : public SizeField {
 public:
  StructuredField(Grid3 g, bool set_outside, double outside)
      : g_(std::move(g)), set_outside_(set_outside), outside_(outside) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t p = 0; p < pts.size(); ++p) h[p] = value(pts[p]);
  }

 private:
  double value(const Vec3& x) const {
    const double c[3] = {x.x, x.y, x.z};
    int idx[3];
    double w[3];
    for (std::size_t a = 0; a < 3; ++a) {
      if (g_.n[a] == 1) {
        idx[a] = 0;
        w[a] = 0;
        continue;
      }
      const double t = (c[a] - g_.o[a]) / g_.d[a];
      const double ft = std::floor(t);
      // Gmsh: a point on the last node already counts as outside (i+1 >= n).
      if (set_outside_ && (ft < 0 || ft + 1 >= g_.n[a])) return outside_;
      const int i = static_cast<int>(std::clamp(ft, 0.0, static_cast<double>(g_.n[a] - 2)));
      idx[a] = i;
      w[a] = std::clamp(t - i, 0.0, 1.0);
    }
    const std::size_t ny = static_cast<std::size_t>(g_.n[1]), nz = static_cast<std::size_t>(g_.n[2]);
    double sum = 0;
    for (int di = 0; di < 2; ++di) {
      if (g_.n[0] == 1 && di) break;
      for (int dj = 0; dj < 2; ++dj) {
        if (g_.n[1] == 1 && dj) break;
        for (int dk = 0; dk < 2; ++dk) {
          if (g_.n[2] == 1 && dk) break;
          const double wt = (di ? w[0] : 1 - w[0]) * (dj ? w[1] : 1 - w[1]) * (dk ? w[2] : 1 - w[2]);
          const std::size_t k = static_cast<std::size_t>(idx[0] + di) * ny * nz +
                                static_cast<std::size_t>(idx[1] + dj) * nz +
                                static_cast<std::size_t>(idx[2] + dk);
          sum += wt * g_.v[k];
        }
      }
    }
    return sum;
  }

  Grid3 g_;
  bool set_outside_;
  double outside_;
};

FieldPtr make_structured(const BuildInputs& in) {
  const std::string& file = in.opts.string("FileName");
  if (file.empty()) in.bad("FileName", "no grid file given");
  const auto path = in.path(file);
  try {
    if (!std::filesystem::exists(path)) file_error(path, "no such file");
    Grid3 g = in.opts.number("TextFormat") != 0 ? read_text(path) : read_binary(path);
    for (std::size_t k = 0; k < g.v.size(); ++k)
      if (!std::isfinite(g.v[k])) {
        const std::size_t nz = static_cast<std::size_t>(g.n[2]), nyz = static_cast<std::size_t>(g.n[1]) * nz;
        file_error(path, fmt::format("value {} at node (i, j, k) = ({}, {}, {}) is not finite", g.v[k],
                                     k / nyz, k % nyz / nz, k % nz));
      }
    return std::make_shared<StructuredField>(std::move(g), in.opts.number("SetOutsideValue") != 0,
                                             in.opts.number("OutsideValue"));
  } catch (FieldError& e) {
    e.field_id = in.id;
    e.option = "FileName";
    throw;
  }
}

}  // namespace

KindSpec structured_kind() {
  return {"Structured",
          "Trilinear interpolation on a regular grid file: Ox Oy Oz, Dx Dy Dz, nx ny nz, then "
          "nx*ny*nz values with z varying fastest (binary: 6 doubles, 3 int32, doubles).",
          {
              str_opt("FileName", "", "grid file"),
              num_opt("TextFormat", 0, "1: text file; 0: binary (Gmsh's default)"),
              num_opt("SetOutsideValue", 0, "1: return OutsideValue outside the grid; 0: extend edges"),
              num_opt("OutsideValue", 0, "value outside the grid when SetOutsideValue = 1"),
          },
          make_structured};
}

}  // namespace sm::field
