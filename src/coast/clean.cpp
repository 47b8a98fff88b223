// Ring cleaning: a single stack pass per ring removes duplicates and spikes (a spike
// uncovered by removing another is caught by the same stack), then the closing seam of a
// closed ring is checked the same way until nothing changes.
#include "coast/clean.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cmath>

#include <fmt/format.h>

#include "base/huge_alloc.h"
#include "base/parallel.h"

namespace sm::coast {

std::size_t CleanReport::count(CleanAction a) const {
  std::size_t n = 0;
  for (const auto& e : entries) n += e.action == a;
  return n;
}

std::string CleanReport::summary() const {
  return fmt::format(
      "{} duplicate vertices, {} spikes, {} south-pole vertices removed; {} degenerate rings dropped; "
      "{} rings sharing an edge merged",
      count(CleanAction::Duplicate), count(CleanAction::Spike), count(CleanAction::PoleVertex),
      count(CleanAction::DegenerateRing), count(CleanAction::MergedRings));
}

namespace {

void clean_ring(Ring& r, CleanReport& rep) {
  auto note = [&](CleanAction a, geo::LonLat p) { rep.entries.push_back({a, r.record, r.id, p}); };
  // Natural Earth closes Antarctica along the South Pole: those vertices are the singular
  // point of the projection and carry no shoreline.
  if (r.closed && std::any_of(r.pts.begin(), r.pts.end(), [](geo::LonLat p) { return p.lat == -90.0; })) {
    std::vector<geo::LonLat> kept;
    kept.reserve(r.pts.size());
    for (auto p : r.pts) {
      if (p.lat == -90.0)
        note(CleanAction::PoleVertex, p);
      else
        kept.push_back(p);
    }
    r.pts = std::move(kept);
    r.wraps_pole = longitude_winding(r.pts) != 0.0;
  }
  // The stack lives in the front of the ring itself (it never grows past the point read),
  // so a clean ring costs no copy.
  std::vector<geo::LonLat>& pts = r.pts;
  std::size_t top = 0;   // stack: pts[0, top)
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const geo::LonLat p = pts[i];
    if (top > 0 && same_point(pts[top - 1], p)) {
      note(CleanAction::Duplicate, p);
      continue;
    }
    if (top >= 2 && same_point(pts[top - 2], p)) {
      note(CleanAction::Spike, pts[top - 1]);
      --top;
      continue;
    }
    pts[top++] = p;
  }
  pts.resize(top);
  std::vector<geo::LonLat>& out = pts;
  if (r.closed) {
    bool changed = true;
    while (changed && out.size() >= 3) {
      changed = false;
      const std::size_t n = out.size();
      if (same_point(out[n - 1], out[0])) {
        note(CleanAction::Duplicate, out[n - 1]);
        out.pop_back();
        changed = true;
      } else if (same_point(out[n - 2], out[0])) {        // spike at out[n-1]
        note(CleanAction::Spike, out[n - 1]);
        out.resize(n - 2);
        changed = true;
      } else if (same_point(out[n - 1], out[1])) {        // spike at out[0]
        note(CleanAction::Spike, out[0]);
        out.erase(out.begin(), out.begin() + 2);
        changed = true;
      }
    }
  }
}

// Rings cleaned on the threads in fixed chunks of kCleanChunk, each chunk's report
// written to its own part (then: per-ring work of one chunk, `after(k, part)`); the parts
// are joined in ring order, so the entries are one thread's for every count.
constexpr std::size_t kCleanChunk = 256;
template <class After>
void clean_in_order(std::vector<Ring>& rings, CleanReport& rep, int threads, After after) {
  const std::size_t n = rings.size();
  std::vector<CleanReport> parts((n + kCleanChunk - 1) / kCleanChunk);
  parallel_for_chunks(resolve_thread_count(threads), n, kCleanChunk, [&](std::size_t begin, std::size_t end) {
    CleanReport& part = parts[begin / kCleanChunk];
    for (std::size_t k = begin; k < end; ++k) {
      clean_ring(rings[k], part);
      after(k, part);
    }
  });
  for (CleanReport& p : parts) rep.entries.insert(rep.entries.end(), p.entries.begin(), p.entries.end());
}

}  // namespace

