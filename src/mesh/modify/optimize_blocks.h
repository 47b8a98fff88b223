// The quality optimisation of a large triangulation in blocks, on the threads: the bad
// triangles cut into blocks by their position, each block (its bad triangles and the
// rings round them) optimised as a store of its own, written back, then a serial pass
// round the blocks' borders. The blocks depend on the mesh only, never on the threads.
#pragma once

#include <cstdint>

#include "mesh/modify/optimize.h"
#include "mesh/triangulation.h"

namespace sm {

/// optimize_quality (optimize.h) in blocks, the same bytes for every opt.threads:
/// the triangles below opt.threshold are cut into a power of two of blocks (about opt.block_bad
/// each, by bisect_parts of their centroids); each block in order claims its bad triangles
/// and two rings of vertex stars round them that no earlier block claimed. Every block is
/// copied into a store of its own (its border edges become hull edges there, so they are
/// never flipped and their vertices never move), optimised by the serial pass (its bank of
/// sacrifices the block's share of the face's), and written back into its own triangle slots
/// and its inner vertices: no two blocks write the same element. The borders are then linked
/// again in block order, and the serial pass runs once more from the bad triangles that touch
/// a border vertex. Without enough bad triangles for two blocks, the serial pass alone.
/// opt must have no to_space and no seeds. An undo journal on the store (store_undo.h) gets
/// everything the blocks write saved first, on one thread, so that it can still put the store back.
OptimizeStats optimize_in_blocks(TriangleStore& m, std::uint32_t fixed_count, const OptimizeOptions& opt);

}  // namespace sm
