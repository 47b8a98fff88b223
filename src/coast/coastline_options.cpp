// The coastline option table (coastline_options.def): the checks, the setters and the
// generated docs.
#include "coast/coastline_options.h"

#include <cmath>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "coast/read_gshhg_binned.h"
#include "coast/region_polygon.h"

namespace sm::coast {

namespace {

using Why = std::optional<std::string>;

// ---- Setters: a member takes the value by its type.

void assign(double& m, const CoastOptionValue& v) { m = v.nums.front(); }
void assign(int& m, const CoastOptionValue& v) { m = static_cast<int>(v.nums.front()); }
void assign(bool& m, const CoastOptionValue& v) { m = v.nums.front() != 0; }
void assign(std::string& m, const CoastOptionValue& v) { m = std::string(v.str); }
void assign(std::optional<int>& m, const CoastOptionValue& v) { m = static_cast<int>(v.nums.front()); }
void assign(std::vector<int>& m, const CoastOptionValue& v) {
  m.clear();
  for (double x : v.nums) m.push_back(static_cast<int>(x));
}
void assign(std::vector<geo::LonLat>& m, const CoastOptionValue& v) {   // {lon, lat, ...}
  m.clear();
  for (std::size_t i = 0; i + 1 < v.nums.size(); i += 2) m.push_back({v.nums[i], v.nums[i + 1]});
}
void assign(std::vector<std::pair<geo::LonLat, geo::LonLat>>& m, const CoastOptionValue& v) {   // dams
  m.clear();
  const auto& x = v.nums;
  for (std::size_t i = 0; i + 3 < x.size(); i += 4) m.push_back({{x[i], x[i + 1]}, {x[i + 2], x[i + 3]}});
}
void assign(std::optional<LonLatBox>& m, const CoastOptionValue& v) {   // {west, east, south, north}
  m = LonLatBox{v.nums[0], v.nums[1], v.nums[2], v.nums[3]};
}

// ---- Defaults as the docs show them, read from a default CoastlineSettings.

std::string show(double x) { return fmt::format("{}", x); }
std::string show(int x) { return fmt::format("{}", x); }
std::string show(bool x) { return x ? "1" : "0"; }
std::string show(const std::string& s) { return s.empty() ? "none" : fmt::format("`\"{}\"`", s); }
std::string show(const std::optional<int>& x) { return x ? show(*x) : "none"; }
std::string show(const std::vector<int>& x) { return fmt::format("`{{{}}}`", fmt::join(x, ", ")); }
template <class T>
std::string show(const std::vector<T>& x) {
  return x.empty() ? "none" : fmt::format("{} given", x.size());
}
std::string show(const std::optional<LonLatBox>& b) {
  return b ? fmt::format("`{{{}, {}, {}, {}}}`", b->west, b->east, b->south, b->north) : "none";
}

// ---- Setters of their own (SM_APPLIES).

// A Region list of 6 or more numbers: the polygon's lon/lat vertices.
std::vector<geo::LonLat> polygon_vertices(std::span<const double> x) {
  std::vector<geo::LonLat> v;
  for (std::size_t i = 0; i + 1 < x.size(); i += 2) v.push_back({x[i], x[i + 1]});
  return v;
}

// Region: four numbers are a box; more, a polygon (checked when set), whose bounding box
// the readers clip to.
void apply_region(CoastlineSettings& s, const CoastOptionValue& v) {
  if (v.nums.size() == 4) {
    s.import.region = LonLatBox{v.nums[0], v.nums[1], v.nums[2], v.nums[3]};
    s.import.region_polygon.clear();
    return;
  }
  s.import.region_polygon = polygon_vertices(v.nums);
  s.import.region = RegionPolygon::make(s.import.region_polygon)->bounding_box();
}
std::string default_region(const CoastlineSettings& s) { return show(s.import.region); }

void apply_curve_type(CoastlineSettings& s, const CoastOptionValue& v) { s.import.deviation.bspline = v.str != "Line"; }
std::string default_curve_type(const CoastlineSettings& s) {
  return s.import.deviation.bspline ? "`\"BSpline\"`" : "`\"Line\"`";
}

void apply_coordinate(CoastlineSettings& s, const CoastOptionValue& v) {
  s.loops2.coordinate = *parse_loops2_coordinate(v.str);
}
std::string default_coordinate(const CoastlineSettings& s) {
  for (std::string_view c : {"lonlat", "lonlat_degrees", "utm", "cartesian"})
    if (parse_loops2_coordinate(c) == s.loops2.coordinate) return fmt::format("`{}`", c);
  return "?";
}

// ---- Checks beyond the type (the value already has it: one finite number, a list of
// finite numbers, one string).

constexpr std::nullptr_t none = nullptr;

Why check_resolution(const CoastOptionValue& v) {
  if (is_gshhg_resolution(v.str)) return std::nullopt;
  return fmt::format("must be \"c\", \"l\", \"i\", \"h\" or \"f\" (crude to full), not \"{}\"", v.str);
}
Why check_curve_type(const CoastOptionValue& v) {
  if (v.str == "BSpline" || v.str == "Line") return std::nullopt;
  return fmt::format("must be \"BSpline\" or \"Line\", not \"{}\"", v.str);
}
Why check_coordinate(const CoastOptionValue& v) {
  if (parse_loops2_coordinate(v.str)) return std::nullopt;
  return fmt::format("must be lonlat, lonlat_degrees, utm or cartesian, not \"{}\"", v.str);
}
Why check_field_id(const CoastOptionValue& v) {
  const double x = v.nums[0];
  if (x == std::floor(x) && x >= 0 && x <= 2147483647.0) return std::nullopt;
  return fmt::format("must be a field id, not {}", x);
}
Why check_utm_zone(const CoastOptionValue& v) {
  const double x = v.nums[0];
  if (x == std::floor(x) && x >= 1 && x <= 60) return std::nullopt;
  return fmt::format("must be a zone 1 to 60, not {}", x);
}
Why check_levels(const CoastOptionValue& v) {
  if (v.nums.empty()) return "is empty: no shoreline would be kept";
  for (double d : v.nums)
    if (d != std::floor(d) || d < 1 || d > 6) return fmt::format("must list levels 1 to 6, not {}", d);
  return std::nullopt;
}
Why check_antarctica_level(const CoastOptionValue& v) {
  const double x = v.nums[0];
  if (x == 0 || x == 5 || x == 6) return std::nullopt;
  return fmt::format("must be 0, 5 or 6, not {}", x);
}
Why check_lat_range(std::span<const double> x) {
  if (!(x[2] < x[3]) || x[2] < -90 || x[3] > 90)
    return fmt::format("needs -90 <= south < north <= 90 (got {} and {})", x[2], x[3]);
  return std::nullopt;
}
Why check_region(const CoastOptionValue& v) {
  const auto& x = v.nums;
  if (x.size() != 4) {   // a polygon
    if (x.size() < 6 || x.size() % 2 != 0)
      return fmt::format("takes a box {{west, east, south, north}} or a polygon of 3 or more lon/lat vertices "
                         "{{lon1, lat1, lon2, lat2, lon3, lat3, ...}}, not {} numbers",
                         x.size());
    auto poly = RegionPolygon::make(polygon_vertices(x));
    if (!poly) return fmt::format("is not a usable polygon: {}", poly.error().message);
    return std::nullopt;
  }
  if (!(x[0] < x[1]) || x[1] - x[0] > 360)
    return fmt::format("needs west < east <= west + 360 (got {} and {})", x[0], x[1]);
  return check_lat_range(x);
}
Why check_patch_box(const CoastOptionValue& v) {
  const auto& x = v.nums;
  if (x.size() != 4) return fmt::format("takes a box {{west, east, south, north}}, not {} numbers", x.size());
  if (!(x[0] < x[1]) || x[1] - x[0] >= 360)
    return fmt::format("needs west < east < west + 360 (got {} and {})", x[0], x[1]);
  return check_lat_range(x);
}
Why check_not_negative(const CoastOptionValue& v) {
  if (v.nums[0] < 0) return "must not be negative";
  return std::nullopt;
}
Why check_not_negative_off(const CoastOptionValue& v) {
  if (v.nums[0] < 0) return fmt::format("must not be negative (0 is off), not {}", v.nums[0]);
  return std::nullopt;
}
Why check_positive(const CoastOptionValue& v) {
  if (!(v.nums[0] > 0)) return "must be positive";
  return std::nullopt;
}
Why check_distance(const CoastOptionValue& v) {
  if (!(v.nums[0] > 0)) return fmt::format("must be a positive distance in metres, not {}", v.nums[0]);
  return std::nullopt;
}
// Lon/lat numbers, `per` of them per item (2: a point, 4: a dam).
Why check_lonlat_items(const CoastOptionValue& v, std::size_t per) {
  const auto& x = v.nums;
  if (x.empty() || x.size() % per != 0)
    return fmt::format("takes {} per {}, not {} number(s)", per == 4 ? "{lon1, lat1, lon2, lat2}" : "{lon, lat}",
                       per == 4 ? "dam" : "point", x.size());
  for (std::size_t i = 1; i < x.size(); i += 2)
    if (x[i] < -90 || x[i] > 90)
      return fmt::format("has latitude {} (value {}): latitudes lie in [-90, 90]", x[i], i + 1);
  return std::nullopt;
}
Why check_points(const CoastOptionValue& v) { return check_lonlat_items(v, 2); }
Why check_dams(const CoastOptionValue& v) { return check_lonlat_items(v, 4); }

#define SM_SETS(member)                                                                   \
  [](CoastlineSettings& s, const CoastOptionValue& v) { assign(s.member, v); },          \
      [](const CoastlineSettings& s) { return show(s.member); }, #member
#define SM_APPLIES(fn, target) apply_##fn, default_##fn, target

constexpr CoastOptionSpec kOptions[] = {
#define SM_COAST_OPTION(name, type, only, values, target, check, help) \
  {#name, CoastOptionType::type, only, values, target, check, help},
#include "coast/coastline_options.def"
#undef SM_COAST_OPTION
};

#undef SM_SETS
#undef SM_APPLIES

std::string_view type_words(const CoastOptionSpec& o) {
  switch (o.type) {
    case CoastOptionType::String:
    case CoastOptionType::Path: return "takes one string";
    case CoastOptionType::List: return "takes a list of numbers";
    case CoastOptionType::Number:
    case CoastOptionType::Flag: return "takes a number";
  }
  return "";
}

}  // namespace

std::span<const CoastOptionSpec> coast_options() { return kOptions; }

const CoastOptionSpec& coast_option(CoastOpt o) { return kOptions[static_cast<std::size_t>(o)]; }

std::string_view coast_option_name(CoastOpt o) { return coast_option(o).name; }

const CoastOptionSpec* find_coast_option(std::string_view name) {
  for (const CoastOptionSpec& o : kOptions)
    if (o.name == name) return &o;
  return nullptr;
}

std::optional<std::string> check_coast_option(const CoastOptionSpec& o, const CoastOptionValue& v) {
  if (o.type == CoastOptionType::String || o.type == CoastOptionType::Path) {
    if (!v.is_string || v.strings != 1) return std::string(type_words(o));
    if (o.type == CoastOptionType::Path && v.str.empty()) return "is empty";
    return o.check ? o.check(v) : std::nullopt;
  }
  if (v.is_string) return std::string(type_words(o));
  for (double d : v.nums)
    if (!std::isfinite(d)) return "is not finite";
  if (o.type != CoastOptionType::List && v.nums.size() != 1)
    return fmt::format("takes one number, not a list of {}", v.nums.size());
  if (o.type == CoastOptionType::Flag && v.nums[0] != 0 && v.nums[0] != 1)
    return fmt::format("must be 0 or 1, not {}", v.nums[0]);
  return o.check ? o.check(v) : std::nullopt;
}

std::string coast_options_markdown() {
  const CoastlineSettings defaults;
  std::string out =
      "| option | value | default | meaning | sets |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const CoastOptionSpec& o : kOptions) {
    out += fmt::format("| `{}` | {} | {} | {}{} | `{}` |\n", o.name, o.values, o.default_of(defaults),
                       o.only.empty() ? std::string() : fmt::format("{} only: ", o.only), o.help, o.target);
  }
  return out;
}

}  // namespace sm::coast
