// Deviation of the coast curves from their source points, and control points put back
// where it exceeds the bound (coast/deviation.h).
//
// What each control-polygon segment's scan finds depends only on the control points two
// before to three after it and the source points between them, so the pass keeps each
// segment's result from round to round and scans again only the segments next to the
// points put back; the final figures are read from those results, not from a second scan
// of every curve. Each scan samples a span once (not once per segment that looks at it).
#include "coast/deviation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <span>

#include "base/parallel.h"
#include "coast/segment_distance.h"

namespace sm::coast {

namespace {

// Points of each span's sampled polyline (the span's own end points included): a cubic
// span of a control polygon coarsened at gamma bends by far less than a gamma over an
// eighth of its length, so the polyline is within a small fraction of the bound.
constexpr int kSamples = 8;

// A polyline with each segment's direction and squared length computed once: the distance
// of many points to one polyline (the curve near a segment against each source point
// between its control points) reuses them. Its segments go in groups of kGroup, each in a
// ball holding its points; a group whose ball lies farther than the nearest segment found
// so far is passed over (the minimum over the rest is the same number: each skipped
// segment's distance, as computed, is larger than it).
class Polyline {
 public:
  static constexpr std::size_t kGroup = 8;

  // `margin` (metres) covers the rounding of the distances and the balls: far above it
  // (coordinates of the sphere's size carry ~1e-16 of it), far below any distance.
  void assign(const std::vector<Vec3>& pts, double margin) {
    a_.clear();
    ab_.clear();
    l2_.clear();
    centre_.clear();
    reach_.clear();
    margin_ = margin;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      a_.push_back(pts[i]);
      if (i + 1 < pts.size()) {
        ab_.push_back(pts[i + 1] - pts[i]);
        l2_.push_back(norm2(ab_.back()));
      }
    }
    for (std::size_t g = 0; g < ab_.size(); g += kGroup) {
      const std::size_t last = std::min(g + kGroup, ab_.size());  // its points g..last
      Vec3 lo = pts[g], hi = pts[g];
      for (std::size_t i = g + 1; i <= last; ++i)
        lo = {std::min(lo.x, pts[i].x), std::min(lo.y, pts[i].y), std::min(lo.z, pts[i].z)},
        hi = {std::max(hi.x, pts[i].x), std::max(hi.y, pts[i].y), std::max(hi.z, pts[i].z)};
      const Vec3 centre = 0.5 * (lo + hi);
      double r2 = 0;
      for (std::size_t i = g; i <= last; ++i) r2 = std::max(r2, norm2(pts[i] - centre));
      centre_.push_back(centre);
      reach_.push_back(std::sqrt(r2) + margin);
    }
  }
  // The distance from p: the nearest segment found on squared distances (no square root
  // per segment: this is most of the pass's time), the root taken once. The group of
  // segment `first` is measured first (the nearest one, as a rule, so that the others
  // are passed over).
  double distance(const Vec3& p, std::size_t first = 0) const {
    return std::sqrt(nearest2(p, first, [](double) { return false; }));
  }
  // Whether distance(p, first) / bound > 1, the search ended once a segment within the
  // bound is found: the minimum only falls as segments are measured, and the root and
  // the division are monotone, so an answer of "not over" on the way stays so.
  bool farther_than(const Vec3& p, std::size_t first, double bound) const {
    const auto over = [bound](double d2) { return std::sqrt(d2) / bound > 1; };
    return over(nearest2(p, first, [&](double d2) { return !over(d2); }));
  }

 private:
  // The smallest squared distance from p to a segment, or the smaller one reached when
  // done(d2) holds after a group (or after the first point).
  template <class Done>
  double nearest2(const Vec3& p, std::size_t first, const Done& done) const {
    if (a_.empty()) return HUGE_VAL;
    double d2 = norm2(p - a_.front());
    if (done(d2)) return d2;
    const std::size_t groups = centre_.size();
    const std::size_t g0 = std::min(first, ab_.size() > 0 ? ab_.size() - 1 : 0) / kGroup;
    for (std::size_t k = 0; k < groups; ++k) {
      const std::size_t g = k == 0 ? g0 : (k <= g0 ? k - 1 : k);
      const double dc = norm(p - centre_[g]) - reach_[g] - margin_;
      if (dc > 0 && dc * dc > d2) continue;
      const std::size_t last = std::min((g + 1) * kGroup, ab_.size());
      for (std::size_t i = g * kGroup; i < last; ++i) {
        const Vec3& a = a_[i];
        const Vec3& ab = ab_[i];
        const double l2 = l2_[i];
        d2 = std::min(d2, segment_distance2(p, a, ab, l2));
      }
      if (done(d2)) return d2;
    }
    return d2;
  }

