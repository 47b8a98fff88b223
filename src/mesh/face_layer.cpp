// Step 2b of a face: the boundary layers (face_layer.h).
#include "mesh/face_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "exact/predicates.h"

namespace sm {
namespace {

using field::BoundaryLayerParams;

constexpr std::uint32_t kPending = 0x80000000u;

// A closed walk of the face's boundary with the face on its left: node r[k], then the
// edge to r[k + 1] (mod size) on curve ec[k]. An embedded curve with layers is walked
// there and back (a slit), both its sides being in the face.
struct Ring {
  std::vector<std::uint32_t> r;
  std::vector<int> ec;
};

// The columns of layer points at one place of a ring: one, or a fan; the first serves
// the edge before the node, the last the edge after it.
using Column = std::vector<std::uint32_t>;

struct LayerBuild {
  FaceWork& f;
  std::map<std::uint32_t, int> vertex_of;  // global node -> model vertex tag

  // Column points are pending (kPending | index into `pending`) until the elements
  // that keep them are known: those of overlapping elements are never made.
  std::vector<Vec2> pending;

  Vec2 xy(std::uint32_t node) const {
    return node & kPending ? pending[node & ~kPending] : f.plane.node_plane(f.mesh.nodes[node]);
  }

  // The field giving curve c its layers on this face, or null.
  const BoundaryLayerParams* field_of(int c) const {
    if (c == 0) return nullptr;
    for (const BoundaryLayerParams& p : *f.opt.boundary_layers)
      if (p.has_curve(c) && !p.excludes(f.tag)) return &p;
    return nullptr;
  }

  // The first layer's height at node n of curve c (Gmsh's getLocalInfoAtNode: a model
  // vertex's own, else between its curve's end points' heights by a quadratic in the
  // curve parameter that prefers the smaller).
  double first_height(const BoundaryLayerParams& p, std::uint32_t n, int c) const {
    if (const auto it = vertex_of.find(n); it != vertex_of.end()) return p.size_at_point(it->second);
    if (p.point_sizes.empty()) return p.size;
    const geo::ModelCurve* mc = f.model.curve(c);
    const auto cm = f.mesh.curves.find(c);
    if (!mc || cm == f.mesh.curves.end()) return p.size;
    const auto pos = std::find(cm->second.nodes.begin(), cm->second.nodes.end(), n);
    if (pos == cm->second.nodes.end()) return p.size;
    const double x = cm->second.t[static_cast<std::size_t>(pos - cm->second.nodes.begin())];
    const double hb = p.size_at_point(mc->begin), he = p.size_at_point(mc->end), hm = std::min(hb, he);
    return hb * (1 - x) * (1 - x) + hm * 2 * x * (1 - x) + he * x * x;
  }

  // A column from node n along unit direction d (the plane's units).
  Column column(const BoundaryLayerParams& p, std::uint32_t n, int c, Vec2 d) {
    Column col;
    const Vec2 o = xy(n);
    for (double L : field::layer_distances(p, first_height(p, n, c), p.thickness)) {
      if (pending.size() >= kPending - 1) break;  // beyond any mesh this program can hold
      col.push_back(kPending | static_cast<std::uint32_t>(pending.size()));
      pending.push_back(o + L * d);
    }
    return col;
  }
};

Vec2 unit(Vec2 v) {
  const double l = std::hypot(v.x, v.y);
  return l > 0 ? Vec2{v.x / l, v.y / l} : Vec2{0, 0};
}
Vec2 left_of(Vec2 d) { return {-d.y, d.x}; }
Vec2 rotate_cw(Vec2 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x + s * v.y, -s * v.x + c * v.y};
}

// Whether the closed walk turns counter-clockwise: the turn at its lowest (then
// leftmost) node, decided by the exact orientation predicate.
bool counter_clockwise(const LayerBuild& b, const std::vector<std::uint32_t>& nodes) {
  const std::size_t n = nodes.size();
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const Vec2 p = b.xy(nodes[i]), q = b.xy(nodes[k]);
    if (p.y < q.y || (p.y == q.y && p.x < q.x)) k = i;
  }
  return orient2d(b.xy(nodes[(k + n - 1) % n]), b.xy(nodes[k]), b.xy(nodes[(k + 1) % n])) == Sign::Positive;
}

