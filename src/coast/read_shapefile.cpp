// Shapefile reader. shapelib prints its errors through a hook; they are captured here and
// returned in the CoastError instead of reaching stderr.
#include "coast/read_shapefile.h"
#include "base/file_identity.h"

#include <atomic>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>
#include <shapefil.h>
#include <unistd.h>

#include "coast/shapefile_sizes.h"

namespace sm::coast {
namespace {

namespace fs = std::filesystem;

// shapelib's error hook has no user pointer: the message of the current call on this
// thread is kept here and read back right after the failing call.
thread_local std::string t_shp_error;

void capture_error(const char* msg) { t_shp_error = msg ? msg : ""; }

SAHooks quiet_hooks() {
  SAHooks h;
  SASetupDefaultHooks(&h);
  h.Error = &capture_error;
  return h;
}

// Removes a temporary directory on scope exit.
struct TempDir {
  fs::path dir;
  ~TempDir() {
    if (!dir.empty()) {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  }
};

fs::path unique_temp_dir() {
  // Process id + a counter keep concurrent readers (threads, processes) apart; the
  // counter carries no state beyond name uniqueness.
  static std::atomic<unsigned> counter{0};
  std::error_code ec;
  const fs::path base = fs::temp_directory_path(ec);
  return (ec ? fs::path("/tmp") : base) /
         fmt::format("sm_coast_shx_{}_{}", static_cast<long>(::getpid()), counter.fetch_add(1));
}

const char* type_name(int t) {
  switch (t) {
    case SHPT_POLYGON: return "Polygon";
    case SHPT_POLYGONZ: return "PolygonZ";
    case SHPT_POLYGONM: return "PolygonM";
    case SHPT_ARC: return "PolyLine";
    case SHPT_ARCZ: return "PolyLineZ";
    case SHPT_ARCM: return "PolyLineM";
    default: return "unsupported";
  }
}

bool is_polygon(int t) { return t == SHPT_POLYGON || t == SHPT_POLYGONZ || t == SHPT_POLYGONM; }
bool is_arc(int t) { return t == SHPT_ARC || t == SHPT_ARCZ || t == SHPT_ARCM; }

struct ShpCloser {
  void operator()(SHPInfo* h) const { SHPClose(h); }
};
struct ObjDeleter {
  void operator()(SHPObject* o) const { SHPDestroyObject(o); }
};

}  // namespace

Result<Coastline> read_shapefile(const std::string& path, ShapefileInfo* info) {
  SAHooks hooks = quiet_hooks();
  std::error_code ec;
  fs::path shp(path);
  if (!fs::is_regular_file(shp, ec)) return CoastError{path, -1, "no such shapefile (.shp)", {}};
  fs::path shx = shp;
  shx.replace_extension(".shx");
  fs::path shx_upper = shp;
  shx_upper.replace_extension(".SHX");
  const bool has_shx = fs::exists(shx, ec) || fs::exists(shx_upper, ec);
  // shapelib believes the lengths the headers claim (it allocates and seeks by them), so
  // they are checked against the real sizes first.
  if (auto e = check_shapefile_sizes(shp, !has_shx ? fs::path() : fs::exists(shx, ec) ? shx : shx_upper)) return *e;
  TempDir tmp;
  std::string open_path = path;
  bool rebuilt = false;
  if (!has_shx) {
    tmp.dir = unique_temp_dir();
    fs::create_directories(tmp.dir, ec);
    if (ec) return CoastError{path, -1, "no .shx index and no temporary directory to rebuild it: " + ec.message(), {}};
    const fs::path link = tmp.dir / shp.filename().replace_extension(".shp");
    fs::create_symlink(fs::absolute(shp, ec), link, ec);
    if (ec) fs::copy_file(shp, link, ec);
    if (ec) return CoastError{path, -1, "cannot stage the .shp to rebuild its index: " + ec.message(), {}};
    t_shp_error.clear();
    if (!SHPRestoreSHX(link.c_str(), "rb", &hooks))
      return CoastError{path, -1, "no .shx index, and rebuilding it failed: " + t_shp_error, {}};
    open_path = link.string();
    rebuilt = true;
  }
  t_shp_error.clear();
  std::unique_ptr<SHPInfo, ShpCloser> h(SHPOpenLL(open_path.c_str(), "rb", &hooks));
  if (!h) return CoastError{path, -1, "not a readable shapefile: " + t_shp_error, {}};
  base::note_input_file(path);
  int n = 0, type = 0;
  double lo[4], hi[4];
  SHPGetInfo(h.get(), &n, &type, lo, hi);
  if (!is_polygon(type) && !is_arc(type))
    return CoastError{path, -1,
                      fmt::format("shape type {} ({}) is not a Polygon or PolyLine", type, type_name(type)), {}};
  if (info) *info = {type, n, rebuilt};

  Coastline out;
  out.file = path;
  for (int i = 0; i < n; ++i) {
    t_shp_error.clear();
    std::unique_ptr<SHPObject, ObjDeleter> o(SHPReadObject(h.get(), i));
    if (!o) return CoastError{path, i, "unreadable record (truncated or corrupt file): " + t_shp_error, {}};
    if (o->nSHPType == SHPT_NULL) continue;
    if (o->nSHPType != type)
      return CoastError{path, i, fmt::format("record of type {} in a {} file", o->nSHPType, type_name(type)), {}};
    if (o->nParts < 1 || o->nVertices < 0)
      return CoastError{path, i, fmt::format("record with {} parts and {} vertices", o->nParts, o->nVertices), {}};
    for (int k = 0; k < o->nParts; ++k) {
      const int a = o->panPartStart[k];
      const int b = k + 1 < o->nParts ? o->panPartStart[k + 1] : o->nVertices;
      if (a < 0 || b > o->nVertices || a > b)
        return CoastError{path, i, fmt::format("part {} has an invalid start index {}", k, a), {}};
      Ring r;
      r.id = o->nShapeId;
      r.record = static_cast<std::size_t>(i);
      r.part = k;
      r.pts.reserve(static_cast<std::size_t>(b - a));
      double twice_area = 0;
      for (int j = a; j < b; ++j) {
        const double x = o->padfX[j];
        double y = o->padfY[j];
        // Natural Earth closes Antarctica along lat -90 written as -90.000000000000014.
        if (std::abs(y) > 90 && std::abs(y) < 90 + 1e-9) y = std::copysign(90.0, y);
        if (!std::isfinite(x) || !std::isfinite(y) || std::abs(y) > 90 || std::abs(x) > 540)
          return CoastError{path, i, fmt::format("part {} vertex {} is not a lon/lat point", k, j - a),
                            geo::LonLat{x, y}};
        if (j + 1 < b) twice_area += x * o->padfY[j + 1] - o->padfX[j + 1] * o->padfY[j];
        r.pts.push_back({x, y});
      }
      if (is_polygon(type)) {
        r.closed = true;
        r.level = twice_area > 0 ? 2 : 1;   // ESRI: outer rings clockwise, holes counter-clockwise
      } else {
        r.closed = r.pts.size() >= 4 && same_point(r.pts.front(), r.pts.back());
      }
      normalise_ring(r);
      out.rings.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace sm::coast