  std::vector<Vec3> a_, ab_, centre_;
  std::vector<double> l2_, reach_;
  double margin_ = 0;
};

// Whether one of the source segments of `pts` near segment `around` (kNearSegments on
// each side) lies within `bound` of p, each measured as Polyline measures it: then
// Polyline::farther_than over all of them is false too (the minimum it finds is at most
// that segment's, the same number), without the polyline's set-up. The answer is whether
// any of them is within, so they are tried from `around` outwards (the nearest, as a
// rule, is there: one or two tried, not half of them).
constexpr std::size_t kNearSegments = 4;
bool near_source(const std::vector<Vec3>& pts, std::size_t around, const Vec3& p, double bound) {
  const std::size_t segments = pts.size() > 0 ? pts.size() - 1 : 0;
  const std::size_t lo = around > kNearSegments ? around - kNearSegments : 0;
  const std::size_t hi = std::min(segments, around + kNearSegments);
  if (lo >= hi) return false;
  const auto within = [&](std::size_t i) {
    const Vec3& a = pts[i];
    const Vec3 ab = pts[i + 1] - pts[i];
    const double l2 = norm2(ab);
    return !(std::sqrt(segment_distance2(p, a, ab, l2)) / bound > 1);
  };
  const std::size_t start = std::min(around, hi - 1);
  if (within(start)) return true;
  // Each step tries one more segment of [lo, hi): at most hi - lo - 1 of them.
  for (std::size_t l = start, r = start + 1; l > lo || r < hi;) {
    if (l > lo && within(--l)) return true;
    if (r < hi && within(r++)) return true;
  }
  return false;
}

// One span of the curve as a group of the near-curve polyline (Polyline, kGroup = kSamples):
// its samples, each sample-to-sample segment's direction and squared length, and the ball
// that holds its points, as Polyline::assign makes them for the group the span is there.
struct SpanGroup {
  long k = 0;   // the span (unwrapped)
  Vec3 p[kSamples + 1];
  Vec3 ab[kSamples];
  double l2[kSamples];
  Vec3 centre;
  double reach = 0;
};
static_assert(Polyline::kGroup == kSamples, "a span is one group of the near-curve polyline");

// The weights (times 6) of the uniform cubic B-spline's four control points at each sample
// of a span, made once: the same doubles as made for each span (t = i / kSamples).
struct SampleWeights {
  double w[kSamples + 1][4];
};
const SampleWeights& sample_weights() {
  static const SampleWeights table = [] {
    SampleWeights sw{};
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples, u = 1 - t;
      sw.w[i][0] = u * u * u;
      sw.w[i][1] = 3 * t * t * t - 6 * t * t + 4;
      sw.w[i][2] = -3 * t * t * t + 3 * t * t + 3 * t + 1;
      sw.w[i][3] = t * t * t;
    }
    return sw;
  }();
  return table;
}

// One curve seen by the pass: its control points, spans and source points on the sphere.
// The source points are mapped to the sphere where a scan reads them (a division and a few
// products each, about four times per point and scan): kept for every curve between the
// rounds, they were 24 bytes a source point, 220 MB of the import's peak on the
// full-resolution world (docs/kernel.md, "Memory of the 2D pipeline": the 3 km world's
// peak is the import's).
class CurveView {
 public:
  CurveView(const WorkCurve& c, const geo::PolarSphere& ps, const DeviationOptions& opt)
      : c_(c), ps_(ps), opt_(opt), n_(static_cast<long>(c.full.size())), m_(static_cast<long>(c.keep.size())) {}

  // Control-polygon segments: s goes from keep[s] to keep[s + 1] (the last one of a
  // periodic curve wraps to keep[0]).
  long segments() const { return c_.periodic ? m_ : m_ - 1; }

