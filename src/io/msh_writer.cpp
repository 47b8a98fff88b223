// MSH 2.2 / 4.1 writer (ASCII and binary). Entities are written in (dim, tag)
// order and nodes and elements are numbered contiguously from 1 in that
// order, as Gmsh does, so the same mesh always gives the same bytes.
#include "io/msh_writer.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <span>

#include "base/output_file.h"
#include "base/parallel.h"

namespace sm::io {
namespace {

constexpr std::uint32_t kUnowned = 0xFFFFFFFFu;
// Nodes a chunk in the passes over every element's or entity's nodes below.
constexpr std::size_t kNodeChunk = std::size_t{1} << 16;

// Buffered byte output that either keeps everything (msh_to_string) or
// drains to a base::OutputFile every few megabytes (large meshes).
class Out {
 public:
  static constexpr std::size_t kItems = 1 << 14;   // items (lines) a chunk
  Out(base::OutputFile* file, int threads) : file_(file), threads_(resolve_thread_count(threads)) {}
  void text(std::string_view s) { buf_.append(s); drain(); }
  template <class... A>
  void f(fmt::format_string<A...> pattern, A&&... args) {
    fmt::format_to(std::back_inserter(buf_), pattern, std::forward<A>(args)...);
    drain();
  }
  template <class T>
  void bin(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    buf_.append(b, sizeof(T));
  }
  void coord(double v) { f("{:.16g}", v); }
  bool finish() {
    if (file_) {
      const bool ok = file_->write(buf_);
      buf_.clear();
      return ok;
    }
    return true;
  }
  std::string take() { return std::move(buf_); }

  /// The text of items [0, n), fill(begin, end, out) appending that of [begin, end) to out:
  /// made in chunks of fixed bounds on the writer's threads, a wave of chunks at a time
  /// (so that at most two waves are held beyond the buffer), and appended in item order,
  /// so the bytes do not depend on the thread count. A wave's text is appended and
  /// written out by one thread while the others make the next wave's: the file's writes
  /// (the kernel's copy of every byte) overlap the formatting instead of following it.
  /// (`per_chunk` items a chunk.)
  template <class Fill>
  void items(std::size_t n, const Fill& fill, std::size_t per_chunk = kItems) {
    const std::size_t chunks = (n + per_chunk - 1) / per_chunk;
    if (threads_ <= 1 || chunks <= 1) {
      for (std::size_t c = 0; c < chunks; ++c) {
        fill(c * per_chunk, std::min(n, (c + 1) * per_chunk), buf_);
        drain();
      }
      return;
    }
    const std::size_t wave = static_cast<std::size_t>(threads_) * 4;
    // Two sets of parts: a wave is made into one while the one before is written from the other.
    std::vector<std::string> parts[2];
    parts[0].resize(std::min(chunks, wave));
    parts[1].resize(std::min(chunks, wave));
    std::size_t written_count = 0;   // the parts of the wave before (in parts[1 - current])
    auto write_out = [&](std::vector<std::string>& done, std::size_t count) {
      for (std::size_t c = 0; c < count; ++c) {
        buf_.append(done[c]);
        drain();
      }
    };
    std::size_t current = 0;
    for (std::size_t c0 = 0; c0 < chunks; c0 += wave, current = 1 - current) {
      const std::size_t nc = std::min(wave, chunks - c0);
      std::vector<std::string>& made = parts[current];
      std::vector<std::string>& done = parts[1 - current];
      // Job 0 writes the wave before; jobs 1..nc make this wave's chunks.
      parallel_for_chunks(threads_, nc + 1, 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t job = begin; job < end; ++job) {
          if (job == 0) {
            write_out(done, written_count);
            continue;
          }
          const std::size_t c = job - 1;
          made[c].clear();
          const std::size_t lo = (c0 + c) * per_chunk;
          fill(lo, std::min(n, lo + per_chunk), made[c]);
        }
      });
      written_count = nc;
    }
    write_out(parts[1 - current], written_count);
  }