CleanReport clean(Coastline& c, int threads) {
  // Rings are cleaned independently, in chunks whose reports are joined in ring order:
  // the same entries for every thread count.
  const std::size_t n = c.rings.size();
  std::vector<char> degenerate(n, 0);
  CleanReport rep;
  clean_in_order(c.rings, rep, threads, [&](std::size_t k, CleanReport& part) {
    const Ring& r = c.rings[k];
    const std::size_t need = r.closed ? 3 : 2;
    if (r.pts.size() < need) {
      part.entries.push_back({CleanAction::DegenerateRing, r.record, r.id,
                              r.pts.empty() ? geo::LonLat{} : r.pts.front()});
      degenerate[k] = 1;
    }
  });
  std::size_t top = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (!degenerate[k]) {
      if (top != k) c.rings[top] = std::move(c.rings[k]);
      ++top;
    }
  c.rings.erase(c.rings.begin() + static_cast<std::ptrdiff_t>(top), c.rings.end());
  return rep;
}

namespace {

// A point with its longitude folded into [0,360) (poles: lon 0), comparable exactly.
struct Key {
  double lon, lat;
  friend bool operator<(Key a, Key b) { return a.lon != b.lon ? a.lon < b.lon : a.lat < b.lat; }
  friend bool operator==(Key a, Key b) { return a.lon == b.lon && a.lat == b.lat; }
};

Key key(geo::LonLat p) {
  if (std::abs(p.lat) == 90.0) return {0.0, p.lat};
  // fmod(x, 360) is x itself for |x| < 360, the usual case: the test spares the division.
  double l = p.lon > -360.0 && p.lon < 360.0 ? p.lon : std::fmod(p.lon, 360.0);
  if (l < 0) l += 360.0;
  // Snap to 1e-9 degree (0.1 mm): Natural Earth writes the dateline as 180.00000000000014.
  l = std::round(l * 1e9) * 1e-9;
  if (l >= 360.0) l -= 360.0;
  return {l, p.lat};
}

struct Edge {
  Key a, b;
  std::uint32_t ring, index;
  friend bool operator<(const Edge& x, const Edge& y) {
    if (!(x.a == y.a)) return x.a < y.a;
    if (!(x.b == y.b)) return x.b < y.b;
    return x.ring != y.ring ? x.ring < y.ring : x.index < y.index;
  }
};

// An edge shared by two rings has both its end points in two rings. Every vertex key is
// hashed into a table of at least 8 slots per vertex: a key met a second time (in the
// same ring or another) marks its slot "repeated" in a second table, and only edges
// between two marked keys are kept, sorted. A true repeat is always marked; a
// collision only adds a candidate that finds no partner, so the merges are exactly those
// of the sort of every edge, at a few per cent of its memory (the whole GSHHG: 9.5 million
// edges of 40 bytes before; a 32 MB table and the candidates now).
std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  std::uint64_t h = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return h;
}
std::uint64_t key_hash(Key k) {
  // +0.0 folds -0.0 onto 0.0, which Key's == treats as equal.
  return mix(std::bit_cast<std::uint64_t>(k.lon + 0.0), std::bit_cast<std::uint64_t>(k.lat + 0.0));
}

// A key's slot: the table is cut into blocks of 1024 slots of two bits (four cache
// lines side by side, which the hardware's adjacent-line prefetch reads together), the
// block chosen by the key's cell of a 1/16 degree grid and the slot within it by the
// key's hash. A ring's consecutive vertices mostly share a cell, so the passes over the
// rings touch one block after another: a slot anywhere in the table was a cache miss
// per vertex and pass (two passes over the 9.5 million vertices of the whole GSHHG were
// most of the cleaning's time). Cells are hashed onto blocks, so a block holds a few cells
// and about the table's mean load; equal keys lie in one cell, so the marks stay exact.
// Finer cells (1/128 degree, blocks of one line) changed block every two or three
// vertices of the full GSHHG: 2.0 s of CPU for the two passes, against 1.0 s here with
// three times the candidates (310,000, whose sort costs 0.05 s); coarser cells than
// these fill a block past the point where collisions multiply the candidates.
constexpr std::size_t kBlockSlots = 1024;
constexpr double kCellsPerDegree = 16;
std::size_t slot_of(Key k, std::size_t slots) {
  // Both are >= 0 (a key's longitude is in [0, 360)): the cast is the floor, without a
  // call to floor() (no rounding instruction in the baseline x86-64 the build targets).
  const auto cx = static_cast<std::int64_t>(k.lon * kCellsPerDegree);
  const auto cy = static_cast<std::int64_t>((k.lat + 90.0) * kCellsPerDegree);
  const std::uint64_t block = mix(static_cast<std::uint64_t>(cx), static_cast<std::uint64_t>(cy));
  const std::size_t blocks = slots / kBlockSlots;
  return static_cast<std::size_t>(block & (blocks - 1)) * kBlockSlots +
         static_cast<std::size_t>(key_hash(k) & (kBlockSlots - 1));
}