  // Source indices of segment s, from its first control point up to (not including) the
  // next one, unwrapped (may run past n for the closing segment of a periodic curve).
  std::pair<long, long> source_range(long s) const {
    const long a = c_.keep[static_cast<std::size_t>(s)];
    long b = s + 1 < m_ ? static_cast<long>(c_.keep[static_cast<std::size_t>(s + 1)]) : c_.keep[0] + n_;
    return {a, b};
  }
  // Source indices from the control point before segment s to the one after it, unwrapped:
  // the source points the span test of segment s reads.
  std::pair<long, long> source_around(long s) const {
    auto [from, to] = source_range(s);
    if (s > 0) {
      from = source_range(s - 1).first;
    } else if (c_.periodic) {
      from = source_range(segments() - 1).first - n_;
    }
    if (s + 1 < segments()) {
      to = source_range(s + 1).second;
    } else if (c_.periodic) {
      to = source_range(0).second + n_;
    }
    return {from, to};
  }
  Vec3 source(long j) const { return ps_.point(c_.uv[static_cast<std::size_t>(((j % n_) + n_) % n_)]); }
  double bound(long j) const {
    const double g = c_.gamma[static_cast<std::size_t>(((j % n_) + n_) % n_)];
    if (opt_.fixed > 0) return opt_.fixed;
    return opt_.factor > 0 ? opt_.factor * g : HUGE_VAL;  // no bound: measured only
  }
  // Segment s itself (straight segments, CurveType "Line").
  void line(long s, std::vector<Vec3>& out) const {
    out.clear();
    out.push_back(ps_.point(control(s)));
    out.push_back(ps_.point(control(s + 1)));
  }
  // Span k (a piece has spans -1 to m-1; a periodic curve's span k is span k mod m) into g:
  // its kSamples + 1 points (its control points k-1 to k+2), and the group's data.
  void span_group(long k, double margin, SpanGroup& g) const {
    g.k = k;
    const Vec2 a = control(k - 1), b = control(k), c = control(k + 1), d = control(k + 2);
    const SampleWeights& w = sample_weights();
    for (int i = 0; i <= kSamples; ++i) {
      const double* wi = w.w[i];
      g.p[i] = ps_.point((wi[0] * a + wi[1] * b + wi[2] * c + wi[3] * d) / 6.0);
    }
    Vec3 lo = g.p[0], hi = g.p[0];
    for (int i = 0; i < kSamples; ++i) {
      g.ab[i] = g.p[i + 1] - g.p[i];
      g.l2[i] = norm2(g.ab[i]);
      const Vec3& q = g.p[i + 1];
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)},
      hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    }
    g.centre = 0.5 * (lo + hi);
    double r2 = 0;
    for (int i = 0; i <= kSamples; ++i) r2 = std::max(r2, norm2(g.p[i] - g.centre));
    g.reach = std::sqrt(r2) + margin;
  }

 private:
  // Control point k: wrapped on a periodic curve; clamped on a piece, whose end points
  // count three times (the spans -1 and m-1 then end exactly on them).
  Vec2 control(long k) const {
    const long i = c_.periodic ? ((k % m_) + m_) % m_ : std::clamp(k, 0L, m_ - 1);
    return c_.uv[c_.keep[static_cast<std::size_t>(i)]];
  }

  const WorkCurve& c_;
  const geo::PolarSphere& ps_;
  const DeviationOptions& opt_;
  long n_, m_;
};

// Whether two points are the same bits (a span's first sample against the one before's
// last: the same sum of the same terms, but for signed zeros).
bool same_bits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

// The curve near segment s (spans s-1, s, s+1) as the three groups of one polyline: the
// spans a scan reads, each made once for the three segments that read it (segments are
// scanned in order; made again when s jumps). The polyline of the three spans (each span
// after the first from its second sample on) is the one whose groups these are when each
// span starts on the bits the one before ends on, which near() checks.
class NearSpans {
 public:
  NearSpans(const CurveView& v, double margin) : v_(v), margin_(margin) {}
  // The three groups for segment s, span s first (as Polyline::distance with the span's
  // first segment as `first` tries them); false when the spans do not join bit for bit.
  bool near(long s, const SpanGroup* (&g)[3]) {
    g[0] = &get(s - 1);
    g[1] = &get(s);
    g[2] = &get(s + 1);
    return same_bits(g[0]->p[kSamples], g[1]->p[0]) && same_bits(g[1]->p[kSamples], g[2]->p[0]);
  }

 private:
  // Span k in slot k mod 3: the three spans of a segment never share a slot.
  const SpanGroup& get(long k) {
    const std::size_t slot = static_cast<std::size_t>(((k % 3) + 3) % 3);
    SpanGroup& g = ring_[slot];
    if (!made_[slot] || g.k != k) {
      v_.span_group(k, margin_, g);
      made_[slot] = 1;
    }
    return g;
  }