  /// The text of blocks [0, n) in order, block k holding weight(k) items (lines): a
  /// block of kItems or more by large(k, *this) (its own items, chunked); a run of
  /// smaller ones cut into groups of consecutive blocks of at most kItems lines in all
  /// (one block at least), each group one chunk of items, small(k, out) appending block
  /// k's text. Groups depend on the weights only: the same bytes for every thread count.
  /// (The world's coast is tens of thousands of curves of a few nodes each: block by
  /// block, their text was made on one thread.)
  template <class Weight, class Small, class Large>
  void blocks(std::size_t n, const Weight& weight, const Small& small, const Large& large) {
    std::vector<std::size_t> group_start;
    for (std::size_t k = 0; k < n;) {
      if (weight(k) >= kItems) {
        large(k, *this);
        ++k;
        continue;
      }
      group_start.clear();
      std::size_t end = k, lines = kItems;
      for (; end < n && weight(end) < kItems; ++end) {
        const std::size_t w = weight(end) + 1;   // and its header line
        if (lines + w > kItems) group_start.push_back(end), lines = 0;
        lines += w;
      }
      group_start.push_back(end);
      items(
          group_start.size() - 1,
          [&](std::size_t begin, std::size_t stop, std::string& out) {
            for (std::size_t g = begin; g < stop; ++g)
              for (std::size_t b = group_start[g]; b < group_start[g + 1]; ++b) small(b, out);
          },
          1);
      k = end;
    }
  }

 private:
  void drain() {
    if (file_ && buf_.size() > (4u << 20)) {
      file_->write(buf_);
      buf_.clear();
    }
  }
  base::OutputFile* file_;
  int threads_ = 1;
  std::string buf_;
};

// Everything both versions need to know about numbering and what is saved.
struct Plan {
  std::vector<std::size_t> order;          // entity indices sorted by (dim, tag)
  std::vector<char> saved;                 // per entity: its elements are written
  std::vector<std::uint32_t> owner;        // per node: owning entity index
  bool has_physicals = false;
};

Plan make_plan(const MeshModel& m, const MshOptions& opt) {
  Plan p;
  p.order = entity_order(m);
  for (const EntityMesh& e : m.entities) p.has_physicals |= !e.physical_tags.empty();
  p.saved.resize(m.entities.size());
  // A partition's interface curves and points (io/partitioned_model.h) are written with
  // their elements, as Gmsh 4.8.4 writes them (it gives them their parent surface's groups,
  // which would read back as a curve group that is not the script's; they have none here).
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    const EntityMesh& e = m.entities[i];
    const bool interface = !e.partitions.empty() && e.parent_dim != e.dim;
    p.saved[i] = opt.save_all || !p.has_physicals || !e.physical_tags.empty() || interface;
  }
  p.owner.assign(m.xyz.size(), kUnowned);
  // A node has one owner (validate_mesh_model): each slot is written once.
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    const std::vector<std::uint32_t>& nodes = m.entities[i].nodes;
    parallel_for_chunks(resolve_thread_count(opt.threads), nodes.size(), kNodeChunk,
                        [&](std::size_t begin, std::size_t end) {
                          for (std::size_t k = begin; k < end; ++k) p.owner[nodes[k]] = static_cast<std::uint32_t>(i);
                        });
  }
  return p;
}

std::size_t element_count(const EntityMesh& e) { return e.connectivity.size() / nodes_per_element(e.type); }

void write_header(Out& o, const MshOptions& opt) {
  o.text("$MeshFormat\n");
  o.text(opt.version == 22 ? "2.2 " : "4.1 ");
  o.text(opt.binary ? "1 8\n" : "0 8\n");
  if (opt.binary) {
    o.bin<int>(1);  // lets the reader detect the byte order
    o.text("\n");
  }
  o.text("$EndMeshFormat\n");
}

void write_physical_names(Out& o, const MeshModel& m) {
  std::vector<const PhysicalGroup*> named;
  for (const PhysicalGroup& g : m.physicals)
    if (!g.name.empty()) named.push_back(&g);
  if (named.empty()) return;
  std::sort(named.begin(), named.end(), [](auto* a, auto* b) {
    return a->dim != b->dim ? a->dim < b->dim : a->tag < b->tag;
  });
  o.f("$PhysicalNames\n{}\n", named.size());
  for (const PhysicalGroup* g : named) o.f("{} {} \"{}\"\n", g->dim, g->tag, g->name);
  o.text("$EndPhysicalNames\n");
}

