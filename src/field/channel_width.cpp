// ChannelWidth field. Built once: for every coast sample p and each side of the
// coast at p, the diameter of the largest ball tangent to the coast at p on that
// side that holds no coast sample of another piece (the local width of the water,
// or of the land on the other side). Evaluated with one nearest-sample query.
//
//        other bank   x   x   x   x          q: a sample of another piece;
//                         q                  ball tangent at p on side +m:
//                       .   .                q inside iff |d|^2 < 2 r (d . m),
//                      .  o  .  r            d = q - p, so its diameter is
//                       .   .                min over q of |d|^2 / (d . m)
//        this bank  x   x   p   x   x
//
// Samples of the same ring are "another piece" only when the way round the coast
// is much longer than the chord (> pi/2 |d|: more than a half circle): otherwise a
// concave bend of the coast would read as a channel as narrow as its samples.
#include "field/channel_width.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "base/parallel.h"
#include "field/batch_pieces.h"
#include "field/error.h"
#include "field/kinds.h"
#include "field/knn.h"
#include "field/min_grid.h"

namespace sm::field {

namespace {

// Along-coast distance over chord above which two samples of one ring face
// each other across the water (a half circle: pi/2).
constexpr double kNeighbourRatio = std::numbers::pi / 2;
// Points closer to the coast than this share of the local sample spacing are on
// it: their side is unknown, both sides' smaller width applies.
constexpr double kOnCoast = 0.1;
// Without SizeMax the widths are searched up to this many median sample spacings.
constexpr double kDefaultCapSpacings = 64;
// The points that set a sample's two widths (none: kNoWitness).
constexpr std::uint32_t kNoWitness = std::numeric_limits<std::uint32_t>::max();
struct Witnesses {
  std::uint32_t pos = kNoWitness, neg = kNoWitness;
};

}  // namespace

struct ChannelWidths::Impl {
  // The samples are held once: by `own` until the k-d tree takes them, then by the tree.
  std::vector<Vec3> own;
  std::span<const Vec3> pts;                     // the samples, wherever they are held
  std::vector<std::uint32_t> prev, next;         // per sample; prev/next == self at an open end
  // Only the set-up's searches read these; released after them.
  std::vector<std::uint32_t> chain;              // per sample
  std::vector<double> s;                         // arc length from the chain's first sample
  std::vector<double> length;                    // per chain (closed: with the closing segment)
  std::vector<char> closed;
  std::vector<double> w_pos, w_neg;              // width on the +side / -side, at most cap
  std::vector<int> water;                        // per chain: CoastChain::water_side (set-up only)
  double cap = kMaxLc;
  std::unique_ptr<KdTree> tree;
  // Per cell, the smallest width that a point there can read: a point reads the
  // widths of its nearest sample and of one of that sample's neighbours along the
  // coast, so sample i carries the smallest of both sides' widths at i, prev and next.
  std::unique_ptr<MinGrid> narrowest;
  // A flat model's normal is z; else the sphere's radial direction (the PolarSphere
  // models are centred on the origin).
  bool flat = true;

  // The unit normal to the coast in the surface at sample i (0: unknown) and the larger
  // of its two segments: computed where they are read, from the samples and their
  // neighbours (the same expressions give the same bits), not held (32 bytes a sample).
  Vec3 side(std::uint32_t i) const {
    const Vec3& p = pts[i];
    const Vec3 up = flat || norm(p) == 0 ? Vec3{0, 0, 1} : p / norm(p);
    const Vec3 c = cross(up, pts[next[i]] - pts[prev[i]]);
    return norm(c) > 0 ? c / norm(c) : Vec3{0, 0, 0};
  }
  double spacing(std::uint32_t i) const {
    return std::max(norm(pts[next[i]] - pts[i]), norm(pts[i] - pts[prev[i]]));
  }