  const CurveView& v_;
  double margin_;
  SpanGroup ring_[3];
  char made_[3] = {0, 0, 0};
};

// Polyline::distance(p, kSamples) over the polyline of the three spans of NearSpans::near
// (the same numbers, group by group: the spans' own data are the groups').
double near_distance(const Vec3& p, const SpanGroup* const (&g)[3], double margin) {
  double d2 = norm2(p - g[0]->p[0]);
  for (int k : {1, 0, 2}) {
    const SpanGroup& h = *g[k];
    const double dc = norm(p - h.centre) - h.reach - margin;
    if (dc > 0 && dc * dc > d2) continue;
    for (int i = 0; i < kSamples; ++i) {
      const Vec3& a = h.p[i];
      const Vec3& ab = h.ab[i];
      const double l2 = h.l2[i];
      d2 = std::min(d2, segment_distance2(p, a, ab, l2));
    }
  }
  return std::sqrt(d2);
}

// The curve near segment s as a scan measures the segment's source points against it:
// the three spans of NearSpans as groups of their own, or their polyline made as one
// where they do not join bit for bit; with straight segments (CurveType "Line"), the
// segment itself. `own`: the curve that follows the segment (span s, or the segment).
class NearCurve {
 public:
  NearCurve(const CurveView& v, bool bspline, double margin) : v_(v), spans_(v, margin), bspline_(bspline), margin_(margin) {}
  void set(long s) {
    grouped_ = false;
    if (!bspline_) {
      v_.line(s, points_);
      own_ = points_;
      line_.assign(points_, margin_);
      return;
    }
    grouped_ = spans_.near(s, groups_);
    own_ = std::span<const Vec3>(groups_[1]->p, kSamples + 1);
    if (grouped_) return;
    points_.assign(groups_[0]->p, groups_[0]->p + kSamples + 1);
    for (int k = 1; k < 3; ++k) points_.insert(points_.end(), groups_[k]->p + 1, groups_[k]->p + kSamples + 1);
    line_.assign(points_, margin_);
  }
  // The span of segment s comes after the span before it (a piece's first segment too: it
  // has span -1): its group is measured first.
  double distance(const Vec3& p) const {
    return grouped_ ? near_distance(p, groups_, margin_) : line_.distance(p, bspline_ ? kSamples : 0);
  }
  std::span<const Vec3> own() const { return own_; }

 private:
  const CurveView& v_;
  NearSpans spans_;
  bool bspline_;
  double margin_;
  const SpanGroup* groups_[3] = {nullptr, nullptr, nullptr};
  bool grouped_ = false;
  std::vector<Vec3> points_;
  Polyline line_;
  std::span<const Vec3> own_;
};

// Whether the curve `own` that follows a segment strays farther than `bound` from the
// source polyline `window` (the source points from the control point before the segment
// to the one after; the segment's own source points are a..b, window[0] is source point
// `from`). The i-th sample of the curve lies, as a rule, nearest the source points that
// far along the segment: the source segments there are tried first, and the whole
// polyline only from the first sample none of them is within the bound of; each sample is
// measured only until a source segment within the bound is found.
bool curve_strays(std::span<const Vec3> own, const std::vector<Vec3>& window, long from, long a, long b, double bound,
                  Polyline& source_line, double margin) {
  const auto along = [&](std::size_t i) {
    const long steps = static_cast<long>(std::max<std::size_t>(own.size() - 1, 1));
    return static_cast<std::size_t>((a - from) + (b - a) * static_cast<long>(i) / steps);
  };
  std::size_t i = 0;
  while (i < own.size() && near_source(window, along(i), own[i], bound)) ++i;
  if (i == own.size()) return false;
  source_line.assign(window, margin);
  for (; i < own.size(); ++i)
    if (source_line.farther_than(own[i], along(i), bound)) return true;
  return false;
}

// What the scan of one control-polygon segment found, kept until a point put back near it
// changes its curve.
struct SegmentResult {
  double ratio = 0;   // the largest distance / bound of its source points
  double max = 0;     // the largest distance of its source points
  long max_at = -1;   // where (source index)
  bool narrow = false;  // over the bound at a feature narrower than the accuracy
  char event = 0;     // 'o': over the bound with no source point left; 'n': narrow
  long event_at = -1;
};