// $Periodic (Gmsh 4.8.4's writeMSHPeriodicNodes and writeMSH4PeriodicNodes): per periodic
// entity its dim, tag and master's tag, its affine map (2.2: an "Affine" line when there
// is one; 4.1: the count 0 or 16 and the numbers), then its node pairs by node tag. Only
// the entities whose elements are written with their master's (Gmsh 2.2's rule; its 4.1
// writes all and its reader skips nodes it does not find), so that every tag is in the file.
template <class Tag>
void write_periodic(Out& o, const MeshModel& m, const Plan& p, const std::vector<Tag>& tag, bool v41, bool binary) {
  std::map<std::pair<int, int>, bool> saved;
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    bool& any = saved[{m.entities[i].dim, m.entities[i].tag}];
    any = any || p.saved[i] != 0;
  }
  std::vector<const PeriodicLink*> links;
  for (const PeriodicLink& l : m.periodic) {
    const auto a = saved.find({l.dim, l.tag}), b = saved.find({l.dim, l.master});
    if (a == saved.end() || b == saved.end() || !a->second || !b->second) continue;
    if (std::all_of(l.nodes.begin(), l.nodes.end(), [&](const auto& q) { return tag[q.first] && tag[q.second]; }))
      links.push_back(&l);
  }
  if (links.empty()) return;
  binary = binary && v41;   // Gmsh writes MSH 2.2's section as text in a binary file too
  o.text("$Periodic\n");
  if (binary) o.bin<std::uint64_t>(links.size());
  else o.f("{}\n", links.size());
  for (const PeriodicLink* l : links) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
    for (const auto& [a, b] : l->nodes) pairs.emplace_back(tag[a], tag[b]);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    const bool affine = l->affine.size() == 16;
    if (binary) {
      o.bin<int>(l->dim), o.bin<int>(l->tag), o.bin<int>(l->master);
      o.bin<std::uint64_t>(affine ? 16 : 0);
      if (affine)
        for (double v : l->affine) o.bin(v);
      o.bin<std::uint64_t>(pairs.size());
      for (const auto& [a, b] : pairs) o.bin<std::uint64_t>(a), o.bin<std::uint64_t>(b);
      continue;
    }
    o.f("{} {} {}\n", l->dim, l->tag, l->master);
    if (v41 || affine) {
      o.text(!affine ? "0" : v41 ? "16" : "Affine");
      if (affine)
        for (double v : l->affine) o.f(" {:.16g}", v);
      o.text("\n");
    }
    o.f("{}\n", pairs.size());
    for (const auto& [a, b] : pairs) o.f("{} {}\n", a, b);
  }
  o.text(binary ? "\n$EndPeriodic\n" : "$EndPeriodic\n");
}

// ---- MSH 2.2 ---------------------------------------------------------------

// One $NodeData section per field, over the written nodes (tag, node) in tag order: one
// string tag (the name), one real tag (time 0), three integer tags (time step 0, one
// component, the node count); in binary the tag is an int and the value a double.
void write_node_data(Out& o, const std::vector<NodeData>& data,
                     const std::vector<std::pair<std::uint64_t, std::uint32_t>>& written, bool binary) {
  for (const NodeData& d : data) {
    o.f("$NodeData\n1\n\"{}\"\n1\n0\n3\n0\n1\n{}\n", d.name, written.size());
    for (const auto& [t, n] : written) {
      if (binary) {
        o.bin<int>(static_cast<int>(t));
        o.bin<double>(d.values[n]);
      } else {
        o.f("{} {:.16g}\n", t, d.values[n]);
      }
    }
    o.text(binary ? "\n$EndNodeData\n" : "$EndNodeData\n");
  }
}