// The vertices of the rings the merge looks at, numbered one after another ring by ring:
// the threads take fixed runs of that numbering, so a continent is shared among them.
struct FlatRings {
  std::vector<std::uint32_t> ring;       // counted rings, in order
  std::vector<std::size_t> first;        // per counted ring: its first vertex; then the total

  explicit FlatRings(const Coastline& c) {
    first.push_back(0);
    for (std::uint32_t r = 0; r < c.rings.size(); ++r)
      if (c.rings[r].closed && !c.rings[r].wraps_pole && !c.rings[r].pts.empty()) {
        ring.push_back(r);
        first.push_back(first.back() + c.rings[r].pts.size());
      }
  }
  std::size_t vertices() const { return first.back(); }
  // Calls f(ring, i) for the vertices [begin, end) of the numbering, in order.
  template <class F>
  void each(std::size_t begin, std::size_t end, F&& f) const {
    auto k = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), begin) - first.begin()) - 1;
    for (std::size_t v = begin; v < end; ++k) {
      const std::size_t stop = std::min(end, first[k + 1]);
      for (; v < stop; ++v) f(ring[k], static_cast<std::uint32_t>(v - first[k]));
    }
  }
};

std::vector<Edge> candidate_edges(const Coastline& c, int threads) {
  const FlatRings flat(c);
  const std::size_t vertices = flat.vertices();
  // Two bits a slot side by side (seen, repeated): one memory access a vertex. Several
  // threads set them with atomic ORs: a slot hit twice ends "repeated" whichever thread came
  // first. One thread sets the same bits with plain ORs (an atomic OR whose old value is read
  // is a compare-and-swap loop).
  std::size_t slots = 2 * kBlockSlots;   // a whole number of blocks, at least two
  while (slots < 8 * vertices) slots *= 2;
  std::vector<std::uint64_t, HugeAlloc<std::uint64_t>> table(slots / 32, 0);   // 32 MiB on the whole GSHHG
  auto slot = [&](Key k) { return slot_of(k, slots); };
  auto repeated = [&](std::size_t i) { return (table[i / 32] >> (2 * (i % 32) + 1)) & 1u; };
  auto point = [&](std::uint32_t r, std::uint32_t i) { return c.rings[r].pts[i]; };
  constexpr std::size_t kChunk = std::size_t{1} << 16;   // vertices
  parallel_for_chunks(threads, vertices, kChunk, [&](std::size_t begin, std::size_t end) {
    flat.each(begin, end, [&](std::uint32_t r, std::uint32_t i) {
      const std::size_t at = slot(key(point(r, i)));
      const unsigned b = 2 * static_cast<unsigned>(at % 32);
      if (threads <= 1) {
        std::uint64_t& plain = table[at / 32];
        plain |= (((plain >> b) & 1u) << (b + 1)) | (std::uint64_t{1} << b);
        return;
      }
      std::atomic_ref<std::uint64_t> w(table[at / 32]);
      const std::uint64_t before = w.fetch_or(std::uint64_t{1} << b, std::memory_order_relaxed);
      if ((before >> b) & 1u) w.fetch_or(std::uint64_t{1} << (b + 1), std::memory_order_relaxed);
    });
  });
  // The edge leaving each vertex, kept when both its ends are marked; the runs' lists are
  // joined in order (the sort below orders them fully in any case).
  std::vector<std::vector<Edge>> parts((vertices + kChunk - 1) / kChunk);
  parallel_for_chunks(threads, vertices, kChunk, [&](std::size_t begin, std::size_t end) {
    std::vector<Edge>& out = parts[begin / kChunk];
    flat.each(begin, end, [&](std::uint32_t r, std::uint32_t i) {
      const auto n = static_cast<std::uint32_t>(c.rings[r].pts.size());
      const Key a = key(point(r, i));
      if (!repeated(slot(a))) return;
      const Key b = key(point(r, (i + 1) % n));
      if (repeated(slot(b))) out.push_back({a, b, r, i});
    });
  });
  std::vector<Edge> edges;
  for (const std::vector<Edge>& p : parts) edges.insert(edges.end(), p.begin(), p.end());
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace

// Polygons cut at the dateline do not always carry the same vertices along the cut:
// every vertex lying on lon +-180 is inserted into the dateline edges of the other rings
// that pass over it, so that the shared runs become identical edges.
// The search for those vertices looks at every source point: the rings go to the threads
// in fixed chunks, each chunk's latitudes joined in ring order (the list one thread makes).
void split_dateline_edges(Coastline& c, int threads) {
  constexpr std::size_t kChunk = 256;   // rings
  std::vector<char> on_dateline(c.rings.size(), 0);
  std::vector<std::vector<double>> found((c.rings.size() + kChunk - 1) / kChunk);
  parallel_for_chunks(resolve_thread_count(threads), c.rings.size(), kChunk, [&](std::size_t b, std::size_t e) {
    std::vector<double>& part = found[b / kChunk];
    for (std::size_t k = b; k < e; ++k) {
      const Ring& r = c.rings[k];
      if (r.closed && !r.wraps_pole)
        for (auto p : r.pts)
          if (key(p).lon == 180.0) {
            part.push_back(p.lat);
            on_dateline[k] = 1;
          }
    }
  });
  std::vector<double> lats;
  for (const std::vector<double>& part : found) lats.insert(lats.end(), part.begin(), part.end());
  if (lats.empty()) return;
  std::sort(lats.begin(), lats.end());
  lats.erase(std::unique(lats.begin(), lats.end()), lats.end());
  for (std::size_t k = 0; k < c.rings.size(); ++k) {
    Ring& r = c.rings[k];
    if (!on_dateline[k]) continue;   // no vertex on the dateline: no dateline edge either
    const std::size_t n = r.pts.size();
    std::vector<geo::LonLat> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const geo::LonLat a = r.pts[i], b = r.pts[(i + 1) % n];
      out.push_back(a);
      if (key(a).lon != 180.0 || key(b).lon != 180.0 || std::abs(a.lon - b.lon) > 1e-6) continue;
      const double lo = std::min(a.lat, b.lat), hi = std::max(a.lat, b.lat);
      auto first = std::upper_bound(lats.begin(), lats.end(), lo);
      auto last = std::lower_bound(lats.begin(), lats.end(), hi);
      if (first >= last) continue;
      if (a.lat < b.lat)
        for (auto it = first; it != last; ++it) out.push_back({a.lon, *it});
      else
        for (auto it = last; it != first; --it) out.push_back({a.lon, *(it - 1)});
    }
    r.pts = std::move(out);
  }
}

