// The blocked quality optimisation (optimize_blocks.h): blocks claimed round the bad
// triangles, each optimised as a store of its own on the threads, written back into its
// own slots, the borders linked again, then a serial pass round the borders.
#include "mesh/modify/optimize_blocks.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

#include "base/check.h"
#include "base/parallel.h"
#include "exact/quality.h"
#include "mesh/partition.h"

namespace sm {
namespace {

constexpr std::uint32_t kMaxBlocks = 1024;
// Rings of vertex stars claimed round a block's bad triangles: the stars of their corners
// (the moves' and swaps' reach), then one more for the cascades.
constexpr int kBlockRings = 2;
constexpr std::uint32_t kUnclaimed = 0xffffffffu;

// A side of a block's store whose twin lies outside the block: its ends (global ids) and,
// when it is a border rather than a hull edge, the original twin.
struct BlockSide {
  std::uint32_t org, dest;
  Side side;  // the global side: its twin before (extraction) or the block's side now (write-back)
};

struct Block {
  std::vector<std::uint32_t> tris;      // owned slots, increasing
  std::uint32_t bad = 0;                // bad triangles the block was cut for
  std::vector<BlockSide> outer;            // at extraction: border sides and their outer twins
  std::vector<BlockSide> sides;            // after write-back: every hull side of the block's store
  std::vector<std::pair<std::uint32_t, Side>> border_out;  // out_side of its border vertices
  OptimizeStats st;
};

// part_count's options for blocks of `per_block` bad triangles.
PartitionOptions block_counts(std::uint32_t per_block) {
  PartitionOptions po;
  po.part_triangles = std::max<std::uint32_t>(per_block, 1);
  po.max_parts = kMaxBlocks;
  return po;
}

// Block b claims the unclaimed triangles round org(s), appending them to tris and grown.
void claim_fan(const TriangleStore& m, Side s, std::uint32_t b, std::vector<std::uint32_t>& owner,
               std::vector<std::uint32_t>& tris, std::vector<std::uint32_t>& grown) {
  const FanEnd end = for_each_fan_side(m, s, [&](Side x) {
    const std::uint32_t u = tri_of(x).value;
    if (owner[u] == kUnclaimed) owner[u] = b, tris.push_back(u), grown.push_back(u);
  });
  SM_ASSERT(end != FanEnd::Corrupt, "optimize_in_blocks: a vertex's fan does not close within the store");
}

// Cuts the bad triangles into blocks and lets each block, in order, claim its bad triangles
// and kBlockRings rings of stars round them: owner[t] names the block of slot t.
std::vector<Block> claim_blocks(const TriangleStore& m, const std::vector<BadTri>& bad,
                                std::uint32_t per_block, std::vector<std::uint32_t>& owner) {
  const std::uint32_t k = part_count(bad.size(), block_counts(per_block));
  std::vector<Vec2> centroid(bad.size());
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const TriId t{bad[i].t};
    centroid[i] = (m.pos(m.vertex(t, 0)) + m.pos(m.vertex(t, 1)) + m.pos(m.vertex(t, 2))) * (1.0 / 3);
  }
  const std::vector<double> weight(bad.size(), 1.0);
  const std::vector<std::uint32_t> part = bisect_parts(centroid, weight, k);
  std::vector<Block> blocks(k);
  std::vector<std::vector<std::uint32_t>> seeds(k);
  for (std::size_t i = 0; i < bad.size(); ++i) seeds[part[i]].push_back(bad[i].t), ++blocks[part[i]].bad;
  owner.assign(m.num_slots(), kUnclaimed);
  // walked[v] == b + 1: block b walked v's fan, which then holds no unclaimed triangle, so
  // a second walk (from another triangle of the front, or the next ring) would claim nothing.
  std::vector<std::uint32_t> walked(m.num_vertices(), 0);
  std::vector<std::uint32_t> front, grown;
  for (std::uint32_t b = 0; b < k; ++b) {
    std::vector<std::uint32_t>& tris = blocks[b].tris;
    front.clear();
    for (std::uint32_t t : seeds[b])
      if (owner[t] == kUnclaimed) owner[t] = b, tris.push_back(t), front.push_back(t);
    for (int ring = 0; ring < kBlockRings; ++ring) {
      grown.clear();
      for (std::uint32_t t : front)
        for (std::uint32_t e = 0; e < 3; ++e) {
          const Side s = side_of(TriId{t}, e);
          if (walked[m.corner[s.value].value] == b + 1) continue;
          walked[m.corner[s.value].value] = b + 1;
          claim_fan(m, s, b, owner, tris, grown);
        }
      front.swap(grown);
    }
    std::sort(tris.begin(), tris.end());
  }
  return blocks;
}

// border[v]: v is a corner of triangles of more than one block (or of a block and of no block).
std::vector<std::uint8_t> border_vertices(const TriangleStore& m, const std::vector<std::uint32_t>& owner) {
  std::vector<std::uint32_t> first(m.num_vertices(), kUnclaimed - 1);
  std::vector<std::uint8_t> border(m.num_vertices(), 0);
  for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
    if (!m.alive(tri_of(Side{s}))) continue;
    const std::uint32_t v = m.corner[s].value, o = owner[s / 3];
    if (first[v] == kUnclaimed - 1) first[v] = o;
    else if (first[v] != o) border[v] = 1;
  }
  return border;
}