void write_msh22(Out& o, const MeshModel& m, const MshOptions& opt, const Plan& p) {
  // Only nodes used by written elements are output, numbered in the order of
  // their owning entities.
  std::vector<char> used(m.xyz.size(), 0);
  std::size_t n_elements = 0;
  for (std::size_t i : p.order) {
    if (!p.saved[i]) continue;
    const EntityMesh& e = m.entities[i];
    for (std::uint32_t n : e.connectivity) used[n] = 1;
    const std::size_t copies = (opt.save_all || e.physical_tags.empty()) ? 1 : e.physical_tags.size();
    n_elements += element_count(e) * copies;
  }
  std::vector<std::uint32_t> tag(m.xyz.size(), 0);
  std::vector<std::uint32_t> node_order;
  for (std::size_t i : p.order)
    for (std::uint32_t n : m.entities[i].nodes)
      if (used[n]) {
        node_order.push_back(n);
        tag[n] = static_cast<std::uint32_t>(node_order.size());
      }

  o.f("$Nodes\n{}\n", node_order.size());
  if (opt.binary) {
    for (std::uint32_t n : node_order) {
      const Vec3 x = m.xyz[n];
      o.bin<int>(static_cast<int>(tag[n]));
      o.bin(x.x), o.bin(x.y), o.bin(x.z);
    }
  } else {
    o.items(node_order.size(), [&](std::size_t begin, std::size_t end, std::string& out) {
      auto it = std::back_inserter(out);
      for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t n = node_order[k];
        const Vec3 x = m.xyz[n];
        it = fmt::format_to(it, FMT_COMPILE("{} {:.16g} {:.16g} {:.16g}\n"), tag[n], x.x, x.y, x.z);
      }
    });
  }
  if (opt.binary) o.text("\n");
  o.text("$EndNodes\n");

  o.f("$Elements\n{}\n", n_elements);
  int elm = 0;
  for (std::size_t i : p.order) {
    if (!p.saved[i]) continue;
    const EntityMesh& e = m.entities[i];
    const int npe = nodes_per_element(e.type);
    const std::size_t ne = element_count(e);
    // SaveAll drops the physical tags in MSH2 (written as 0).
    std::vector<int> phys = opt.save_all || e.physical_tags.empty() ? std::vector<int>{0} : e.physical_tags;
    for (int ph : phys) {
      if (!opt.binary) {
        const int first = elm;
        o.items(ne, [&](std::size_t begin, std::size_t end, std::string& out) {
          auto it = std::back_inserter(out);
          for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t* c = &e.connectivity[k * npe];
            it = fmt::format_to(it, FMT_COMPILE("{} {} 2 {} {}"), first + static_cast<int>(k) + 1,
                                static_cast<int>(e.type), ph, e.tag);
            for (int j = 0; j < npe; ++j) it = fmt::format_to(it, FMT_COMPILE(" {}"), tag[c[j]]);
            *it++ = '\n';
          }
        });
        elm += static_cast<int>(ne);
        continue;
      }
      for (std::size_t k = 0; k < ne; ++k) {
        ++elm;
        const std::uint32_t* c = &e.connectivity[k * npe];
        // Gmsh writes a one-element block header (type, 1, 2 tags) before
        // every element; readers accept any block size, we match Gmsh.
        o.bin<int>(static_cast<int>(e.type)), o.bin<int>(1), o.bin<int>(2);
        o.bin<int>(elm), o.bin<int>(ph), o.bin<int>(e.tag);
        for (int j = 0; j < npe; ++j) o.bin<int>(static_cast<int>(tag[c[j]]));
      }
    }
  }
  if (opt.binary) o.text("\n");
  o.text("$EndElements\n");
  write_periodic(o, m, p, tag, /*v41=*/false, opt.binary);
  if (!opt.node_data.empty()) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> written;
    for (std::uint32_t n : node_order) written.emplace_back(tag[n], n);
    write_node_data(o, opt.node_data, written, opt.binary);
  }
}

// ---- MSH 4.1 ---------------------------------------------------------------

struct Box {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(Vec3 x) {
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
    hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
  }
  bool empty() const { return lo.x > hi.x; }
};

// The box of the points `nodes`, in chunks of fixed bounds on `threads` threads (a
// surface's elements read millions of points in no order): the least and greatest
// coordinates are the same however the chunks are cut and joined.
Box bounding_box(const MeshModel& m, std::span<const std::uint32_t> nodes, int threads) {
  constexpr std::size_t kBoxChunk = 1 << 16;
  std::vector<Box> chunk_box((nodes.size() + kBoxChunk - 1) / kBoxChunk);
  parallel_for_chunks(resolve_thread_count(threads), nodes.size(), kBoxChunk, [&](std::size_t begin, std::size_t end) {
    Box& b = chunk_box[begin / kBoxChunk];
    for (std::size_t k = begin; k < end; ++k) b.add(m.xyz[nodes[k]]);
  });
  Box box;
  for (const Box& b : chunk_box)
    if (!b.empty()) box.add(b.lo), box.add(b.hi);
  return box;
}

