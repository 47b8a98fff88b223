// Mesh.NbPartitions: the 2D mesh partitioned with METIS (io/mesh_partition.h) when it is
// meshed, or again at a Save whose options changed since, and which output formats can
// hold the partitions (MSH only as 4.1).
#pragma once

#include <string>

#include "io/mesh_partition.h"
#include "io/output_format.h"
#include "interp/options.h"
#include "mesh/mesh_stats.h"
#include "mesh/model_mesh.h"

namespace sm::interp {

class Interpreter;
class Options;

/// The METIS settings the options ask for (Mesh.NbPartitions, Mesh.MetisAlgorithm,
/// Mesh.MetisMaxLoadImbalance).
io::MeshPartitionOptions partition_options(const Options& o);

/// Partitions `mesh` as the options ask into the kernel state (KernelState::partition),
/// with its figures in *stats when given; nothing (empty()) or why not (more parts than
/// elements, ...). Nothing to do, and nothing refused, without Mesh.NbPartitions.
OptionRefusal partition_mesh_now(Interpreter& in, const ModelMesh& mesh, MeshStats* stats);

/// The kernel's partition made with the options' settings now (a Save after the options
/// changed since meshing partitions again); "" or why not.
std::string current_partition(Interpreter& in);

/// Whether `f` as the options write it has a place for partitions (MSH only as 4.1).
bool holds_partitions(const io::OutputFormat& f, const Options& o);

}  // namespace sm::interp