  // One sample's two widths (the set-up's search; see the constructor). `seed`: the
  // points that set the previous sample's widths (kNoWitness: none), replaced by this
  // sample's. Each call reads the tree and writes only sample i's widths.
  void search(std::size_t i, Witnesses& seed);

  double width_at(std::uint32_t i, const Vec3& x) const {
    const double off = dot(x - pts[i], side(i));
    if (std::fabs(off) <= kOnCoast * spacing(i)) return std::min(w_pos[i], w_neg[i]);
    return off > 0 ? w_pos[i] : w_neg[i];
  }
};

void ChannelWidths::Impl::search(std::size_t i, Witnesses& seed) {
  const Vec3 p = pts[i], normal = side(static_cast<std::uint32_t>(i));
  double wp = w_pos[i], wn = w_neg[i];
  // Where the water side is known, the land side is not searched: it stays at 0
  // during the search (so that it does not hold the bound up) and gets the water
  // side's width after it, so that every point near the sample reads that.
  const int water_side = water[chain[i]];
  if (water_side > 0) wn = 0;
  if (water_side < 0) wp = 0;
  // Whether point j at squared distance d2 counts at all (not the same coast point,
  // not this bank's neighbour).
  const auto counts = [&](std::uint32_t j, double d2) {
    if (d2 == 0) return false;  // the same coast point in two pieces
    if (chain[j] == chain[i]) {
      double along = std::fabs(s[j] - s[i]);
      if (closed[chain[i]]) along = std::min(along, length[chain[i]] - along);
      if (along <= kNeighbourRatio * std::sqrt(d2)) return false;
    }
    return true;
  };
  // The search's widths are only ever lowered to a width some point gives, so the
  // final ones are the least over every point that counts (within the cap). A point
  // that counts and gives w_seed bounds that least from above: the cells are pruned
  // against the smaller of the running width and w_seed (1 + 1e-9), which is still
  // above the least one, so the point giving it is still visited and the answer is
  // the same bits (the point's own width comes from the search, never the seed's).
  // The seed's d2 is the tree's (field/near_tree.h: the same expression on the same
  // coordinates), so it counts exactly when the search would count it.
  double sp = cap, sn = cap;
  for (const std::uint32_t j : {seed.pos, seed.neg}) {
    if (j == kNoWitness || j == i) continue;
    const Vec3 dv = pts[j] - p;
    const double d2 = norm2(dv);
    if (!(d2 < cap * cap) || !counts(j, d2)) continue;
    const double dm = dot(dv, normal);
    constexpr double kSeedMargin = 1 + 1e-9;
    if (normal == Vec3{0, 0, 0}) {
      sp = std::min(sp, std::sqrt(d2) * kSeedMargin);
      sn = sp;
    } else if (dm > 0) {
      sp = std::min(sp, d2 / dm * kSeedMargin);
    } else if (dm < 0) {
      sn = std::min(sn, d2 / -dm * kSeedMargin);
    }
  }
  std::uint32_t jp = kNoWitness, jn = kNoWitness;
  const auto visit = [&](std::uint32_t j, double d2) -> double {
    if (counts(j, d2)) {
      const double d = std::sqrt(d2);
      const double dm = dot(pts[j] - p, normal);
      if (normal == Vec3{0, 0, 0}) {  // no tangent: the nearest other piece, either side
        if (d < wp) wp = d, jp = j;
        if (d < wn) wn = d, jn = j;
      } else if (dm > 0) {
        if (d2 / dm < wp) wp = d2 / dm, jp = j;
      } else if (dm < 0) {
        if (d2 / -dm < wn) wn = d2 / -dm, jn = j;
      }
    }
    const double b = std::max(std::min(wp, sp), std::min(wn, sn));
    return b * b;
  };
  // A point lowers wp only inside the ball tangent at p on side +m of diameter wp (the
  // picture: |d|^2 < wp (d . m)), centred at p + m wp / 2; wn likewise on side -m. A cell
  // whose box is farther from both balls than their radii holds none, and is skipped:
  // the widths are the same, from fewer points (the ball around p of radius
  // max(wp, wn) that bounds the visit holds every coast point near p, most of them on
  // this bank). The margins, relative 1e-6 and 1e-9 of the coordinates, are far above
  // the rounding of d2 / dm and of the centres (about 1e-16 of the coordinates).
  const double slack = 1e-9 * (norm(p) + cap);
  const auto may_hold = [&](const auto& box_dist2) {
    if (normal == Vec3{0, 0, 0}) return true;
    for (const double sign : {1.0, -1.0}) {
      const double w = sign > 0 ? std::min(wp, sp) : std::min(wn, sn);
      if (!(w > 0)) continue;
      const double r = 0.5 * w * (1 + 1e-6) + slack;
      if (box_dist2(p + (sign * 0.5 * w) * normal) <= r * r) return true;
    }
    return false;
  };
  const double start = std::max(std::min(wp, sp), std::min(wn, sn));
  tree->visit_within(p, std::min(cap * cap, start * start * (1 + 1e-9)), visit, may_hold);
  if (water_side > 0) wn = wp;
  if (water_side < 0) wp = wn;
  w_pos[i] = wp;
  w_neg[i] = wn;
  seed = {jp, jn};
}

ChannelWidths::ChannelWidths(std::vector<CoastChain> chains, double cap, int threads, bool seeded)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.cap = cap;
  std::size_t total = 0;
  for (const CoastChain& c : chains) total += c.points.size();
  m.own.reserve(total);
  m.chain.reserve(total);
  m.s.reserve(total);
  m.prev.reserve(total);
  m.next.reserve(total);
  for (const CoastChain& c : chains) {
    if (c.points.empty()) continue;
    const auto first = static_cast<std::uint32_t>(m.own.size());
    const auto id = static_cast<std::uint32_t>(m.length.size());
    const std::size_t n = c.points.size();
    double arc = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) arc += norm(c.points[k] - c.points[k - 1]);
      m.own.push_back(c.points[k]);
      m.chain.push_back(id);
      m.s.push_back(arc);
      const bool wrap = c.closed && n > 2;
      const auto at = [&](std::size_t q) { return first + static_cast<std::uint32_t>(q); };
      m.prev.push_back(k > 0 ? at(k - 1) : wrap ? at(n - 1) : at(k));
      m.next.push_back(k + 1 < n ? at(k + 1) : wrap ? at(0) : at(k));
    }
    const bool wrap = c.closed && n > 2;
    m.length.push_back(wrap ? arc + norm(c.points.front() - c.points.back()) : arc);
    m.closed.push_back(wrap ? 1 : 0);
    m.water.push_back(c.water_side);
  }
  // The chains' own copies of the points are not needed any more.
  std::vector<CoastChain>().swap(chains);
  m.pts = m.own;
  const std::size_t n = m.pts.size();
  // The surface's normal (Impl::side): a flat model's plane (z constant), else the
  // sphere's radial direction.
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin, ext = 0;
  for (const Vec3& p : m.pts) {
    zmin = std::min(zmin, p.z), zmax = std::max(zmax, p.z);
    ext = std::max({ext, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }
  m.flat = n == 0 || zmax - zmin <= 1e-12 * std::max(ext, 1e-300);
  if (!(m.cap > 0)) m.cap = 0;
  m.w_pos.assign(n, m.cap);
  m.w_neg.assign(n, m.cap);
  if (n == 0 || m.cap == 0) return;
  KnnOptions tree_options;
  tree_options.threads = resolve_thread_count(threads);
  m.tree = std::make_unique<KdTree>(std::move(m.own), tree_options);
  m.pts = m.tree->points();
  std::vector<Vec3>().swap(m.own);
  // Each sample's search reads the tree and writes only its own widths: samples are
  // independent, so chunks of them run on `threads` threads with the same result.
  // The seed is the chunk's previous sample's (none at a chunk's start).
  constexpr std::size_t kSamplesPerChunk = 2048;
  const int workers = resolve_thread_count(threads);
  parallel_for_chunks(workers, n, kSamplesPerChunk, [&](std::size_t begin, std::size_t end) {
    Witnesses seed;
    for (std::size_t i = begin; i < end; ++i) {
      if (!seeded) seed = {};
      m.search(i, seed);
    }
  });
  std::vector<std::uint32_t>().swap(m.chain);
  std::vector<double>().swap(m.s);
  std::vector<double>().swap(m.length);
  std::vector<char>().swap(m.closed);
  std::vector<int>().swap(m.water);
  // Each sample's least width and spacing on the threads too (each written by its own
  // index): serial, they and the grid's sorts were a third of the set-up on the world's coasts.
  std::vector<double> least(n), gaps(n);
  constexpr std::size_t kChunk = std::size_t{1} << 15;
  parallel_for_chunks(workers, n, kChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      least[i] = std::min({m.w_pos[i], m.w_neg[i], m.w_pos[m.prev[i]], m.w_neg[m.prev[i]], m.w_pos[m.next[i]],
                           m.w_neg[m.next[i]]});
      gaps[i] = m.spacing(static_cast<std::uint32_t>(i));
    }
  });
  // Level-0 cells of about the median spacing: finer cells would only hold one sample.
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(n / 2), gaps.end());
  m.narrowest = std::make_unique<MinGrid>(m.pts, least, gaps[n / 2], workers);
}