void reverse_ring(Ring& g) {
  // Edge k joins r[k] and r[k+1]: reversed, node order reversed and each edge keeps its curve.
  const std::size_t n = g.r.size();
  Ring out;
  for (std::size_t i = 0; i < n; ++i) out.r.push_back(g.r[(n - i) % n]);
  for (std::size_t i = 0; i < n; ++i) out.ec.push_back(g.ec[(2 * n - i - 1) % n]);
  g = std::move(out);
}

// The end column where a layer stops at ring place k and the boundary goes on along a
// curve without layers (step +1: after k; -1: before k): that curve's nodes from k on,
// its far end excluded (Gmsh's addColumnAtTheEndOfTheBL: the curve's interior nodes).
Column end_column(const Ring& g, std::size_t k, int step) {
  const std::size_t n = g.r.size();
  auto at = [n](std::size_t i, int s) { return (i + n + static_cast<std::size_t>(s + 1) - 1) % n; };
  const int c = step > 0 ? g.ec[k] : g.ec[at(k, -1)];
  Column col;
  std::size_t j = k;
  for (std::size_t guard = 0; guard + 1 < n; ++guard) {
    const std::size_t next = at(j, step);
    // The edge leaving `next` onward must still be on c for `next` to be interior to it.
    const int onward = step > 0 ? g.ec[next] : g.ec[at(next, -1)];
    if (onward != c) break;
    col.push_back(g.r[next]);
    j = next;
  }
  return col;
}

struct DirectedEdges {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;  // (from, to) -> how many
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> curve;   // a boundary edge's curve
  void add(std::uint32_t a, std::uint32_t b) { ++count[{a, b}]; }
  // An element's edge a -> b: on the boundary (or an earlier element's reversed edge)
  // it cancels; else the rest of the face now ends at b -> a.
  void element_edge(std::uint32_t a, std::uint32_t b) {
    const auto it = count.find({a, b});
    if (it != count.end() && it->second > 0) {
      if (--it->second == 0) count.erase(it);
    } else {
      add(b, a);
    }
  }
};

struct LayerElement {
  std::array<std::uint32_t, 4> v;  // counter-clockwise; v[3] unused for a triangle
  int nv;
  int layer;
  int column;
  bool quads;  // the field keeps quadrangles
};

// Whether segments pq and rs meet, Gmsh's test: each one's ends not strictly on one
// side of the other (touching and collinear overlap count), by the exact predicate.
bool segments_meet(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  const int a = static_cast<int>(orient2d(p, q, r)), c = static_cast<int>(orient2d(p, q, s));
  const int d = static_cast<int>(orient2d(r, s, p)), e = static_cast<int>(orient2d(r, s, q));
  return a * c <= 0 && d * e <= 0 && !(a == 0 && c == 0 && !(std::max(std::min(p.x, q.x), std::min(r.x, s.x)) <=
                                                                 std::min(std::max(p.x, q.x), std::max(r.x, s.x)) &&
                                                             std::max(std::min(p.y, q.y), std::min(r.y, s.y)) <=
                                                                 std::min(std::max(p.y, q.y), std::max(r.y, s.y))));
}