// What the pass keeps of one curve between rounds: each segment's result and each source
// point's distance to the curve.
struct CurveState {
  std::vector<SegmentResult> seg;
  std::vector<double> dist;
  std::vector<char> fresh;  // per control point: put back by the last change
  bool stale = false;       // changed since its segments were scanned
};

// What one look at a curve found: the points to put back, and the figures over its
// segments (aggregate below).
struct CurveScan {
  std::vector<std::uint32_t> add;  // source points to put back
  std::vector<std::uint32_t> split;  // source segments (their first point) to split at the middle
  double max = 0, max_ratio = 0;
  long max_at = -1;
  std::size_t over = 0;  // spans over the bound with no source point left
  long over_at = -1;
  std::size_t narrow = 0;  // spans over the bound whose points would make a spike
  long narrow_at = -1;
  double narrow_max = 0;  // the farthest source point of those
};

// The angle (radians) at b between the directions to a and to c, in (u,v): the map is
// conformal, so it is the angle on the sphere.
double angle_at(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = a - b, w = c - b;
  return std::atan2(std::abs(u.x * w.y - u.y * w.x), dot(u, w));
}

// Scans the segments of one curve (all of them, or with `fresh` those whose curve a point
// put back last changed) into st.seg and st.dist, and picks the point to put back on each
// segment over the bound.
CurveScan scan_curve(const WorkCurve& c, const geo::PolarSphere& ps, const DeviationOptions& opt, CurveState& st,
                     const std::vector<char>* fresh) {
  CurveScan out;
  if (c.keep.size() < 2 || c.open_boundary) return out;
  CurveView v(c, ps, opt);
  const long n = static_cast<long>(c.full.size());
  const long m = static_cast<long>(c.keep.size());
  st.seg.resize(static_cast<std::size_t>(v.segments()));
  st.dist.resize(c.full.size(), 0.0);
  const double min_angle = opt.min_angle_deg * geo::kDegToRad;
  const bool bounded = opt.fixed > 0 || opt.factor > 0;
  const double margin = 1e-10 * opt.radius;   // the rounding of distances on this sphere
  // A segment's curve depends on the control points two before to three after it: the
  // segments a point put back changed are marked from the points (three before to two
  // after each), not looked for at every segment of the curve.
  std::vector<char> touched;
  if (fresh) {
    touched.assign(static_cast<std::size_t>(v.segments()), 0);
    for (long k = 0; k < m; ++k) {
      if (!(*fresh)[static_cast<std::size_t>(k)]) continue;
      for (long s = k - 3; s <= k + 2; ++s) {
        const long i = c.periodic ? ((s % m) + m) % m : s;
        if (i >= 0 && i < v.segments()) touched[static_cast<std::size_t>(i)] = 1;
      }
    }
  }
  auto control = [&](long k) { return c.uv[c.keep[static_cast<std::size_t>(c.periodic ? ((k % m) + m) % m : k)]]; };
  // Putting j back between the control points of segment s: no corner sharper than
  // min_angle at j, nor at its two neighbours unless they were already that sharp (a
  // point deep in an inlet or at the tip of a spit narrower than the accuracy would make
  // a spike the mesh cannot follow at that size).
  auto allowed = [&](long s, long j) {
    const Vec2 A = control(s), B = control(s + 1), J = c.uv[static_cast<std::size_t>(j % n)];
    if (angle_at(A, J, B) < min_angle) return false;
    if (c.periodic || s > 0) {
      const Vec2 P = control(s - 1);
      if (angle_at(P, A, J) < std::min(min_angle, angle_at(P, A, B))) return false;
    }
    if (c.periodic || s + 2 < m) {
      const Vec2 N = control(s + 2);
      if (angle_at(J, B, N) < std::min(min_angle, angle_at(A, B, N))) return false;
    }
    return true;
  };
  // A control point between those of segment s, on their straight segment: no corner at
  // itself, and the same at its neighbours; only where the segment's ends are not
  // sharper than min_angle already (the tip of a spike the curve does not follow).
  auto allowed_between = [&](long s) {
    const Vec2 A = control(s), B = control(s + 1);
    if ((c.periodic || s > 0) && angle_at(control(s - 1), A, B) < min_angle) return false;
    if ((c.periodic || s + 2 < m) && angle_at(A, B, control(s + 2)) < min_angle) return false;
    return true;
  };
  // Splitting the data's segment from source point a: allowed as above and longer than a
  // tenth of the bound (each split halves it, so the splits end).
  auto splittable = [&](long s, long a) {
    return allowed_between(s) && norm(v.source(a + 1) - v.source(a)) > 0.1 * v.bound(a);
  };
  NearCurve near(v, opt.bspline, margin);
  Polyline source_line;
  std::vector<std::pair<double, long>> candidates;
  // With a bound, the source points from the control point before segment s to the one
  // after it on the sphere (`window`, unwrapped indices from window_lo): the next segment's
  // window shares two thirds of them, taken from this one rather than mapped again (each
  // source point was mapped about four times a scan: the mapping was a fifth of the
  // pass's CPU on the full-resolution world at 3 km).
  std::vector<Vec3> window, next_window;
  long window_lo = 0;
  auto make_window = [&](long from, long to) {
    next_window.clear();
    const long hi = window_lo + static_cast<long>(window.size());
    for (long j = from; j <= to; ++j)
      next_window.push_back(j >= window_lo && j < hi ? window[static_cast<std::size_t>(j - window_lo)] : v.source(j));
    std::swap(window, next_window);
    window_lo = from;
  };
  for (long s = 0; s < v.segments(); ++s) {
    if (fresh && !touched[static_cast<std::size_t>(s)]) continue;
    SegmentResult& r = st.seg[static_cast<std::size_t>(s)];
    r = SegmentResult{};
    const auto [a, b] = v.source_range(s);
    near.set(s);
    candidates.clear();
    long from = a;   // the window's first source index
    if (bounded) {
      const auto around = v.source_around(s);
      from = around.first;
      make_window(around.first, around.second);
    }
    const auto source = [&](long j) { return bounded ? window[static_cast<std::size_t>(j - from)] : v.source(j); };
    // Source points to the curve.
    const bool last_point_too = !c.periodic && s + 1 == v.segments();
    for (long j = a; j < b || (j == b && last_point_too); ++j) {
      const double d = near.distance(source(j));
      const double q = d / v.bound(j);
      st.dist[static_cast<std::size_t>(j % n)] = d;
      if (d > r.max) r.max = d, r.max_at = j % n;
      r.ratio = std::max(r.ratio, q);
      if (j > a && j < b) candidates.emplace_back(q, j);
    }
    // The curve to the source points: the span that follows the segment against the
    // source polyline from the control point before it to the one after. It decides only
    // whether the segment is over the bound: not computed when its source points are
    // already over it, nor without a bound (measuring only, the default).
    const bool curve_over =
        bounded && r.ratio <= 1 && curve_strays(near.own(), window, from, a, b, v.bound(a), source_line, margin);
    if (r.ratio <= 1 && !curve_over) continue;
    // The farthest source point that makes no spike; a few tries, farthest first.
    std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
      return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    long pick = -1;
    for (std::size_t t = 0; t < candidates.size() && t < 8 && pick < 0; ++t)
      if (allowed(s, candidates[t].second)) pick = candidates[t].second;
    if (pick >= 0) {
      out.add.push_back(static_cast<std::uint32_t>(pick % n));
    } else if (candidates.empty() && b == a + 1 && splittable(s, a)) {
      // No source point left between the control points (a segment of the data longer
      // than the accuracy, at a bend): the data's own segment is split at its middle, a
      // point of the shoreline; the control points closing in on the bend bring the
      // curve to it (the cut of a B-spline is a sixth of its second difference).
      out.split.push_back(static_cast<std::uint32_t>(a % n));
    } else if (candidates.empty() && !allowed_between(s)) {
      // A spike of the data itself, narrower than the accuracy.
      r.narrow = true, r.event = 'n', r.event_at = a % n;
    } else if (candidates.empty()) {
      r.event = 'o', r.event_at = a % n;
    } else {
      // A feature narrower than the accuracy, left out on purpose.
      r.narrow = true, r.event = 'n', r.event_at = candidates.front().second % n;
    }
  }
  return out;
}