ChannelWidths::~ChannelWidths() = default;

std::size_t ChannelWidths::samples() const { return impl_->pts.size(); }

std::pair<double, double> ChannelWidths::sample_widths(std::size_t i) const {
  return {impl_->w_pos.at(i), impl_->w_neg.at(i)};
}

void ChannelWidths::width(std::span<const Vec3> pts, std::span<double> w) const {
  const double all = impl_->cap;
  width_within(pts, std::span<const double>(&all, 1), w);
}

void ChannelWidths::width_within(std::span<const Vec3> pts, std::span<const double> max_width,
                                 std::span<double> w) const {
  const Impl& m = *impl_;
  if (!m.tree) {
    std::fill(w.begin(), w.end(), m.cap);
    return;
  }
  // In pieces whose scratch lives on the stack (field/batch_pieces.h).
  for_each_piece(pts.size(), [&](std::size_t from, std::size_t n) {
    width_piece(pts.subspan(from, n), max_width.size() <= 1 ? max_width : max_width.subspan(from, n),
                w.subspan(from, n));
  });
}

void ChannelWidths::width_piece(std::span<const Vec3> pts, std::span<const double> max_width,
                                std::span<double> w) const {
  const Impl& m = *impl_;
  // Farther than max_width / 2 from the coast the water is wider than that. Not
  // initialised: each array's first pts.size() (radius: max_width.size()) are written.
  double radius[kBatchPiece], dist[kBatchPiece];
  std::uint32_t index[kBatchPiece];
  for (std::size_t i = 0; i < max_width.size(); ++i) radius[i] = 0.5 * std::min(max_width[i], m.cap);
  m.tree->nearest_within(pts, std::span<const double>(radius, max_width.size()), std::span<double>(dist, pts.size()),
                         std::span<std::uint32_t>(index, pts.size()));
  for (std::size_t k = 0; k < pts.size(); ++k) {
    std::uint32_t i = index[k];
    const Vec3& x = pts[k];
    if (i >= m.pts.size()) {  // far (or a non-finite point: NaN)
      w[k] = std::isnan(dist[k]) ? dist[k] : m.cap;
      continue;
    }
    // Linear along the coast segment the point projects onto, next side first.
    double value = m.width_at(i, x);
    for (const std::uint32_t j : {m.next[i], m.prev[i]}) {
      if (j == i) continue;
      const Vec3 e = m.pts[j] - m.pts[i];
      const double e2 = norm2(e);
      const double u = e2 > 0 ? dot(x - m.pts[i], e) / e2 : 0;
      if (u > 0 && u <= 1) {
        value = (1 - u) * value + u * m.width_at(j, x);
        break;
      }
    }
    // The ball of radius dist around x holds no coast: the water is at least twice
    // that wide (also where the samples are too sparse to see it).
    w[k] = std::min(std::max(value, 2 * dist[k]), m.cap);
  }
}

