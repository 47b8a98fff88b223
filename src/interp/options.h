// The typed registry of General.*, Geometry.* and Mesh.* options with Gmsh
// 4.8.4's defaults (table generated from the manual's option index), deprecated
// aliases sharing storage, validation, and closest-name suggestions.
#pragma once

#include "base/edit_distance.h"  // edit_distance, for "did you mean" suggestions

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diag_format.h"

namespace sm::io {
struct PictureBox;
}

namespace sm::interp {

enum class OptionKind { Number, String, Color, Box };

struct OptionInfo {
  OptionKind kind;
  std::string_view name;
  std::string_view default_text;   ///< number text, string, or "r,g,b,a"
  bool read_only;                  ///< set only by the program (e.g. Mesh.NbNodes)
  std::string_view help;
};

/// RGBA components 0..255.
using Color = std::array<double, 4>;
/// A lon/lat box {west, east, south, north} in degrees (Mesh.PictureBox); all 0: none.
using LonLatBox = std::array<double, 4>;

/// Why a setter or a check of an option refused a value: its kind of diag_kinds.def (an
/// Option* kind, NodeDataUnknownValue, a PictureBox* kind, the Mesh.* checks made when
/// meshing) and that kind's message, which the interpreter, the CLI and the Python module print.
/// No kind (kCount) and no message: the value was taken.
struct OptionRefusal {
  lang::Diag kind = lang::Diag::kCount;
  std::string message;

  /// Whether the value was taken (nothing refused).
  bool empty() const { return kind == lang::Diag::kCount; }
};

/// The refusal of `kind` with `args` (checked against the kind's format at compile time).
template <class... Args>
OptionRefusal option_refusal(std::type_identity_t<lang::DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), lang::format_diag<Args...>(kind, args...)};
}

/// Whether box `b` {W, E, S, N} frames a picture (io/picture.h's normalise_picture_box, the
/// normalised box in `*out`), or the refusal naming its bounds (a PictureBox* kind).
OptionRefusal check_picture_box(const LonLatBox& b, io::PictureBox* out);

/// All option values of one run. A plain value passed in the interpreter's
/// context: no global state, so two runs never see each other's settings.
class Options {
 public:
  Options();

  /// The option with this exact name or deprecated alias; nullptr if unknown.
  const OptionInfo* find(std::string_view name) const;
  /// The known option (or alias) nearest to `name` by edit distance.
  std::string closest(std::string_view name) const;

  /// Readers; `name` must be a known option of the right kind.
  double number(std::string_view name) const;
  const std::string& string(std::string_view name) const;
  const Color& color(std::string_view name) const;
  const LonLatBox& box(std::string_view name) const;

  /// Setters return nothing (empty()) or why the value is refused (unknown option, wrong
  /// kind, read-only, outside the allowed set), as a kind and its message. `internal` lets
  /// the program update read-only statistics.
  OptionRefusal set_number(std::string_view name, double v, bool internal = false);
  OptionRefusal set_string(std::string_view name, std::string v, bool internal = false);
  OptionRefusal set_color(std::string_view name, const Color& c);
  /// {W, E, S, N}, or all 0 for none; refused when it frames nothing (S >= N, a latitude
  /// outside [-90, 90], W = E; io/picture.h's normalise_picture_box).
  OptionRefusal set_box(std::string_view name, const LonLatBox& b);

  /// Whether the option was given a value since the last reset (by a statement, the
  /// command line or the Python module), rather than holding its default: for the
  /// options whose default depends on the model (interp/kernel/quality_floor_option.h).
  bool was_set(std::string_view name) const;

  /// Back to the defaults (`Delete Options;`).
  void reset();

  /// Every option of the table, in table order (deprecated aliases excluded).
  static const std::vector<OptionInfo>& table();
  /// Deprecated aliases as (alias, canonical name) pairs.
  static const std::vector<std::pair<std::string_view, std::string_view>>& aliases();

 private:
  std::size_t index_of(std::string_view name, OptionKind kind) const;
  std::vector<double> nums_;
  std::vector<std::string> strs_;
  std::vector<Color> colors_;
  std::vector<LonLatBox> boxes_;
  std::vector<bool> set_;   // per option: given a value since the last reset
};

/// Named colours accepted on the right of `X.Color.Y = Name;` ("Red", ...).
bool named_color(std::string_view name, Color& out);


}  // namespace sm::interp