// The figures of one curve from its segments' results, in segment order (the first
// segment reaching the largest distance names the place, the first of each kind of
// segment left over the bound too).
void aggregate(const CurveState& st, CurveScan& out) {
  for (const SegmentResult& r : st.seg) {
    out.max_ratio = std::max(out.max_ratio, r.ratio);
    if (r.event == 'n') {
      ++out.narrow;
      if (out.narrow_at < 0) out.narrow_at = r.event_at;
    } else if (r.event == 'o') {
      ++out.over;
      if (out.over_at < 0) out.over_at = r.event_at;
    }
    if (r.narrow) {
      if (r.max > out.narrow_max) out.narrow_max = r.max;
    } else if (r.max > out.max) {
      out.max = r.max, out.max_at = r.max_at;
    }
  }
}

// Inserts the middle of each source segment `split` (by its first point; sorted below)
// into the curve's points, renumbers `keep` and `add` (sorted) and adds the new points to
// `add`: they become control points. The state's distances follow
// (a middle's distance is measured when its segments are scanned again).
void split_segments(WorkCurve& c, std::vector<std::uint32_t>& split, const geo::PolarSphere& ps,
                    std::vector<std::uint32_t>& keep, std::vector<std::uint32_t>& add, CurveState& st) {
  std::sort(split.begin(), split.end());
  split.erase(std::unique(split.begin(), split.end()), split.end());
  const std::size_t n = c.full.size();
  std::vector<std::uint32_t> new_index(n);
  std::vector<geo::LonLat> full;
  std::vector<Vec2> uv;
  std::vector<double> gamma;
  std::vector<double> dist;
  full.reserve(n + split.size());
  uv.reserve(n + split.size());
  gamma.reserve(n + split.size());
  dist.reserve(n + split.size());
  std::vector<std::uint32_t> mids;
  for (std::size_t j = 0, k = 0; j < n; ++j) {
    new_index[j] = static_cast<std::uint32_t>(full.size());
    full.push_back(c.full[j]);
    uv.push_back(c.uv[j]);
    gamma.push_back(c.gamma[j]);
    dist.push_back(st.dist[j]);
    if (k < split.size() && split[k] == j) {
      const std::size_t e = (j + 1) % n;   // a periodic curve's last segment closes on 0
      const Vec2 mid = 0.5 * (c.uv[j] + c.uv[e]);
      mids.push_back(static_cast<std::uint32_t>(full.size()));
      full.push_back(ps.lonlat_from_param(mid));
      uv.push_back(mid);
      gamma.push_back(std::min(c.gamma[j], c.gamma[e]));
      dist.push_back(0.0);
      ++k;
    }
  }
  c.full = std::move(full);
  c.uv = std::move(uv);
  c.gamma = std::move(gamma);
  st.dist = std::move(dist);
  for (SegmentResult& r : st.seg) {
    if (r.max_at >= 0) r.max_at = new_index[static_cast<std::size_t>(r.max_at)];
    if (r.event_at >= 0) r.event_at = new_index[static_cast<std::size_t>(r.event_at)];
  }
  for (std::uint32_t& k : keep) k = new_index[k];
  for (std::uint32_t& k : add) k = new_index[k];
  std::vector<std::uint32_t> all;
  std::merge(add.begin(), add.end(), mids.begin(), mids.end(), std::back_inserter(all));
  add = std::move(all);
}