bool ChannelWidths::certainly_at_least(const Vec3& x, double max_width) const {
  const Impl& m = *impl_;
  if (!m.narrowest) return false;
  // width_within finds the nearest sample within r = min(max_width, cap) / 2 and reads
  // at least the smallest width the grid holds for it (interpolation between two
  // widths stays above the smaller one up to rounding, hence the margin); without
  // a sample that near it reads the cap.
  const double wanted = std::min(max_width, m.cap);
  constexpr double kRounding = 1e-9;
  return m.narrowest->at_least(x, 0.5 * wanted, wanted * (1 + kRounding));
}

ChannelWidthField::ChannelWidthField(std::vector<CoastChain> chains, const ChannelWidthOptions& o, double cap)
    : widths_(std::move(chains), cap, o.threads), o_(o), cap_(cap) {}

double ChannelWidthField::size_of(double w) const {
  // A width that reached the search cap is "wide": no constraint.
  const double size = w >= cap_ ? kMaxLc : w / o_.elements_across;
  return std::clamp(size, o_.size_min, o_.size_max);
}

void ChannelWidthField::eval(std::span<const Vec3> pts, std::span<double> h) const {
  widths_.width(pts, h);
  for (double& v : h) v = size_of(v);
}

void ChannelWidthField::lower(std::span<const Vec3> pts, std::span<double> h) const {
  // Only a width below N h can lower h (none at all where h <= SizeMin; any where
  // SizeMax is below h). Past the limit width_within returns a width >= N h, whose
  // size is >= h: the min below leaves h as it is, as a full evaluation would.
  // Where h <= SizeMax and the grid of smallest widths shows none below N h within
  // reach, that width is >= min(N h, cap), whose size is >= h: no search needed.
  for_each_piece(pts.size(),
                 [&](std::size_t from, std::size_t n) { lower_piece(pts.subspan(from, n), h.subspan(from, n)); });
}

