// Where the wall time of a run goes, and beside it the process's CPU time (all threads): every interval between two
// stage changes is charged to the innermost open stage, and the time with no stage open to the script's own evaluation.
// The stages are exclusive, so they add up to the time since the clock started by construction of the account, not by a
// remainder computed at the end: each second is measured where it is spent. It is a Progress, so that kernel code
// reporting stages (the field set-up's kinds) can charge them without knowing about the clock.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/progress.h"
#include "mesh/mesh_stats.h"

namespace sm::interp {

class StageClock final : public Progress {
 public:
  /// Seconds since any fixed origin; the steady clock (wall) and the process's CPU clock
  /// unless a test supplies its own.
  using Clock = std::function<double()>;
  /// `base`: the stage charged while no other is open ("script").
  StageClock() : StageClock("script") {}
  explicit StageClock(std::string base, Clock now = {}, Clock cpu = {});

  /// A stage opens inside the current one (the current one stops being charged).
  void begin(std::string_view name, std::uint64_t total) override;
  void update(std::uint64_t) override {}
  /// The innermost stage closes; the one around it is charged again.
  void end() override;

  /// The stages so far, each once (in the order they first ran) with its seconds, the
  /// open ones charged up to now; the base first.
  std::vector<StageTime> stages() const;
  /// The same stages with the CPU seconds of the process (every thread) spent in each: on a
  /// loaded machine the wall account leans on the load, this one does not.
  std::vector<StageTime> cpu_stages() const;
  /// Seconds since the clock started (the sum of stages()).
  double elapsed() const;

 private:
  void charge(double now);

  Clock now_, cpu_;
  double started_ = 0, last_ = 0, last_cpu_ = 0;
  std::vector<std::size_t> open_;     // indices into times_, innermost last; [0] the base
  std::vector<StageTime> times_;
  std::vector<double> cpu_times_;     // CPU seconds, parallel to times_
};

/// Charges `name` on `clock` and shows it on `display` (either may be null) while it lives.
class StageScope {
 public:
  StageScope(Progress* clock, Progress* display, std::string_view name, std::uint64_t total = 0);
  ~StageScope();
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;

 private:
  Progress* clock_;
  Progress* display_;
};

/// `stages` with those named `prefix`... ("field Box") under `min_seconds` summed into the
/// stage `into` ("fields", added where the first of them was when there is none), so that
/// an account names each field kind that matters and not every one.
std::vector<StageTime> fold_small_stages(const std::vector<StageTime>& stages, std::string_view prefix,
                                         double min_seconds, std::string_view into);

/// `Time: script 0.512 s, import 11.494 s, ..., total 12.610 s`, the total the sum.
std::string format_time_line(const std::vector<StageTime>& stages);

}  // namespace sm::interp