// $Entities (the model's own entities) or, for a partitioned mesh, $PartitionedEntities
// (the entities with partitions: partition count, no ghost entities, then per entity its
// parent's dim and tag and its partitions before the usual fields), as Gmsh 4.8.4 writes.
void write_entities41(Out& o, const MeshModel& m, const MshOptions& opt, const Plan& p, bool partitioned) {
  auto listed = [&](const EntityMesh& e) { return e.partitions.empty() != partitioned; };
  // An entity's second element block (quadrangles beside triangles) is not listed again.
  std::vector<char> extra(m.entities.size(), 0);
  for (std::size_t k = 0; k < p.order.size(); ++k) extra[p.order[k]] = is_extra_block(m, p.order, k) ? 1 : 0;
  std::size_t count[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < m.entities.size(); ++i)
    if (listed(m.entities[i]) && !extra[i]) ++count[std::clamp(m.entities[i].dim, 0, 3)];
  // A partitioned mesh's model entities hold no mesh: their boxes are their pieces'.
  std::map<std::pair<int, int>, Box> piece_boxes;
  if (m.num_partitions > 0 && !partitioned)
    for (const EntityMesh& e : m.entities)
      if (!e.partitions.empty() && e.parent_dim == e.dim) {
        Box& b = piece_boxes[{e.dim, e.parent_tag}];
        for (std::uint32_t n : e.connectivity) b.add(m.xyz[n]);
      }
  o.text(partitioned ? "$PartitionedEntities\n" : "$Entities\n");
  if (opt.binary) {
    if (partitioned) o.bin<std::uint64_t>(static_cast<std::uint64_t>(m.num_partitions)), o.bin<std::uint64_t>(0);
    for (std::size_t c : count) o.bin<std::uint64_t>(c);
  } else {
    if (partitioned) o.f("{}\n0\n", m.num_partitions);
    o.f("{} {} {} {}\n", count[0], count[1], count[2], count[3]);
  }
  for (std::size_t k = 0; k < p.order.size(); ++k) {
    const std::size_t i = p.order[k];
    const EntityMesh& e = m.entities[i];
    if (!listed(e) || extra[i]) continue;
    Box box = bounding_box(m, e.nodes, opt.threads);
    const Box used = bounding_box(m, e.connectivity, opt.threads);
    if (!used.empty()) box.add(used.lo), box.add(used.hi);
    for (std::size_t j = k + 1; j < p.order.size() && extra[p.order[j]]; ++j)
      for (std::uint32_t n : m.entities[p.order[j]].connectivity) box.add(m.xyz[n]);
    if (const auto it = piece_boxes.find({e.dim, e.tag}); it != piece_boxes.end())
      box.add(it->second.lo), box.add(it->second.hi);
    if (box.empty()) box.add(Vec3{0, 0, 0});
    if (opt.binary) {
      o.bin<int>(e.tag);
      if (partitioned) {
        o.bin<int>(e.parent_dim), o.bin<int>(e.parent_tag);
        o.bin<std::uint64_t>(e.partitions.size());
        for (int q : e.partitions) o.bin<int>(q);
      }
      if (e.dim == 0) {
        o.bin(box.lo.x), o.bin(box.lo.y), o.bin(box.lo.z);
      } else {
        for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z}) o.bin(v);
      }
      o.bin<std::uint64_t>(e.physical_tags.size());
      for (int t : e.physical_tags) o.bin<int>(t);
      if (e.dim > 0) {
        o.bin<std::uint64_t>(e.boundary.size());
        for (int t : e.boundary) o.bin<int>(t);
      }
    } else {
      o.f("{} ", e.tag);
      if (partitioned) {
        o.f("{} {} {} ", e.parent_dim, e.parent_tag, e.partitions.size());
        for (int q : e.partitions) o.f("{} ", q);
      }
      if (e.dim == 0) {
        o.f("{:.16g} {:.16g} {:.16g} ", box.lo.x, box.lo.y, box.lo.z);
      } else {
        o.f("{:.16g} {:.16g} {:.16g} {:.16g} {:.16g} {:.16g} ", box.lo.x, box.lo.y, box.lo.z, box.hi.x,
            box.hi.y, box.hi.z);
      }
      o.f("{} ", e.physical_tags.size());
      for (int t : e.physical_tags) o.f("{} ", t);
      if (e.dim > 0) {
        o.f("{} ", e.boundary.size());
        for (int t : e.boundary) o.f("{} ", t);
      }
      o.text("\n");
    }
  }
  o.text(opt.binary ? "\n" : "");
  o.text(partitioned ? "$EndPartitionedEntities\n" : "$EndEntities\n");
}