void merge_touching_rings(Coastline& c, CleanReport& rep, int threads) {
  split_dateline_edges(c, threads);
  for (;;) {
    const std::vector<Edge> edges = candidate_edges(c, resolve_thread_count(threads));
    std::vector<char> busy(c.rings.size(), 0), dead(c.rings.size(), 0);
    bool merged = false;
    for (const Edge& e : edges) {
      if (busy[e.ring]) continue;
      // The same edge run the other way in another ring of the same level.
      auto it = std::lower_bound(edges.begin(), edges.end(), Edge{e.b, e.a, 0, 0});
      for (; it != edges.end() && it->a == e.b && it->b == e.a; ++it) {
        if (it->ring == e.ring || busy[it->ring] || c.rings[it->ring].level != c.rings[e.ring].level) continue;
        Ring& A = c.rings[e.ring];
        Ring& B = c.rings[it->ring];
        // A: ... p=A[i] -> q=A[i+1] ...; B: ... q=B[j] -> p=B[j+1] ...
        // Merged: A from q round to p, then B from after p round to before q.
        const std::size_t na = A.pts.size(), nb = B.pts.size();
        std::vector<geo::LonLat> pts;
        pts.reserve(na + nb);
        for (std::size_t k = 0; k < na; ++k) pts.push_back(A.pts[(e.index + 1 + k) % na]);
        for (std::size_t k = 2; k < nb; ++k) pts.push_back(B.pts[(it->index + k) % nb]);
        rep.entries.push_back({CleanAction::MergedRings, B.record, B.id, A.pts[e.index]});
        A.pts = std::move(pts);
        unwrap_longitudes(A.pts);
        A.area_km2 = A.area_km2 + B.area_km2;
        busy[e.ring] = busy[it->ring] = 1;
        dead[it->ring] = 1;
        merged = true;
        break;
      }
    }
    if (!merged) return;
    std::vector<Ring> kept;
    for (std::size_t r = 0; r < c.rings.size(); ++r)
      if (!dead[r]) kept.push_back(std::move(c.rings[r]));
    c.rings = std::move(kept);
    // The rest of a shared run now folds back on itself: the spike pass removes it (every
    // ring again, on the threads: a pass over all the source points).
    clean_in_order(c.rings, rep, threads, [](std::size_t, CleanReport&) {});
  }
}

}  // namespace sm::coast
