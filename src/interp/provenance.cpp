// Kernel errors as located diagnostics with provenance notes (see provenance.h).
#include "interp/provenance.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include <fmt/format.h>

#include "interp/geo_diagnostic.h"
#include "interp/interpreter.h"

namespace sm::interp {

using geo::EntityKind;
using geo::GeoErrorKind;
using lang::Diag;

void record_created(KernelState& k, int key_dim, int tag, lang::SourceRange at) {
  k.created_at.insert_or_assign(std::make_pair(key_dim, tag), at);
}

namespace {

int key_of(EntityKind k) {
  switch (k) {
    case EntityKind::Point: return 0;
    case EntityKind::Curve: return 1;
    case EntityKind::Surface: return 2;
    case EntityKind::Volume: return 3;
    case EntityKind::CurveLoop: return kCurveLoopKey;
    case EntityKind::SurfaceGeometry: return kGeometryKey;
    default: return kPhysicalKeyBase - 1;   // no key: physical dims are not in the error
  }
}

const char* key_name(int key) {
  switch (key) {
    case 0: return "point";
    case 1: return "curve";
    case 2: return "surface";
    case 3: return "volume";
    case kCurveLoopKey: return "curve loop";
    case kGeometryKey: return "surface geometry";
    default: return "entity";
  }
}

}  // namespace

std::vector<lang::DiagNote> provenance_notes(const KernelState& k, const geo::GeoError& e) {
  // Which existing entities the error's tags name: the first is `e.entity` (absent for a
  // missing one, whose other tags are the entity being created); the others depend on
  // the kind (geo/error.h and the kernel's make_error calls).
  std::vector<std::pair<int, int>> named;
  const auto& t = e.tags;
  auto add = [&](int key, std::size_t i) {
    if (i < t.size()) named.emplace_back(key, std::abs(t[i]));
  };
  if (e.kind != GeoErrorKind::MissingEntity) add(key_of(e.entity), 0);
  switch (e.kind) {
    case GeoErrorKind::LoopNotClosed:
      for (std::size_t i = 1; i < t.size(); ++i) add(1, i);
      break;
    case GeoErrorKind::SelfReference: add(0, 1); break;
    case GeoErrorKind::HoleOutside: add(kCurveLoopKey, 1), add(kCurveLoopKey, 2); break;
    case GeoErrorKind::SharedBoundary:
      if (t.size() >= 4) {
        add(1, 1), add(kCurveLoopKey, 2), add(kCurveLoopKey, 3);
      } else {
        add(kCurveLoopKey, 1);
      }
      break;
    case GeoErrorKind::CoincidentPoints:
      if (e.entity == EntityKind::SurfaceGeometry) add(0, 1), add(0, 2);
      break;
    default: break;
  }
  std::vector<lang::DiagNote> notes;
  std::vector<std::pair<int, int>> seen;
  for (const auto& key : named) {
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    const auto it = k.created_at.find(key);
    if (it == k.created_at.end()) continue;
    notes.push_back({it->second, fmt::format("{} {} was created here", key_name(key.first), key.second)});
  }
  return notes;
}

std::vector<lang::DiagNote> provenance_notes(const KernelState& k, const MeshError& e) {
  std::vector<lang::DiagNote> notes;
  for (const MeshEntity& x : e.entities) {
    const auto it = k.created_at.find({x.dim, x.tag});
    if (it == k.created_at.end()) continue;
    notes.push_back({it->second, fmt::format("{} {} was created here", key_name(x.dim), x.tag)});
  }
  return notes;
}

void fail_geo(Interpreter& in, lang::SourceRange at, const geo::GeoError& e) {
  GeoDiagnostic d = geo_diagnostic(e);
  in.fail_message_with_notes(at, d.kind, std::move(d.message), provenance_notes(in.kernel(), e));
}

}  // namespace sm::interp