// Kept elements and the boundary's edges in a uniform grid of boxes, for the overlap
// filter: an element is tested against what shares a cell with its bounding box.
class OverlapGrid {
 public:
  OverlapGrid(const LayerBuild& b, const std::vector<LayerElement>& els,
              const std::vector<std::pair<Vec2, Vec2>>& lines)
      : b_(b), els_(els), lines_(lines) {
    lo_ = {1e300, 1e300};
    Vec2 hi{-1e300, -1e300};
    auto grow = [&](Vec2 p) {
      lo_.x = std::min(lo_.x, p.x), lo_.y = std::min(lo_.y, p.y);
      hi.x = std::max(hi.x, p.x), hi.y = std::max(hi.y, p.y);
    };
    for (const auto& l : lines) grow(l.first), grow(l.second);
    for (const LayerElement& e : els)
      for (int j = 0; j < e.nv; ++j) grow(b.xy(e.v[static_cast<std::size_t>(j)]));
    const double items = static_cast<double>(els.size() + lines.size());
    n_ = static_cast<int>(std::clamp(std::sqrt(items), 1.0, 1024.0));
    cell_ = {std::max((hi.x - lo_.x) / n_, 1e-300), std::max((hi.y - lo_.y) / n_, 1e-300)};
    cells_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      Box bx = box_of(lines[i].first, lines[i].second);
      visit(bx, [&](std::vector<Item>& c) { c.push_back({true, i}); });
    }
  }

  bool overlaps(std::size_t i) const {
    const LayerElement& e = els_[i];
    bool hit = false;
    visit(element_box(e), [&](const std::vector<Item>& c) {
      for (const Item& it : c) {
        if (hit) return;
        if (it.line) {
          hit = edges_meet(e, lines_[it.index].first, lines_[it.index].second, nullptr);
        } else if (els_[it.index].column != e.column) {
          hit = elements_meet(e, els_[it.index]);
        }
      }
    });
    return hit;
  }

  void insert(std::size_t i) {
    visit(element_box(els_[i]), [&](std::vector<Item>& c) { c.push_back({false, i}); });
  }

 private:
  struct Item {
    bool line;
    std::size_t index;
  };
  struct Box {
    int x0, y0, x1, y1;
  };

  int cell_index(double v, double lo, double size) const {
    return std::clamp(static_cast<int>(std::floor((v - lo) / size)), 0, n_ - 1);
  }
  Box box_of(Vec2 p, Vec2 q) const {
    return {cell_index(std::min(p.x, q.x), lo_.x, cell_.x), cell_index(std::min(p.y, q.y), lo_.y, cell_.y),
            cell_index(std::max(p.x, q.x), lo_.x, cell_.x), cell_index(std::max(p.y, q.y), lo_.y, cell_.y)};
  }
  Box element_box(const LayerElement& e) const {
    Box bx = box_of(b_.xy(e.v[0]), b_.xy(e.v[1]));
    for (int j = 2; j < e.nv; ++j) {
      const Box o = box_of(b_.xy(e.v[static_cast<std::size_t>(j)]), b_.xy(e.v[static_cast<std::size_t>(j)]));
      bx = {std::min(bx.x0, o.x0), std::min(bx.y0, o.y0), std::max(bx.x1, o.x1), std::max(bx.y1, o.y1)};
    }
    return bx;
  }
  template <class Fn>
  void visit(Box bx, Fn&& fn) const {
    for (int y = bx.y0; y <= bx.y1; ++y)
      for (int x = bx.x0; x <= bx.x1; ++x)
        fn(cells_[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(x)]);
  }
  template <class Fn>
  void visit(Box bx, Fn&& fn) {
    for (int y = bx.y0; y <= bx.y1; ++y)
      for (int x = bx.x0; x <= bx.x1; ++x)
        fn(cells_[static_cast<std::size_t>(y) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(x)]);
  }

  // Whether an edge of element e meets segment pq; with `ids` (the segment's node ids)
  // edges sharing a node with it do not count, as in Gmsh.
  bool edges_meet(const LayerElement& e, Vec2 p, Vec2 q, const std::array<std::uint32_t, 2>* ids) const {
    for (int j = 0; j < e.nv; ++j) {
      const std::uint32_t a = e.v[static_cast<std::size_t>(j)], c = e.v[static_cast<std::size_t>((j + 1) % e.nv)];
      const Vec2 pa = b_.xy(a), pc = b_.xy(c);
      if (ids ? (a == (*ids)[0] || a == (*ids)[1] || c == (*ids)[0] || c == (*ids)[1])
              : (pa == p || pa == q || pc == p || pc == q))
        continue;
      if (segments_meet(pa, pc, p, q)) return true;
    }
    return false;
  }
  bool elements_meet(const LayerElement& e, const LayerElement& o) const {
    for (int j = 0; j < o.nv; ++j) {
      const std::array<std::uint32_t, 2> ids{o.v[static_cast<std::size_t>(j)],
                                             o.v[static_cast<std::size_t>((j + 1) % o.nv)]};
      if (edges_meet(e, b_.xy(ids[0]), b_.xy(ids[1]), &ids)) return true;
    }
    return false;
  }

  const LayerBuild& b_;
  const std::vector<LayerElement>& els_;
  const std::vector<std::pair<Vec2, Vec2>>& lines_;
  Vec2 lo_;
  Vec2 cell_;
  int n_ = 1;
  std::vector<std::vector<Item>> cells_;
};

