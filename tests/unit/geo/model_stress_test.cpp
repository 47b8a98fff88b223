// Random sequences of model statements (fixed seed), valid and invalid alike: no crash, every
// failure is a typed error, and after every step all references resolve (curves -> points,
// loops -> curves, surfaces -> loops/embedded, physical groups -> entities) and every loop
// still chains and closes.
#include "geo/model.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

// The first broken invariant, or "" (plain checks: millions of them per run).
std::string broken_invariant(const Model& m) {
  for (const auto& [t, c] : m.curves()) {
    if (c.tag != t || !c.shape || c.begin != c.points.front() || c.end != c.points.back())
      return "curve " + std::to_string(t);
    for (int p : c.points)
      if (!m.vertex(p)) return "curve " + std::to_string(t) + " point " + std::to_string(p);
  }
  for (const auto& [t, l] : m.curve_loops()) {
    if (l.curves.empty()) return "empty loop " + std::to_string(t);
    // A loop kept unclosed, as Gmsh keeps it, has its reason and bounds no surface.
    if (l.unclosed) {
      if (l.unclosed->kind != GeoErrorKind::LoopNotClosed) return "loop " + std::to_string(t) + " unclosed kind";
      for (const auto& [st, s] : m.surfaces())
        for (int sl : s.loops)
          if (std::abs(sl) == t) return "surface " + std::to_string(st) + " on unclosed loop " + std::to_string(t);
      continue;
    }
    // Chains close: every curve's end is the next one's start, within each subloop.
    int chain_start = 0, end = 0;
    for (std::size_t i = 0; i < l.curves.size(); ++i) {
      const ModelCurve* c = m.curve(std::abs(l.curves[i]));
      if (!c) return "loop " + std::to_string(t) + " curve " + std::to_string(l.curves[i]);
      const int from = l.curves[i] > 0 ? c->begin : c->end, to = l.curves[i] > 0 ? c->end : c->begin;
      if (i == 0 || end == chain_start) chain_start = from;
      else if (from != end) return "loop " + std::to_string(t) + " broken";
      end = to;
    }
    if (end != chain_start) return "loop " + std::to_string(t) + " open";
  }
  for (const auto& [t, s] : m.surfaces()) {
    for (int l : s.loops)
      if (!m.curve_loop(std::abs(l))) return "surface " + std::to_string(t) + " loop";
    for (int p : s.embedded_points)
      if (!m.vertex(p)) return "surface " + std::to_string(t) + " embedded point";
    for (int c : s.embedded_curves)
      if (!m.curve(c)) return "surface " + std::to_string(t) + " embedded curve";
  }
  for (const auto& [key, g] : m.physicals())
    for (int e : g.entities) {
      const int a = std::abs(e);
      if ((g.dim == 0 && !m.vertex(a)) || (g.dim == 1 && !m.curve(a)) || (g.dim == 2 && !m.surface(a)))
        return "physical " + std::to_string(g.tag);
    }
  for (const auto& [t, v] : m.vertices())
    if (!std::isfinite(v.xyz.x + v.xyz.y + v.xyz.z)) return "point " + std::to_string(t) + " not finite";
  return "";
}

// Tags of everything, next tags and sizes: what a failed statement must leave alone.
std::vector<int> snapshot(const Model& m) {
  std::vector<int> s;
  for (int d = 0; d <= 2; ++d) {
    const std::vector<int> t = m.tags(d);
    s.push_back(-1 - d);
    s.insert(s.end(), t.begin(), t.end());
  }
  const std::vector<int> l = m.loop_tags();
  s.push_back(-9);
  s.insert(s.end(), l.begin(), l.end());
  for (const auto& [t, c] : m.curves()) s.insert(s.end(), c.points.begin(), c.points.end());
  for (const auto& [key, g] : m.physicals()) s.push_back(static_cast<int>(g.entities.size()));
  s.push_back(m.new_point_tag());
  s.push_back(m.new_curve_tag());
  s.push_back(m.new_reg());
  s.push_back(m.current_geometry());
  s.push_back(static_cast<int>(m.geometries().size()));
  return s;
}

}  // namespace

