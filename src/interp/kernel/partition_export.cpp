// Mesh.NbPartitions in the kernel state (see partition_export.h).
#include "interp/kernel/partition_export.h"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/progress_sink.h"
#include "io/from_model_mesh.h"

namespace sm::interp {

io::MeshPartitionOptions partition_options(const Options& o) {
  io::MeshPartitionOptions po;
  po.parts = static_cast<int>(o.number("Mesh.NbPartitions"));
  po.algorithm = static_cast<int>(o.number("Mesh.MetisAlgorithm"));
  po.ufactor = static_cast<int>(o.number("Mesh.MetisMaxLoadImbalance"));
  return po;
}

namespace {

// Mesh.NbPartitions = parts refused for `error`.
OptionRefusal partition_refusal(int parts, const io::PartitionError& error) {
  using lang::Diag;
  switch (error.problem) {
    case io::PartitionProblem::None: break;
    case io::PartitionProblem::NoElements: return option_refusal(Diag::PartitionsNoElements, parts);
    case io::PartitionProblem::PartCount: return option_refusal(Diag::PartitionsTooMany, parts, error.elements);
    case io::PartitionProblem::MetisOutOfMemory: return option_refusal(Diag::PartitionsMetisMemory, parts);
    case io::PartitionProblem::MetisFailed: break;
  }
  return option_refusal(Diag::PartitionsMetisFailed, parts);
}

}  // namespace

OptionRefusal partition_mesh_now(Interpreter& in, const ModelMesh& mesh, MeshStats* stats) {
  KernelState& k = in.kernel();
  const io::MeshPartitionOptions po = partition_options(in.options());
  if (po.parts <= 0) return {};
  // The partitioned entities are made per (entity, one element type): a surface with
  // quadrangles is not split into them yet.
  for (const auto& [tag, s] : mesh.surfaces)
    if (!s.quads.empty())
      return option_refusal(lang::Diag::PartitionsQuadrangles, po.parts, tag);
  const StageScope stage(&k.clock, progress_sink(in), "partitions");
  const io::MeshModel mm = io::from_model_mesh(k.model, mesh);
  auto partition = std::make_shared<io::MeshPartition>();
  io::PartitionError error;
  if (!io::partition_mesh(mm, po, partition.get(), &error)) return partition_refusal(po.parts, error);
  if (stats) {
    stats->partitions = partition->parts;
    stats->partition_edge_cut = partition->edge_cut;
    stats->partition_imbalance = partition->imbalance;
    stats->partition_min = *std::min_element(partition->part_elements.begin(), partition->part_elements.end());
    stats->partition_max = *std::max_element(partition->part_elements.begin(), partition->part_elements.end());
  }
  k.partition = std::move(partition);
  k.partition_options = po;
  return {};
}

std::string current_partition(Interpreter& in) {
  const KernelState& k = in.kernel();
  const io::MeshPartitionOptions want = partition_options(in.options());
  const io::MeshPartitionOptions& have = k.partition_options;
  if (k.partition && have.parts == want.parts && have.algorithm == want.algorithm && have.ufactor == want.ufactor)
    return {};
  if (!k.mesh) return "Mesh.NbPartitions: there is no 2D mesh to partition (mesh with -2 or 'Mesh 2;' first)";
  return partition_mesh_now(in, *k.mesh, nullptr).message;
}

bool holds_partitions(const io::OutputFormat& f, const Options& o) {
  if (!f.holds_partitions) return false;
  if (f.mesh_format != 1) return true;   // VTK, UGRID
  const double version = f.msh_file_version != 0 ? f.msh_file_version : o.number("Mesh.MshFileVersion");
  return version >= 4;
}

}  // namespace sm::interp