// Slit s joined into the first ring that holds one of its end nodes: from that node out
// along the slit to its tip and back, then on as before. False when no ring holds either.
bool join_slit(std::vector<Ring>& rings, const FaceChain& s) {
  for (int end = 0; end < 2; ++end) {
    std::vector<std::uint32_t> nodes = s.nodes;
    std::vector<int> curves = s.edge_curve;
    if (end == 1) {
      std::reverse(nodes.begin(), nodes.end());
      std::reverse(curves.begin(), curves.end());
    }
    for (Ring& g : rings) {
      const auto pos = std::find(g.r.begin(), g.r.end(), nodes.front());
      if (pos == g.r.end()) continue;
      const std::size_t i = static_cast<std::size_t>(pos - g.r.begin());
      // r[i], out along the slit to its end and back to r[i], then on as before.
      // Each walk node with the curve of the edge leaving it: out along curves[m], the
      // tip back along its last edge, back along curves[m - 1], and r[i] again onward
      // along the ring's old edge i.
      const std::size_t last = nodes.size() - 1;
      std::vector<std::uint32_t> walk;
      std::vector<int> wc;
      for (std::size_t m = 1; m < last; ++m) walk.push_back(nodes[m]), wc.push_back(curves[m]);
      walk.push_back(nodes[last]), wc.push_back(curves[last - 1]);
      for (std::size_t m = last; m-- > 1;) walk.push_back(nodes[m]), wc.push_back(curves[m - 1]);
      walk.push_back(nodes[0]), wc.push_back(g.ec[i]);
      g.ec[i] = curves.front();
      g.r.insert(g.r.begin() + static_cast<std::ptrdiff_t>(i + 1), walk.begin(), walk.end());
      g.ec.insert(g.ec.begin() + static_cast<std::ptrdiff_t>(i + 1), wc.begin(), wc.end());
      return true;
    }
  }
  return false;
}

// A slit touching no ring: a ring of its own, walked out and back.
Ring slit_ring(const FaceChain& s) {
  Ring g;
  for (std::size_t k = 0; k < s.nodes.size(); ++k) g.r.push_back(s.nodes[k]);
  for (std::size_t k = 0; k + 1 < s.nodes.size(); ++k) g.ec.push_back(s.edge_curve[k]);
  for (std::size_t k = s.nodes.size() - 1; k-- > 1;) g.r.push_back(s.nodes[k]);
  for (std::size_t k = s.nodes.size() - 1; k-- > 0;) g.ec.push_back(s.edge_curve[k]);
  return g;
}

// The rings: the loops with the face on their left, then the embedded layer curves as
// slits, joined to a ring at an end node they share with it (else rings of their own).
// The embedded curves without layers are handed back in `plain_embedded`.
std::vector<Ring> layer_rings(LayerBuild& b, std::vector<FaceChain>& plain_embedded) {
  FaceWork& f = b.f;
  std::vector<Ring> rings;
  for (std::size_t ci = 0; ci < f.chains.size(); ++ci) {
    Ring g{f.chains[ci].nodes, f.chains[ci].edge_curve};
    const bool ccw = counter_clockwise(b, g.r);
    if (ccw != (ci == 0)) reverse_ring(g);
    rings.push_back(std::move(g));
  }
  std::vector<FaceChain> slits;
  for (FaceChain& ch : f.emb_curves) {
    bool layered = false;
    for (int c : ch.edge_curve) layered = layered || b.field_of(c);
    (layered ? slits : plain_embedded).push_back(std::move(ch));
  }
  f.emb_curves.clear();  // given back later: the plain ones, and slit edges left bare
  for (const FaceChain& s : slits)
    if (!join_slit(rings, s)) rings.push_back(slit_ring(s));
  return rings;
}

DirectedEdges boundary_edges(const std::vector<Ring>& rings) {
  DirectedEdges de;
  for (const Ring& g : rings)
    for (std::size_t k = 0; k < g.r.size(); ++k) {
      const std::uint32_t a = g.r[k], c = g.r[(k + 1) % g.r.size()];
      de.add(a, c);
      de.curve[{a, c}] = g.ec[k];
    }
  return de;
}