void ChannelWidthField::lower_piece(std::span<const Vec3> pts, std::span<double> h) const {
  // Not initialised: the first `count` of each are written.
  std::uint32_t which[kBatchPiece];
  PiecePoints at;
  double limit[kBatchPiece], w[kBatchPiece];
  std::size_t count = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!(h[i] > o_.size_min)) continue;
    const bool capped = o_.size_max < h[i];
    const double lim = capped ? cap_ : o_.elements_across * h[i];
    if (!capped && widths_.certainly_at_least(pts[i], lim)) continue;
    which[count] = static_cast<std::uint32_t>(i);
    at.p[count] = pts[i];
    limit[count] = lim;
    ++count;
  }
  if (count == 0) return;
  widths_.width_within(std::span<const Vec3>(at.p, count), std::span<const double>(limit, count),
                       std::span<double>(w, count));
  for (std::size_t k = 0; k < count; ++k) h[which[k]] = std::min(h[which[k]], size_of(w[k]));
}

namespace {

// The search radius: N * SizeMax, or without SizeMax a multiple of the median
// sample spacing (wider channels are not what this field is for, and an
// unbounded search would visit every sample of a world coastline).
double search_cap(const std::vector<CoastChain>& chains, const ChannelWidthOptions& o) {
  if (o.size_max < kMaxLc) return o.elements_across * o.size_max;
  std::vector<double> gaps;
  for (const CoastChain& c : chains)
    for (std::size_t k = 1; k < c.points.size(); ++k) gaps.push_back(norm(c.points[k] - c.points[k - 1]));
  if (gaps.empty()) return 0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
  return kDefaultCapSpacings * gaps[gaps.size() / 2];
}

FieldPtr make_channel_width(const BuildInputs& in) {
  const Options& o = in.opts;
  ChannelWidthOptions opts;
  opts.elements_across = o.number("ElementsAcross");
  opts.size_min = o.number("SizeMin");
  opts.size_max = o.number("SizeMax");
  opts.threads = in.ctx.threads;
  if (!(opts.elements_across >= 1)) in.bad("ElementsAcross", "must be at least 1");
  if (!(opts.size_min >= 0)) in.bad("SizeMin", "must be positive or zero");
  if (!(opts.size_max > 0) || opts.size_max < opts.size_min) in.bad("SizeMax", "must be positive and at least SizeMin");
  const int coast = static_cast<int>(o.number("CoastlineId"));
  std::vector<int> curves;
  for (double v : o.list("CurvesList")) curves.push_back(static_cast<int>(v));
  if (coast != 0 && !curves.empty()) in.bad("CoastlineId", "give either CoastlineId or CurvesList, not both");
  if (coast != 0) {
    std::optional<std::vector<int>> c;
    if (in.ctx.coastline_curves) c = in.ctx.coastline_curves(coast);
    if (!c) in.bad("CoastlineId", fmt::format("Coastline[{}] does not exist or is not imported yet", coast));
    curves = std::move(*c);
  }
  if (curves.empty()) in.bad("CurvesList", "no curves: set CoastlineId or CurvesList");
  std::optional<std::vector<CoastChain>> chains;
  if (in.ctx.curve_chains) chains = in.ctx.curve_chains(curves);
  if (!chains) in.bad(coast != 0 ? "CoastlineId" : "CurvesList", "a listed curve does not exist");
  return make_channel_width_field(std::move(*chains), opts);
}

}  // namespace

