// How long-running kernel stages say how far they are: coastline import, 1D and
// 2D meshing call a Progress the front end supplies; the kernel never prints itself.
#pragma once

#include <cstdint>
#include <string_view>

namespace sm {

/// A sink for progress reports. Stages call begin, then update any number of times, then
/// end, from one thread at a time (a parallel stage reports from its coordinating thread).
/// Implementations decide how often to draw: update may be called for every unit of work.
/// A stage may open a nested stage for finer progress inside one of its units (begin while
/// it is open, e.g. "2D refine" with one unit per part of a large face inside "2D" with one
/// unit per face); update and end then apply to the nested stage until it ends, after
/// which the outer stage continues.
class Progress {
 public:
  virtual ~Progress() = default;
  /// A stage starts: `name` as in the statistics summary ("1D", "2D refine"), `total` units
  /// of work (faces, curves, estimated triangles), 0 when unknown.
  virtual void begin(std::string_view name, std::uint64_t total) = 0;
  /// `done` units of the current stage are finished (non-decreasing within a stage).
  virtual void update(std::uint64_t done) = 0;
  /// The current stage is finished.
  virtual void end() = 0;
};

/// Calls through a possibly null Progress: kernel code holds a `Progress*` that is null
/// when nobody listens, and reports with these helpers instead of testing it everywhere.
inline void progress_begin(Progress* p, std::string_view name, std::uint64_t total) {
  if (p) p->begin(name, total);
}
inline void progress_update(Progress* p, std::uint64_t done) {
  if (p) p->update(done);
}
inline void progress_end(Progress* p) {
  if (p) p->end();
}

}  // namespace sm