// The elements with their layer (1 at the wall) and their column (those of one edge,
// or of one slot of a fan), as Gmsh numbers them for its overlap filter.
struct LayerElements {
  const LayerBuild& b;
  std::vector<LayerElement> els;
  int column_id = 0;
  void add(std::array<std::uint32_t, 4> v, int nv, int layer, const BoundaryLayerParams& p) {
    if (orient2d(b.xy(v[0]), b.xy(v[1]), b.xy(v[2])) == Sign::Negative)
      std::swap(v[1], v[static_cast<std::size_t>(nv - 1)]);
    els.push_back({v, nv, layer, column_id, p.quads});
  }
};

// The columns at each place k of ring g: one along the bisector, a fan at a fan point or
// a slit's tip, or the end column where the layer stops; `fan_at[k]` marks the fans.
std::vector<std::vector<Column>> ring_columns(LayerBuild& b, const Ring& g, std::vector<bool>& fan_at) {
  const FaceWork& f = b.f;
  const std::size_t n = g.r.size();
  std::vector<std::vector<Column>> cols(n);
  fan_at.assign(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    const int cp = g.ec[(k + n - 1) % n], cn = g.ec[k];
    const BoundaryLayerParams* fp = b.field_of(cp);
    const BoundaryLayerParams* fn = b.field_of(cn);
    if (!fp && !fn) continue;
    const std::uint32_t v = g.r[k];
    if (fp && fn) {
      const Vec2 pv = b.xy(v), pp = b.xy(g.r[(k + n - 1) % n]), pn = b.xy(g.r[(k + 1) % n]);
      const Vec2 dp = unit(pv - pp), dn = unit(pn - pv);
      const Vec2 np = left_of(dp), nn = left_of(dn);
      const Sign turn = orient2d(pp, pv, pn);
      // Away from the face: a right turn, or a U-turn (a slit's tip).
      const bool uturn = turn == Sign::Zero && dot(dp, dn) < 0;
      const bool reflex = turn == Sign::Negative || uturn;
      const auto vt = b.vertex_of.find(v);
      const bool fan = reflex && vt != b.vertex_of.end() && fn->is_fan_point(vt->second);
      if (fan || uturn) {
        // The turn from np clockwise to nn, in (0, pi].
        double theta = uturn ? std::numbers::pi : -std::atan2(cross(dp, dn), dot(dp, dn));
        theta = std::clamp(theta, 0.0, std::numbers::pi);
        const int size = fan ? fn->fan_size(vt->second, f.opt.boundary_layer_fan_elements) : 0;
        const int extra = std::clamp(static_cast<int>(theta / std::numbers::pi * size + 0.5), 0, 1000);
        for (int j = 0; j <= extra + 1; ++j)
          cols[k].push_back(b.column(*fn, v, cn, unit(rotate_cw(np, theta * j / (extra + 1)))));
        // Without a fan (extra = 0), Gmsh's tip keeps its two columns and nothing between.
        fan_at[k] = fan;
      } else {
        Vec2 d = unit(np + nn);
        if (d.x == 0 && d.y == 0) d = np;
        cols[k].push_back(b.column(*fn, v, cn, d));
      }
    } else if (fp) {
      cols[k].push_back(end_column(g, k, +1));
    } else {
      cols[k].push_back(end_column(g, k, -1));
    }
  }
  return cols;
}

