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

bool FaceWork::fail(std::string msg, std::optional<Vec3> where, std::initializer_list<int> curves) {
  MeshError& e = res.error;
  e.kind = MeshErrorKind::Failed;
  e.add_entity(2, tag);
  for (int c : curves) e.add_entity(1, c);
  e.message = fmt::format("surface {}: {}", tag, msg);
  if (where) {
    e.xyz = *where;
    if (plane.geom) {
      e.has_lonlat = true;
      e.where = plane.lonlat(*where);
      e.message += fmt::format(" near lon {:.6f}, lat {:.6f}", e.where.lon, e.where.lat);
    } else {
      e.message += fmt::format(" near ({}, {}, {})", where->x, where->y, where->z);
    }
  }
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