// Puts the scan's points back into curve i's control points; the segments between old
// control points keep their results under their new numbers (those near a new point are
// scanned again next).
std::size_t put_back(WorkCurve& curve, CurveScan& s, CurveState& st, const geo::PolarSphere& ps,
                     std::size_t& segments_split) {
  std::vector<std::uint32_t>& keep = curve.keep;
  std::sort(s.add.begin(), s.add.end());
  if (!s.split.empty()) {
    split_segments(curve, s.split, ps, keep, s.add, st);
    segments_split += s.split.size();
  }
  std::vector<std::uint32_t> merged;
  merged.reserve(keep.size() + s.add.size());
  std::merge(keep.begin(), keep.end(), s.add.begin(), s.add.end(), std::back_inserter(merged));
  merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
  st.fresh.assign(merged.size(), 0);
  for (std::size_t k = 0, a = 0; k < merged.size(); ++k) {  // which control points are new
    while (a < s.add.size() && s.add[a] < merged[k]) ++a;
    if (a < s.add.size() && s.add[a] == merged[k]) st.fresh[k] = 1;
  }
  // Segment k starts at control point k: an old one's segment was old - (new ones before).
  const std::size_t segments = curve.periodic ? merged.size() : merged.size() - 1;
  std::vector<SegmentResult> seg(segments);
  for (std::size_t k = 0, added = 0; k < segments; ++k) {
    if (st.fresh[k]) {
      ++added;
      continue;
    }
    const std::size_t old = k - added;
    if (old < st.seg.size()) seg[k] = st.seg[old];
  }
  st.seg = std::move(seg);
  st.stale = true;
  const std::size_t added = merged.size() - keep.size();
  keep = std::move(merged);
  return added;
}

}  // namespace