// The elements of each layer edge of ring g, then of each fan.
void ring_elements(const LayerBuild& b, const Ring& g, const std::vector<std::vector<Column>>& cols,
                   const std::vector<bool>& fan_at, LayerElements& out) {
  const std::size_t n = g.r.size();
  for (std::size_t k = 0; k < n; ++k) {
    const BoundaryLayerParams* fl = b.field_of(g.ec[k]);
    if (!fl) continue;
    const std::size_t k1 = (k + 1) % n;
    const Column& c1 = cols[k].back();
    const Column& c2 = cols[k1].front();
    const std::size_t N = std::min(c1.size(), c2.size());
    if (N == 0) continue;
    for (std::size_t l = 0; l < N; ++l) {
      const std::uint32_t v11 = l == 0 ? g.r[k] : c1[l - 1], v12 = l == 0 ? g.r[k1] : c2[l - 1];
      out.add({v11, v12, c2[l], c1[l]}, 4, static_cast<int>(l + 1), *fl);
    }
    if (c1.size() != c2.size())
      out.add({c1[N - 1], c2[N - 1], c1.size() > c2.size() ? c1[N] : c2[N], 0}, 3, static_cast<int>(N + 1), *fl);
    ++out.column_id;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const BoundaryLayerParams* fl = b.field_of(g.ec[k]);
    for (std::size_t i = 0; fl && fan_at[k] && i + 1 < cols[k].size(); ++i) {
      const Column& c1 = cols[k][i];
      const Column& c2 = cols[k][i + 1];
      const std::size_t N = std::min(c1.size(), c2.size());
      for (std::size_t l = 0; l < N; ++l) {
        if (l == 0)
          out.add({g.r[k], c2[0], c1[0], 0}, 3, 1, *fl);
        else
          out.add({c1[l - 1], c2[l - 1], c2[l], c1[l]}, 4, static_cast<int>(l + 1), *fl);
      }
      ++out.column_id;
    }
  }
}

// Gmsh's filter (Mesh/filterElements.cpp there): layer by layer, an element whose
// edges cross the face's boundary or an element kept before (not of its own column)
// is dropped, and each column ends below its first dropped element (its first
// element stays all the same).
std::vector<bool> kept_elements(const LayerBuild& b, const std::vector<LayerElement>& els, const DirectedEdges& de) {
  std::vector<std::pair<Vec2, Vec2>> lines;
  for (const auto& [e, cnt] : de.count) lines.push_back({b.xy(e.first), b.xy(e.second)});
  std::vector<std::size_t> order(els.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return els[x].layer < els[y].layer; });
  std::vector<bool> dropped(els.size(), false);
  {
    OverlapGrid grid(b, els, lines);
    for (std::size_t i : order) {
      if (grid.overlaps(i))
        dropped[i] = true;
      else
        grid.insert(i);
    }
  }
  std::vector<bool> keep(els.size(), false);
  std::map<int, std::vector<std::size_t>> by_column;
  for (std::size_t i = 0; i < els.size(); ++i) by_column[els[i].column].push_back(i);
  for (const auto& [col, members] : by_column) {
    for (std::size_t j = 0; j < members.size(); ++j) {
      if (dropped[members[j]] && j > 0) break;
      keep[members[j]] = true;
      if (dropped[members[j]]) break;
    }
  }
  return keep;
}

// The kept elements into the face: their pending points made nodes in the order they are
// met, quadrangles kept or split along their shorter diagonal; every edge of every
// element cancels against the boundary and its neighbours in `de`.
void emit_layer_elements(LayerBuild& b, const std::vector<LayerElement>& els, const std::vector<bool>& keep,
                         DirectedEdges& de) {
  FaceWork& f = b.f;
  std::vector<std::uint32_t> made(b.pending.size(), kNoLocal);
  auto node_of = [&](std::uint32_t v) {
    if (!(v & kPending)) return v;
    std::uint32_t& m = made[v & ~kPending];
    if (m == kNoLocal) {
      const Vec2 q = b.pending[v & ~kPending];
      m = f.plane.geom ? f.mesh.add_node(f.plane.to_space(q), f.plane.to_param(q))
                       : f.mesh.add_node(f.plane.to_space(q));
      f.layer_nodes.push_back(m);
    }
    return m;
  };
  const bool recombined = f.recombined();
  for (std::size_t i = 0; i < els.size(); ++i) {
    if (!keep[i]) continue;
    const LayerElement& e = els[i];
    std::array<std::uint32_t, 4> q{};
    for (int j = 0; j < e.nv; ++j) q[static_cast<std::size_t>(j)] = node_of(e.v[static_cast<std::size_t>(j)]);
    for (int j = 0; j < e.nv; ++j)
      de.element_edge(q[static_cast<std::size_t>(j)], q[static_cast<std::size_t>((j + 1) % e.nv)]);
    if (e.nv == 3) {
      f.layer_triangles.push_back({q[0], q[1], q[2]});
    } else if (e.quads || recombined) {
      f.layer_quads.push_back(q);
    } else {
      const double d02 = norm(b.xy(q[2]) - b.xy(q[0])), d13 = norm(b.xy(q[3]) - b.xy(q[1]));
      if (d02 <= d13) {
        f.layer_triangles.push_back({q[0], q[1], q[2]});
        f.layer_triangles.push_back({q[0], q[2], q[3]});
      } else {
        f.layer_triangles.push_back({q[0], q[1], q[3]});
        f.layer_triangles.push_back({q[1], q[2], q[3]});
      }
    }
  }
}

