// The words of the 2D mesher's warnings: each MeshNote kind picks its diagnostic kind and
// passes the note's values to the kind's format (lang/diag_kinds.def).
#include "interp/kernel/mesh_note_words.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

namespace sm::interp {

using namespace sm::lang;
using namespace fmt::literals;

namespace {

// A list of islands or sharp corners shows its first few members, then how many more.
constexpr std::size_t kListedMembers = 8;

const char* plural_s(std::uint64_t n) { return n == 1 ? "" : "s"; }

std::string tag_list_words(const std::vector<int>& tags) {
  std::string s;
  for (int t : tags) s += fmt::format("{}{}", s.empty() ? "" : ", ", t);
  return s;
}

// "surface N", or the Compound Surface whose union N is.
std::string surface_words(int surface, const CompoundSurfacePlan& compounds) {
  if (const std::vector<int>* originals = compound_union_of(compounds, surface))
    return fmt::format("the union of Compound Surface{{{}}}", tag_list_words(*originals));
  return fmt::format("surface {}", surface);
}

// "2, 3, 4" or "2, 3, ..., 9 and 4 more".
std::string loop_list_words(const std::vector<int>& loops) {
  std::string s;
  for (std::size_t i = 0; i < std::min(loops.size(), kListedMembers); ++i)
    s += fmt::format("{}{}", i ? ", " : "", loops[i]);
  if (loops.size() > kListedMembers) s += fmt::format(" and {} more", loops.size() - kListedMembers);
  return s;
}

// "5.0 degrees at (0, 0, 0); 7.2 degrees at ...; and 4 more".
std::string corner_list_words(const std::vector<MeshNoteCorner>& corners) {
  std::string s;
  for (std::size_t i = 0; i < std::min(corners.size(), kListedMembers); ++i)
    s += fmt::format("{}{:.1f} degrees at {}", i ? "; " : "", corners[i].degrees, place_words(corners[i].place));
  if (corners.size() > kListedMembers) s += fmt::format("; and {} more", corners.size() - kListedMembers);
  return s;
}

}  // namespace

std::string place_words(const MeshPlace& place) {
  if (!place.on_sphere) return fmt::format("({:.6g}, {:.6g}, {:.6g})", place.xyz.x, place.xyz.y, place.xyz.z);
  return fmt::format("lon {:.4f}, lat {:.4f}", place.lonlat.lon, place.lonlat.lat);
}

void report_mesh_note(Diagnostics& diags, SourceRange at, const MeshNote& note, const CompoundSurfacePlan& compounds) {
  const std::string surface = surface_words(note.surface, compounds);
  const std::string place = place_words(note.place);
  switch (note.kind) {
    case MeshNoteKind::IslandsLeftOut:
      if (note.loops.size() == 1)
        diags.report(at, Diag::MeshIslandLeftOut, "surface"_a = surface, "place"_a = place, "loop"_a = note.loops[0]);
      else
        diags.report(at, Diag::MeshIslandsLeftOut, "surface"_a = surface, "count"_a = note.loops.size(),
                     "place"_a = place, "loops"_a = loop_list_words(note.loops));
      return;
    case MeshNoteKind::BoundaryOffPlane:
      diags.report(at, Diag::MeshBoundaryOffPlane, "surface"_a = surface, "distance"_a = note.distance,
                   "relative"_a = note.relative, "place"_a = place);
      return;
    case MeshNoteKind::FloorSharpCorners:
      diags.report(at, Diag::MeshFloorSharpCorners, "surface"_a = surface, "count"_a = note.count,
                   "s"_a = plural_s(note.count), "floor"_a = note.floor, "limit"_a = note.sharp_limit_degrees,
                   "corners"_a = corner_list_words(note.corners));
      return;
    case MeshNoteKind::FloorStillBelow:
      if (note.work_budget > 0)
        diags.report(at, Diag::MeshFloorOutOfWork, "surface"_a = surface, "count"_a = note.count,
                     "s"_a = plural_s(note.count), "floor"_a = note.floor, "rounds"_a = note.rounds,
                     "rounds_s"_a = plural_s(note.rounds), "points"_a = note.new_points,
                     "budget"_a = note.work_budget, "rho"_a = note.worst_rho, "place"_a = place);
      else
        diags.report(at, Diag::MeshFloorStillBelow, "surface"_a = surface, "count"_a = note.count,
                     "s"_a = plural_s(note.count), "floor"_a = note.floor, "rounds"_a = note.rounds,
                     "rounds_s"_a = plural_s(note.rounds), "points"_a = note.new_points, "rho"_a = note.worst_rho,
                     "place"_a = place);
      return;
    case MeshNoteKind::FloorPutBack:
      diags.report(at, Diag::MeshFloorPutBack, "surface"_a = surface, "floor"_a = note.floor, "count"_a = note.count,
                   "before"_a = note.count_before, "rounds"_a = note.rounds, "rounds_s"_a = plural_s(note.rounds),
                   "points"_a = note.new_points);
      return;
    case MeshNoteKind::FloorFault:
      diags.report(at, Diag::MeshFloorFault, "surface"_a = surface, "fault"_a = note.fault, "place"_a = place);
      return;
  }
}

void report_compound_declined(Diagnostics& diags, SourceRange at, const CompoundSurfacePlan::Declined& declined) {
  diags.report(at, Diag::MeshCompoundDeclined, "surfaces"_a = tag_list_words(declined.surfaces),
               "why"_a = declined.why);
}

}  // namespace sm::interp