// Scratch shared by the blocks on the threads, each writing only entries of its own:
// slot_local[t] for the triangles it owns, vertex_local[v] for its inner vertices (one that
// is no border vertex has all its triangles in one block). Lookups in them replace binary
// searches in the block's lists, which cost as much as the rest of the copy.
struct BlockMaps {
  std::vector<std::uint32_t> slot_local;    // per triangle slot: its index in its block
  std::vector<std::uint32_t> vertex_local;  // per vertex: kUnclaimed, or its local id
};

// Block b's triangles as a store of their own: vertices by increasing global id (verts),
// triangles in slot order, twins outside the block cut (recorded in blk.outer).
TriangleStore extract_block(const TriangleStore& m, std::uint32_t b, const std::vector<std::uint32_t>& owner,
                            const std::vector<std::uint8_t>& border, BlockMaps& maps, Block& blk,
                            std::vector<std::uint32_t>& verts) {
  const std::uint32_t n = static_cast<std::uint32_t>(blk.tris.size());
  // The inner vertices once each (the first sight marks them), the border ones sorted
  // apart (other blocks see them too), then both lists merged by global id.
  verts.clear();
  std::vector<std::uint32_t> shared;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t t = blk.tris[i];
    maps.slot_local[t] = i;
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t v = m.corner[3 * t + e].value;
      if (border[v]) {
        shared.push_back(v);
      } else if (maps.vertex_local[v] == kUnclaimed) {
        maps.vertex_local[v] = 0;
        verts.push_back(v);
      }
    }
  }
  std::sort(verts.begin(), verts.end());
  std::sort(shared.begin(), shared.end());
  shared.erase(std::unique(shared.begin(), shared.end()), shared.end());
  const std::size_t inner = verts.size();
  verts.insert(verts.end(), shared.begin(), shared.end());
  std::inplace_merge(verts.begin(), verts.begin() + static_cast<std::ptrdiff_t>(inner), verts.end());
  for (std::uint32_t j = 0; j < verts.size(); ++j)
    if (!border[verts[j]]) maps.vertex_local[verts[j]] = j;
  const auto local_vertex = [&](VertexId v) {
    if (!border[v.value]) return VertexId{maps.vertex_local[v.value]};
    return VertexId{static_cast<std::uint32_t>(std::lower_bound(verts.begin(), verts.end(), v.value) - verts.begin())};
  };
  TriangleStore sub;
  sub.xy.resize(verts.size());
  for (std::size_t j = 0; j < verts.size(); ++j) sub.xy[j] = m.xy[verts[j]];
  sub.corner.resize(3 * std::size_t{n});
  sub.twin.assign(3 * std::size_t{n}, Side{});
  sub.side_flags.resize(3 * std::size_t{n});
  sub.tri_flags.assign(n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s = side_of(TriId{blk.tris[i]}, e);
      sub.corner[3 * i + e] = local_vertex(m.corner[s.value]);
      sub.side_flags[3 * i + e] = m.side_flags[s.value];
      const Side o = m.twin[s.value];
      if (!o.valid()) continue;
      const std::uint32_t u = tri_of(o).value;
      if (owner[u] != b) {
        blk.outer.push_back({m.org(s).value, m.dest(s).value, o});
        continue;
      }
      sub.twin[3 * i + e] = Side{3 * maps.slot_local[u] + o.value % 3};
    }
  sub.rebuild_out_side();
  return sub;
}

