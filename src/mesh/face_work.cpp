// The state of one face in the 2D pipeline: its error and place texts (face_work.h).
#include "mesh/face_work.h"

#include <fmt/format.h>

namespace sm {

FaceWork::FaceWork(const geo::Model& the_model, ModelMesh& the_mesh, const Mesh2dOptions& options, double diag,
                   Mesh2dResult& result, std::vector<std::uint32_t>& scratch, int surface)
    : model(the_model), mesh(the_mesh), opt(options), bbox(diag), res(result), tag(surface), local_of(scratch) {}

FaceWork::~FaceWork() {
  for (std::uint32_t node : global)
    if (node < local_of.size()) local_of[node] = kNoLocal;
}

bool FaceWork::fail(MeshProblem problem, std::initializer_list<long long> numbers, std::optional<Vec3> where,
                    std::initializer_list<int> curves) {
  MeshError& e = res.error;
  e.kind = MeshErrorKind::Failed;
  e.problem = problem;
  e.surface = tag;
  e.add_entity(2, tag);
  for (int c : curves) e.add_entity(1, c);
  std::size_t i = 0;
  for (long long n : numbers)
    if (i < e.numbers.size()) e.numbers[i++] = n;
  if (where) {
    e.has_xyz = true;
    e.xyz = *where;
    if (plane.geom) {
      e.has_lonlat = true;
      e.where = plane.lonlat(*where);
    }
  }
  return false;
}

bool FaceWork::fail_because(MeshProblem problem, std::string reason) {
  fail(problem);
  res.error.reason = std::move(reason);
  return false;
}

std::string FaceWork::where_text(Vec3 p) const {
  if (!plane.geom) return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z);
  const geo::LonLat ll = plane.lonlat(p);
  return fmt::format("lon {:.4f}, lat {:.4f}", ll.lon, ll.lat);
}

MeshPlace FaceWork::place_of(Vec3 p) const {
  MeshPlace at;
  at.xyz = p;
  at.on_sphere = plane.geom != nullptr;
  if (at.on_sphere) at.lonlat = plane.lonlat(p);
  return at;
}

bool FaceWork::recombined() const { return opt.constraints && opt.constraints->recombines(tag); }

}  // namespace sm