// $Nodes's blocks: an entity's header, then its node tags and places (tag[n]: node n's tag).
void write_node_blocks41(Out& o, const MeshModel& m, const MshOptions& opt, const std::vector<char>& node_block,
                         const Plan& p, const std::vector<std::uint64_t>& tag) {
  std::vector<std::size_t> node_blocks;
  for (std::size_t i : p.order)
    if (node_block[i]) node_blocks.push_back(i);
  auto has_param = [&](const EntityMesh& e) {
    return opt.save_parametric && e.dim > 0 && e.params.size() == e.nodes.size() * e.dim;
  };
  // A block's node tags, then its coordinates (and parameters), items [begin, end) of each.
  auto node_tags = [&](const EntityMesh& e, std::size_t begin, std::size_t end, std::string& out) {
    auto it = std::back_inserter(out);
    for (std::size_t k = begin; k < end; ++k) it = fmt::format_to(it, FMT_COMPILE("{}\n"), tag[e.nodes[k]]);
  };
  auto node_places = [&](const EntityMesh& e, std::size_t begin, std::size_t end, std::string& out) {
    const bool param = has_param(e);
    auto it = std::back_inserter(out);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3 x = m.xyz[e.nodes[k]];
      it = fmt::format_to(it, FMT_COMPILE("{:.16g} {:.16g} {:.16g}"), x.x, x.y, x.z);
      if (param)
        for (int d = 0; d < e.dim; ++d) it = fmt::format_to(it, FMT_COMPILE(" {:.16g}"), e.params[k * e.dim + d]);
      *it++ = '\n';
    }
  };
  auto node_header = [&](const EntityMesh& e, std::string& out) {
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("{} {} {} {}\n"), e.dim, e.tag, has_param(e) ? 1 : 0,
                   e.nodes.size());
  };
  if (!opt.binary)
    o.blocks(
        node_blocks.size(), [&](std::size_t b) { return 2 * m.entities[node_blocks[b]].nodes.size(); },
        [&](std::size_t b, std::string& out) {
          const EntityMesh& e = m.entities[node_blocks[b]];
          node_header(e, out);
          node_tags(e, 0, e.nodes.size(), out);
          node_places(e, 0, e.nodes.size(), out);
        },
        [&](std::size_t b, Out& out) {
          const EntityMesh& e = m.entities[node_blocks[b]];
          std::string header;
          node_header(e, header);
          out.text(header);
          out.items(e.nodes.size(), [&](std::size_t begin, std::size_t end, std::string& text) {
            node_tags(e, begin, end, text);
          });
          out.items(e.nodes.size(), [&](std::size_t begin, std::size_t end, std::string& text) {
            node_places(e, begin, end, text);
          });
        });
  if (opt.binary)
    for (const std::size_t i : node_blocks) {
      const EntityMesh& e = m.entities[i];
      const bool param = has_param(e);
      o.bin<int>(e.dim), o.bin<int>(e.tag), o.bin<int>(param ? 1 : 0), o.bin<std::uint64_t>(e.nodes.size());
      for (std::uint32_t n : e.nodes) o.bin<std::uint64_t>(tag[n]);
      for (std::size_t k = 0; k < e.nodes.size(); ++k) {
        const Vec3 x = m.xyz[e.nodes[k]];
        o.bin(x.x), o.bin(x.y), o.bin(x.z);
        if (param)
          for (int d = 0; d < e.dim; ++d) o.bin(e.params[k * e.dim + d]);
      }
    }
}