std::shared_ptr<const ChannelWidthField> make_channel_width_field(std::vector<CoastChain> chains,
                                                                  const ChannelWidthOptions& opts) {
  for (const CoastChain& c : chains)
    for (const Vec3& p : c.points)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        FieldError e(FieldErrc::BadValue, "ChannelWidth: a coast sample is not finite");
        e.bad = BadValueWhat::CoastSample;
        throw e;
      }
  if (!(opts.elements_across >= 1)) {
    FieldError e(FieldErrc::BadValue, "ChannelWidth: ElementsAcross must be at least 1");
    e.bad = BadValueWhat::ElementsAcross;
    throw e;
  }
  const double cap = search_cap(chains, opts);
  return std::make_shared<ChannelWidthField>(std::move(chains), opts, cap);
}

KindSpec channel_width_kind() {
  return {"ChannelWidth",
          "Local width w of the water (diameter of the largest empty ball tangent to the coast: the "
          "medial-axis feature size) divided by ElementsAcross, clamped to [SizeMin, SizeMax]. Samples "
          "of one ring face each other only when the way round is more than pi/2 times their distance. "
          "Built once with a k-d tree; one nearest-sample query per point.",
          {
              num_opt("CoastlineId", 0, "the coastline whose curves are the coast (Coastline[n], imported)"),
              list_opt("CurvesList", "coast curve tags (chained into rings through the curve loops)"),
              num_opt("ElementsAcross", 2, "elements across a channel (at least 1)"),
              num_opt("SizeMin", 0, "smallest size returned"),
              num_opt("SizeMax", kMaxLc,
                      "largest size returned; widths up to ElementsAcross * SizeMax are searched "
                      "(without it: 64 median coast sample spacings)"),
          },
          make_channel_width};
}

}  // namespace sm::field