// The block's store written into its own slots and inner vertices (border vertices do not
// move: their stars are cut); its hull sides and border vertices' out_side are recorded for
// the serial phase.
void write_back(TriangleStore& m, const TriangleStore& sub, const std::vector<std::uint32_t>& verts,
                const std::vector<std::uint8_t>& border, Block& blk) {
  const auto global_side = [&](Side ls) { return Side{3 * blk.tris[ls.value / 3] + ls.value % 3}; };
  for (std::uint32_t i = 0; i < blk.tris.size(); ++i)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side ls{3 * i + e};
      const Side s = global_side(ls);
      m.corner[s.value] = VertexId{verts[sub.corner[ls.value].value]};
      m.side_flags[s.value] = sub.side_flags[ls.value];
      const Side lo = sub.twin[ls.value];
      m.twin[s.value] = lo.valid() ? global_side(lo) : Side{};
      if (!lo.valid()) blk.sides.push_back({verts[sub.org(ls).value], verts[sub.dest(ls).value], s});
    }
  for (std::uint32_t j = 0; j < verts.size(); ++j) {
    const Side out = sub.out_side[j].valid() ? global_side(sub.out_side[j]) : Side{};
    if (border[verts[j]]) {
      blk.border_out.emplace_back(verts[j], out);
    } else {
      m.xy[verts[j]] = sub.xy[j];
      m.out_side[verts[j]] = out;
    }
  }
  const auto by_ends = [](const BlockSide& a, const BlockSide& c) { return std::tie(a.org, a.dest) < std::tie(c.org, c.dest); };
  std::sort(blk.sides.begin(), blk.sides.end(), by_ends);
}

// The block's side org -> dest now (its store keeps every hull edge).
Side side_now(const Block& blk, std::uint32_t org, std::uint32_t dest) {
  const BlockSide key{org, dest, Side{}};
  const auto it = std::lower_bound(blk.sides.begin(), blk.sides.end(), key, [](const BlockSide& a, const BlockSide& c) {
    return std::tie(a.org, a.dest) < std::tie(c.org, c.dest);
  });
  SM_ASSERT(it != blk.sides.end() && it->org == org && it->dest == dest, "a block lost a border edge");
  return it->side;
}

// The borders linked again (in block order): to an unclaimed triangle, whose sides did not
// move, or to the other block's side now; then the border vertices' out_side.
void link_blocks(TriangleStore& m, const std::vector<Block>& blocks, const std::vector<std::uint32_t>& owner) {
  for (const Block& blk : blocks)
    for (const BlockSide& o : blk.outer) {
      const Side s = side_now(blk, o.org, o.dest);
      const std::uint32_t other = owner[tri_of(o.side).value];
      const Side t = other == kUnclaimed ? o.side : side_now(blocks[other], o.dest, o.org);
      m.twin[s.value] = t;
      m.twin[t.value] = s;
    }
  for (const Block& blk : blocks)
    for (const auto& [v, out] : blk.border_out) m.out_side[v] = out;
}