// What is left of the face's boundary after the layers: edges walked both ways become
// embedded edges (a slit without layers), the rest is chained into the loops of the rest
// of the face, the outer one (the largest area) first.
bool rest_of_face(LayerBuild& b, const DirectedEdges& de, std::vector<FaceChain>& plain_embedded) {
  FaceWork& f = b.f;
  std::map<std::uint32_t, std::vector<std::uint32_t>> out;
  for (const auto& [e, cnt] : de.count) {
    const auto back = de.count.find({e.second, e.first});
    if (back != de.count.end()) {
      if (e.first < e.second) {
        const auto cv = de.curve.find(e);
        f.emb_curves.push_back(FaceChain{{e.first, e.second}, {cv != de.curve.end() ? cv->second : 0}});
      }
      continue;
    }
    for (int i = 0; i < cnt; ++i) out[e.first].push_back(e.second);
  }
  for (FaceChain& ch : plain_embedded) f.emb_curves.push_back(std::move(ch));
  std::vector<FaceChain> loops;
  std::set<std::uint32_t> used;
  for (const auto& [start, nexts] : out) {
    if (used.count(start)) continue;
    FaceChain ch;
    std::uint32_t v = start;
    for (std::size_t guard = 0; guard <= out.size(); ++guard) {
      const auto it = out.find(v);
      if (it == out.end() || it->second.size() != 1 || used.count(v))
        return f.fail(MeshProblem::LayersOverlap, {}, f.mesh.nodes[v].xyz);
      used.insert(v);
      ch.nodes.push_back(v);
      const auto cv = de.curve.find({v, it->second.front()});
      ch.edge_curve.push_back(cv != de.curve.end() ? cv->second : 0);
      v = it->second.front();
      if (v == start) break;
    }
    if (v != start || ch.nodes.size() < 3)
      return f.fail(MeshProblem::LayersOpen, {}, f.mesh.nodes[start].xyz);
    loops.push_back(std::move(ch));
  }
  auto area = [&](const FaceChain& ch) {
    double a = 0;
    for (std::size_t i = 0; i < ch.nodes.size(); ++i)
      a += cross(b.xy(ch.nodes[i]), b.xy(ch.nodes[(i + 1) % ch.nodes.size()]));
    return std::abs(a);
  };
  std::size_t outer = 0;
  for (std::size_t i = 1; i < loops.size(); ++i)
    if (area(loops[i]) > area(loops[outer])) outer = i;
  if (loops.empty()) return f.fail(MeshProblem::LayersFill);
  std::swap(loops[0], loops[outer]);
  f.chains = std::move(loops);
  return true;
}

}  // namespace

bool build_boundary_layers(FaceWork& f) {
  if (!f.opt.boundary_layers || f.opt.boundary_layers->empty() || f.estimate_only) return true;
  LayerBuild b{f, {}, {}};
  bool any = false;
  for (const FaceChain& ch : f.chains)
    for (int c : ch.edge_curve) any = any || b.field_of(c);
  for (const FaceChain& ch : f.emb_curves)
    for (int c : ch.edge_curve) any = any || b.field_of(c);
  if (!any) return true;
  for (const auto& [vt, node] : f.mesh.vertex_node) b.vertex_of.emplace(node, vt);

  std::vector<FaceChain> plain_embedded;
  const std::vector<Ring> rings = layer_rings(b, plain_embedded);
  DirectedEdges de = boundary_edges(rings);
  LayerElements elements{b, {}, 0};
  for (const Ring& g : rings) {
    std::vector<bool> fan_at;
    const std::vector<std::vector<Column>> cols = ring_columns(b, g, fan_at);
    ring_elements(b, g, cols, fan_at, elements);
  }
  const std::vector<bool> keep = kept_elements(b, elements.els, de);
  emit_layer_elements(b, elements.els, keep, de);
  return rest_of_face(b, de, plain_embedded);
}

}  // namespace sm