std::vector<double> source_distances(const WorkCurve& c, const DeviationOptions& opt) {
  const geo::PolarSphere ps({0, 0, 0}, opt.radius);
  CurveState st;
  scan_curve(c, ps, opt, st, nullptr);
  std::vector<double> d(c.full.size(), 0.0);
  if (!st.dist.empty()) d = st.dist;
  return d;
}

DeviationReport bound_deviation(std::vector<WorkCurve>& curves, const DeviationOptions& opt) {
  DeviationReport rep;
  const geo::PolarSphere ps({0, 0, 0}, opt.radius);
  const int threads = resolve_thread_count(opt.threads);
  std::vector<CurveScan> scans(curves.size());
  std::vector<CurveState> states(curves.size());
  std::vector<char> active(curves.size(), 1), changed(curves.size(), 0);
  const int rounds = opt.fixed > 0 || opt.factor > 0 ? opt.max_rounds : 0;
  // One curve a chunk: the rings come largest first (GSHHG's continents lead), so chunks of
  // 64 put nearly every point in the first one and left the other threads idle. Each
  // curve's scan is written to its own slot: the chunks decide only who runs it.
  constexpr std::size_t kChunk = 1;
  for (int round = 0; round < rounds; ++round) {
    parallel_for_chunks(threads, curves.size(), kChunk, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        if (!active[i]) continue;
        scans[i] = scan_curve(curves[i], ps, opt, states[i], round == 0 ? nullptr : &states[i].fresh);
        states[i].stale = false;
      }
    });
    if (round == 0)
      for (std::size_t i = 0; i < curves.size(); ++i) {
        CurveScan figures;
        aggregate(states[i], figures);
        rep.max_before = std::max({rep.max_before, figures.max, figures.narrow_max});
      }
    bool any = false;
    for (std::size_t i = 0; i < curves.size(); ++i) {
      if (!active[i]) continue;
      CurveScan& s = scans[i];
      if (s.add.empty() && s.split.empty()) {
        active[i] = 0;
        continue;
      }
      rep.points_added += put_back(curves[i], s, states[i], ps, rep.segments_split);
      changed[i] = 1;
      any = true;
    }
    rep.rounds = round + 1;
    if (!any) break;
  }
  // The final figures over every curve: from the segments' results, after scanning those
  // the last round's points changed (when the rounds ran out), or every segment once when
  // there is no bound (measured only).
  parallel_for_chunks(threads, curves.size(), kChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      CurveState& st = states[i];
      if (curves[i].open_boundary || curves[i].keep.size() < 2) {
        st = CurveState{};
        continue;
      }
      if (rounds == 0) {
        scan_curve(curves[i], ps, opt, st, nullptr);
      } else if (st.stale) {
        scan_curve(curves[i], ps, opt, st, &st.fresh);
        st.stale = false;
      }
    }
  });
  // Every source point's distance in one array for the 95th percentile, each curve's freed
  // as it is copied (the two at once were 8 bytes a source point more at the import's peak).
  std::size_t total = 0;
  for (const CurveState& st : states) total += st.dist.size();
  std::vector<double> all;
  all.reserve(total);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    CurveScan s;
    aggregate(states[i], s);
    if (rounds == 0) rep.max_before = std::max({rep.max_before, s.max, s.narrow_max});  // no bound: measured only
    rep.curves_changed += changed[i] ? 1 : 0;
    if (s.max > rep.max) rep.max = s.max, rep.where = curves[i].full[static_cast<std::size_t>(s.max_at)];
    rep.max_ratio = std::max(rep.max_ratio, s.max_ratio);
    if (s.over > 0 && rep.left_over_bound == 0) rep.where_over = curves[i].full[static_cast<std::size_t>(s.over_at)];
    rep.left_over_bound += s.over;
    if (s.narrow > 0 && rep.narrow_features == 0)
      rep.where_narrow = curves[i].full[static_cast<std::size_t>(s.narrow_at)];
    rep.narrow_features += s.narrow;
    rep.narrow_max = std::max(rep.narrow_max, s.narrow_max);
    all.insert(all.end(), states[i].dist.begin(), states[i].dist.end());
    states[i] = CurveState{};
  }
  if (!all.empty()) {
    const std::size_t k = std::min(all.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(all.size())));
    std::nth_element(all.begin(), all.begin() + static_cast<long>(k), all.end());
    rep.p95 = all[k];
  }
  return rep;
}

}  // namespace sm::coast