// With an undo journal on the store (store_undo.h), everything the blocks and the linking
// will write is saved first, here on one thread (the journal is not shared by threads): the
// claimed slots, the corners of their triangles (inner ones move, border ones get a new
// out_side) and the unclaimed slots across their borders (their twins are linked again).
void journal_blocks(TriangleStore& m, const std::vector<Block>& blocks, const std::vector<std::uint32_t>& owner) {
  if (!m.undo_link.journal) return;
  for (const Block& blk : blocks)
    for (const std::uint32_t t : blk.tris)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side s = side_of(TriId{t}, e);
        m.will_change_tri(TriId{t});
        m.will_change_vertex(m.corner[s.value]);
        const Side o = m.twin[s.value];
        if (o.valid() && owner[tri_of(o).value] == kUnclaimed) m.will_change_tri_of(o);
      }
}

void add_counts(OptimizeStats& to, const OptimizeStats& s) {
  to.swaps += s.swaps, to.moves += s.moves, to.refused += s.refused, to.star_measures += s.star_measures;
  to.compound_tried += s.compound_tried, to.compound_pinned += s.compound_pinned;
  to.compound_repeated += s.compound_repeated;
  to.compound_valence_skipped += s.compound_valence_skipped;
  to.rounds = std::max(to.rounds, s.rounds);
}

}  // namespace

OptimizeStats optimize_in_blocks(TriangleStore& m, std::uint32_t fixed_count, const OptimizeOptions& opt) {
  SM_ASSERT(!opt.to_space && !opt.seeds, "optimize_in_blocks: unsupported options");
  OptimizeOptions serial = opt;
  serial.block_min_triangles = 0;
  const int threads = std::max(opt.threads, 1);
  std::vector<BadTri> bad;
  const double min_before = scan_plane_bad(m, opt.threshold, threads, nullptr, bad);
  if (bad.size() < 2 * std::uint64_t{std::max<std::uint32_t>(opt.block_bad, 1)}) return optimize_quality(m, fixed_count, serial);
  OptimizeStats st;
  st.bad_before = static_cast<std::uint32_t>(bad.size());
  st.min_before = min_before;
  std::vector<std::uint32_t> owner;
  std::vector<Block> blocks = claim_blocks(m, bad, opt.block_bad, owner);
  const std::vector<std::uint8_t> border = border_vertices(m, owner);
  BlockMaps maps{std::vector<std::uint32_t>(m.num_slots()), std::vector<std::uint32_t>(m.num_vertices(), kUnclaimed)};
  journal_blocks(m, blocks, owner);
  // The face's bank of sacrifices (optimize.h: max_share_loss) shared by the blocks as
  // their bad triangles are: no block may spend another's.
  const double bank = std::max(0.0, opt.max_share_loss) * m.num_triangles();
  parallel_for_chunks(threads, blocks.size(), 1, [&](std::size_t b, std::size_t) {
    Block& blk = blocks[b];
    std::vector<std::uint32_t> verts;
    TriangleStore sub = extract_block(m, static_cast<std::uint32_t>(b), owner, border, maps, blk, verts);
    OptimizeOptions bo = serial;
    bo.threads = 1;
    bo.max_share_loss = bank * blk.bad / double(bad.size()) / double(sub.num_triangles());
    const std::uint32_t fixed =
        static_cast<std::uint32_t>(std::lower_bound(verts.begin(), verts.end(), fixed_count) - verts.begin());
    blk.st = optimize_quality(sub, fixed, bo);
    write_back(m, sub, verts, border, blk);
  });
  link_blocks(m, blocks, owner);
  for (const Block& blk : blocks) add_counts(st, blk.st);
  st.blocks = static_cast<std::uint32_t>(blocks.size());
  // The serial pass from what the blocks could not reach: bad triangles at a border vertex.
  std::vector<std::uint8_t> seeds(m.num_slots(), 0);
  for (std::uint32_t s = 0; s < m.corner.size(); ++s)
    if (border[m.corner[s].value]) seeds[s / 3] = 1;
  serial.seeds = &seeds;
  serial.max_share_loss = 0;
  add_counts(st, optimize_quality(m, fixed_count, serial));
  bad.clear();
  st.min_after = scan_plane_bad(m, opt.threshold, threads, nullptr, bad);
  st.bad_after = static_cast<std::uint32_t>(bad.size());
  return st;
}

}  // namespace sm