TEST_CASE("model stress: 3000 random statements keep the model consistent") {
  std::mt19937 rng(12345);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  auto coord = [&] { return static_cast<double>(pick(9)) * 0.25 - 1.0; };   // a coarse grid: duplicates happen
  auto some = [&](const std::vector<int>& v) { return v.empty() ? 1 + pick(40) : v[pick(static_cast<int>(v.size()))]; };
  Model m;
  REQUIRE(m.add_point(1000, {0, 0, 0}));
  REQUIRE(m.add_point(1001, {0, 0, 1}));
  int ok = 0, failed = 0, surfaces_made = 0, loops_made = 0;
  for (int step = 0; step < 3000; ++step) {
    const std::vector<int> pts = m.tags(0), curves = m.tags(1), surfs = m.tags(2), loops = m.loop_tags();
    const std::vector<int> before = snapshot(m);
    GeoStatus st;
    const int op = pick(16);
    switch (op) {
      case 0:
      case 1:
      case 2:
        st = m.add_point(pick(3) ? m.new_point_tag() : 1 + pick(60), {coord(), coord(), coord()}, pick(2) * 0.1);
        break;
      case 3:
      case 4:
      case 5: {
        std::vector<int> cp;
        const int n = 2 + pick(4);
        for (int i = 0; i < n; ++i) cp.push_back(some(pts));
        if (pick(4) == 0) cp.push_back(cp.front());
        const CurveKind kinds[] = {CurveKind::Line, CurveKind::Spline, CurveKind::BSpline, CurveKind::Bezier,
                                   CurveKind::Circle, CurveKind::Ellipse};
        st = m.add_curve(pick(4) ? m.new_curve_tag() : 1 + pick(60), kinds[pick(6)], cp);
        break;
      }
      case 6:
      case 7: {
        // A loop that often closes: walk curves end to start.
        std::vector<int> lc;
        if (!curves.empty()) {
          int c = some(curves);
          lc.push_back(c);
          const ModelCurve* mc = m.curve(c);
          int end = mc->end;
          for (int k = 0; k < 5 && end != mc->begin; ++k) {
            int next = 0;
            for (int t : curves)
              if (t != c && m.curve(t)->begin == end) next = t;
            if (!next) break;
            lc.push_back(next);
            end = m.curve(next)->end;
          }
          if (pick(5) == 0) std::swap(lc.front(), lc.back());
          if (pick(7) == 0) lc.front() = -lc.front();
        }
        st = m.add_curve_loop(m.new_loop_tag(), lc);
        break;
      }
      case 8: {
        std::vector<int> ls{some(loops)};
        if (pick(3) == 0) ls.push_back(some(loops));
        st = pick(4) ? m.add_plane_surface(m.new_surface_tag(), ls) : m.add_surface_filling(m.new_surface_tag(), ls);
        break;
      }
      case 9: {
        std::vector<DimTag> e{{pick(3), pick(3) == 0 ? some(surfs) : pick(2) ? some(curves) : some(pts)}};
        st = m.remove(e, pick(2) == 1);
        break;
      }
      case 10: m.coherence(); break;
      case 11: {
        auto d = m.duplicate({{1, some(curves)}});
        if (d) st = m.translate(*d, {0.25, 0, 0});
        else st = d.error();
        break;
      }
      case 12: st = m.rotate({{0, some(pts)}, {1, some(curves)}}, {0, 0, 1}, {0, 0, 0}, 0.5 * pick(4)); break;
      case 13: {
        const int c = some(curves);
        const ModelCurve* mc = m.curve(c);
        std::vector<int> at;
        if (mc && mc->points.size() > 2) at.push_back(mc->points[1]);
        else at.push_back(some(pts));
        auto r = m.split_curve(c, at);
        if (!r) st = r.error();
        break;
      }
      case 14: {
        auto r = m.add_physical(pick(3), pick(2) ? std::optional<int>{} : std::optional<int>{1 + pick(5)},
                                std::string(1, static_cast<char>('a' + pick(3))), {pick(2) ? some(pts) : some(curves)},
                                static_cast<PhysicalOp>(pick(3)));
        if (!r) st = r.error();
        break;
      }
      case 15: {
        if (pick(2)) st = m.add_polar_sphere(1 + pick(2), 1000, 1001);
        else if (pick(2)) st = m.set_current_geometry(1 + pick(3));
        else m.set_euclidean();
        break;
      }
    }
    surfaces_made = std::max(surfaces_made, static_cast<int>(m.surfaces().size()));
    loops_made = std::max(loops_made, static_cast<int>(m.curve_loops().size()));
    if (st.ok()) {
      ++ok;
    } else {
      ++failed;
      // A failed statement changes nothing (Duplicata + Translate is two statements).
      if (op != 11) REQUIRE(snapshot(m) == before);
      CHECK(kind_of(st.error().id) == st.error().kind);
      CHECK((st.error().kind != GeoErrorKind::MissingEntity || !st.error().tags.empty()));
    }
    const std::string broken = broken_invariant(m);
    CAPTURE(step);
    REQUIRE(broken == "");
  }
  // Both paths were exercised substantially.
  CHECK(ok > 500);
  CHECK(failed > 300);
  CHECK(m.curves().size() > 0);
  CHECK(loops_made >= 5);
  CHECK(surfaces_made >= 2);
}