// $Elements: its counts, then each saved entity's block (tag[n]: node n's tag).
void write_element_blocks41(Out& o, const MeshModel& m, const MshOptions& opt, const Plan& p,
                            const std::vector<std::uint64_t>& tag) {
  std::size_t e_blocks = 0, n_elem = 0;
  for (std::size_t i : p.order)
    if (p.saved[i] && element_count(m.entities[i])) ++e_blocks, n_elem += element_count(m.entities[i]);
  o.text("$Elements\n");
  const std::uint64_t min_el = n_elem ? 1 : 0;
  if (opt.binary) {
    o.bin<std::uint64_t>(e_blocks), o.bin<std::uint64_t>(n_elem), o.bin<std::uint64_t>(min_el),
        o.bin<std::uint64_t>(n_elem);
  } else {
    o.f("{} {} {} {}\n", e_blocks, n_elem, min_el, n_elem);
  }
  // The element blocks with the number before each one's first element.
  std::vector<std::size_t> element_blocks;
  std::vector<std::uint64_t> first_element;
  {
    std::uint64_t count = 0;
    for (std::size_t i : p.order)
      if (p.saved[i] && element_count(m.entities[i])) {
        element_blocks.push_back(i);
        first_element.push_back(count);
        count += element_count(m.entities[i]);
      }
  }
  auto element_header = [&](const EntityMesh& e, std::string& out) {
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("{} {} {} {}\n"), e.dim, e.tag, static_cast<int>(e.type),
                   element_count(e));
  };
  auto element_lines = [&](std::size_t b, std::size_t begin, std::size_t end, std::string& out) {
    const EntityMesh& e = m.entities[element_blocks[b]];
    const int npe = nodes_per_element(e.type);
    const std::uint64_t first = first_element[b];
    auto it = std::back_inserter(out);
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t* c = &e.connectivity[k * npe];
      it = fmt::format_to(it, FMT_COMPILE("{} "), first + k + 1);
      for (int j = 0; j < npe; ++j) it = fmt::format_to(it, FMT_COMPILE("{} "), tag[c[j]]);
      *it++ = '\n';
    }
  };
  if (!opt.binary)
    o.blocks(
        element_blocks.size(), [&](std::size_t b) { return element_count(m.entities[element_blocks[b]]); },
        [&](std::size_t b, std::string& out) {
          const EntityMesh& e = m.entities[element_blocks[b]];
          element_header(e, out);
          element_lines(b, 0, element_count(e), out);
        },
        [&](std::size_t b, Out& out) {
          const EntityMesh& e = m.entities[element_blocks[b]];
          std::string header;
          element_header(e, header);
          out.text(header);
          out.items(element_count(e), [&](std::size_t begin, std::size_t end, std::string& text) {
            element_lines(b, begin, end, text);
          });
        });
  std::uint64_t elm = 0;
  for (std::size_t i : p.order) {
    const EntityMesh& e = m.entities[i];
    const std::size_t ne = element_count(e);
    if (!p.saved[i] || !ne || !opt.binary) continue;
    const int npe = nodes_per_element(e.type);
    o.bin<int>(e.dim), o.bin<int>(e.tag), o.bin<int>(static_cast<int>(e.type)), o.bin<std::uint64_t>(ne);
    for (std::size_t k = 0; k < ne; ++k) {
      ++elm;
      const std::uint32_t* c = &e.connectivity[k * npe];
      o.bin<std::uint64_t>(elm);
      for (int j = 0; j < npe; ++j) o.bin<std::uint64_t>(tag[c[j]]);
    }
  }
}

void write_msh41(Out& o, const MeshModel& m, const MshOptions& opt, const Plan& p) {
  write_entities41(o, m, opt, p, /*partitioned=*/false);
  if (m.num_partitions > 0) write_entities41(o, m, opt, p, /*partitioned=*/true);

  // Node blocks: every saved entity, plus every entity owning a node that a
  // saved element uses (the boundary of a physical surface, say).
  std::vector<char> node_block(m.entities.size(), 0);
  const int threads = resolve_thread_count(opt.threads);
  for (std::size_t i = 0; i < m.entities.size(); ++i) {
    if (!p.saved[i]) continue;
    node_block[i] = 1;
    // The same value from every element: stores made atomic (relaxed), not ordered.
    const std::vector<std::uint32_t>& used = m.entities[i].connectivity;
    parallel_for_chunks(threads, used.size(), kNodeChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
        std::atomic_ref<char>(node_block[p.owner[used[k]]]).store(1, std::memory_order_relaxed);
    });
  }
  // An entity's second element block holds no nodes: its first block's node block is
  // the entity's (written when either is saved).
  for (std::size_t k = 1; k < p.order.size(); ++k)
    if (is_extra_block(m, p.order, k) && node_block[p.order[k]]) {
      node_block[p.order[k]] = 0;
      std::size_t first = k - 1;
      while (first > 0 && is_extra_block(m, p.order, first)) --first;
      node_block[p.order[first]] = 1;
    }
  std::vector<std::uint64_t> tag(m.xyz.size(), 0);
  std::size_t n_blocks = 0, n_nodes = 0;
  for (std::size_t i : p.order) {
    if (!node_block[i]) continue;
    ++n_blocks;
    const std::vector<std::uint32_t>& nodes = m.entities[i].nodes;
    const std::size_t before = n_nodes;
    parallel_for_chunks(threads, nodes.size(), kNodeChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) tag[nodes[k]] = before + k + 1;
    });
    n_nodes += nodes.size();
  }
  // The partitioned entities list the nodes in another order than the model's: their tags
  // stay the MeshModel's numbering (node i is tag i + 1, as in the unpartitioned file and
  // every other format; io/from_model_mesh.h), so blocks need not run in tag order, and a
  // split file keeps the whole mesh's tags (as Gmsh writes them).
  std::uint64_t min_tag = n_nodes ? 1 : 0, max_tag = n_nodes;
  if (m.num_partitions > 0 && n_nodes > 0) {
    min_tag = ~std::uint64_t{0}, max_tag = 0;
    for (std::size_t i : p.order)
      if (node_block[i])
        for (std::uint32_t n : m.entities[i].nodes) {
          tag[n] = std::uint64_t{n} + 1;
          min_tag = std::min(min_tag, tag[n]), max_tag = std::max(max_tag, tag[n]);
        }
  }
  o.text("$Nodes\n");
  if (opt.binary) {
    o.bin<std::uint64_t>(n_blocks), o.bin<std::uint64_t>(n_nodes), o.bin<std::uint64_t>(min_tag),
        o.bin<std::uint64_t>(max_tag);
  } else {
    o.f("{} {} {} {}\n", n_blocks, n_nodes, min_tag, max_tag);
  }
  write_node_blocks41(o, m, opt, node_block, p, tag);
  o.text(opt.binary ? "\n$EndNodes\n" : "$EndNodes\n");

  write_element_blocks41(o, m, opt, p, tag);
  o.text(opt.binary ? "\n$EndElements\n" : "$EndElements\n");
  if (m.num_partitions == 0) write_periodic(o, m, p, tag, /*v41=*/true, opt.binary);
  if (!opt.node_data.empty()) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> written;
    for (std::size_t i : p.order)
      if (node_block[i])
        for (std::uint32_t n : m.entities[i].nodes) written.emplace_back(tag[n], n);
    std::sort(written.begin(), written.end());   // in tag order (partitioned: not block order)
    write_node_data(o, opt.node_data, written, opt.binary);
  }
}

void write_all(Out& o, const MeshModel& m, const MshOptions& opt) {
  const Plan p = make_plan(m, opt);
  write_header(o, opt);
  write_physical_names(o, m);
  if (opt.version == 22)
    write_msh22(o, m, opt, p);
  else
    write_msh41(o, m, opt, p);
}

}  // namespace

std::string msh_to_string(const MeshModel& mesh, const MshOptions& opt) {
  Out o(nullptr, opt.threads);
  write_all(o, mesh, opt);
  return o.take();
}

namespace {

bool check_msh(const MeshModel& mesh, const MshOptions& opt, std::string* error) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = "invalid mesh: " + why;
    return false;
  }
  if (mesh.num_partitions > 0 && opt.version == 22) {
    *error = "partitions are written in MSH 4.1 only: set Mesh.MshFileVersion = 4.1";
    return false;
  }
  return true;
}

}  // namespace

bool save_msh(const MeshModel& mesh, const MshOptions& opt, const std::string& path, std::string* error) {
  if (!check_msh(mesh, opt, error)) return false;
  base::OutputFile file;
  if (!file.open(path)) {
    *error = file.error();
    return false;
  }
  Out o(&file, opt.threads);
  write_all(o, mesh, opt);
  if (!o.finish() || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

bool save_msh_files(const std::function<const MeshModel&(std::size_t)>& mesh, const MshOptions& opt,
                    const std::vector<std::string>& paths, std::string* error) {
  std::vector<base::OutputFile> files(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const MeshModel& m = mesh(i);
    if (!check_msh(m, opt, error)) return false;
    if (!files[i].open(paths[i])) {
      *error = files[i].error();
      return false;
    }
    Out o(&files[i], opt.threads);
    write_all(o, m, opt);
    // Synced now, renamed with the others at the end: what waits holds a descriptor only.
    if (!o.finish() || !files[i].prepare()) {
      *error = files[i].error();
      return false;
    }
  }
  std::vector<base::OutputFile*> all;
  for (base::OutputFile& f : files) all.push_back(&f);
  std::size_t failed = 0;
  if (!base::commit_together(all, &failed)) {
    *error = fmt::format("{}: {}", paths[failed], files[failed].error());
    return false;
  }
  return true;
}

}  // namespace sm::io
