// The run's stage account (see stage_clock.h).
#include "interp/stage_clock.h"

#include <algorithm>

#include <fmt/format.h>

#include "base/cpu_clock.h"

namespace sm::interp {

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

StageClock::StageClock(std::string base, Clock now, Clock cpu)
    : now_(now ? std::move(now) : Clock(steady_seconds)), cpu_(cpu ? std::move(cpu) : Clock(process_cpu_seconds)) {
  started_ = last_ = now_();
  last_cpu_ = cpu_();
  times_.push_back({std::move(base), 0});
  cpu_times_.push_back(0);
  open_.push_back(0);
}

void StageClock::charge(double now) {
  times_[open_.back()].seconds += now - last_;
  last_ = now;
  const double cpu = cpu_();
  cpu_times_[open_.back()] += cpu - last_cpu_;
  last_cpu_ = cpu;
}

void StageClock::begin(std::string_view name, std::uint64_t) {
  charge(now_());
  // A stage that ran before is charged again in its one entry (linear in the distinct
  // names, a handful per run).
  const auto it = std::find_if(times_.begin(), times_.end(), [&](const StageTime& t) { return t.name == name; });
  if (it != times_.end()) {
    open_.push_back(static_cast<std::size_t>(it - times_.begin()));
  } else {
    times_.push_back({std::string(name), 0});
    cpu_times_.push_back(0);
    open_.push_back(times_.size() - 1);
  }
}

void StageClock::end() {
  if (open_.size() <= 1) return;   // the base stays open
  charge(now_());
  open_.pop_back();
}

std::vector<StageTime> StageClock::stages() const {
  std::vector<StageTime> out = times_;
  out[open_.back()].seconds += now_() - last_;
  return out;
}

std::vector<StageTime> StageClock::cpu_stages() const {
  std::vector<StageTime> out;
  out.reserve(times_.size());
  for (std::size_t i = 0; i < times_.size(); ++i) out.push_back({times_[i].name, cpu_times_[i]});
  out[open_.back()].seconds += cpu_() - last_cpu_;
  return out;
}

double StageClock::elapsed() const { return now_() - started_; }

StageScope::StageScope(Progress* clock, Progress* display, std::string_view name, std::uint64_t total)
    : clock_(clock), display_(display) {
  progress_begin(clock_, name, total);
  progress_begin(display_, name, total);
}

StageScope::~StageScope() {
  progress_end(display_);
  progress_end(clock_);
}

std::vector<StageTime> fold_small_stages(const std::vector<StageTime>& stages, std::string_view prefix,
                                         double min_seconds, std::string_view into) {
  std::vector<StageTime> out;
  std::size_t into_at = stages.size();   // index in `out`; none yet
  double folded = 0;
  bool any = false;
  for (const StageTime& t : stages) {
    const bool small = t.name.size() > prefix.size() && t.name.compare(0, prefix.size(), prefix) == 0 &&
                       t.seconds < min_seconds;
    if (small) {
      folded += t.seconds;
      if (!any && into_at == stages.size()) {
        out.push_back({std::string(into), 0});
        into_at = out.size() - 1;
      }
      any = true;
      continue;
    }
    if (t.name == into) {
      if (into_at == stages.size()) {
        out.push_back(t);
        into_at = out.size() - 1;
      } else {
        out[into_at].seconds += t.seconds;
      }
      continue;
    }
    out.push_back(t);
  }
  if (into_at < out.size()) out[into_at].seconds += folded;
  return out;
}

std::string format_time_line(const std::vector<StageTime>& stages) {
  std::string out = "Time:";
  double total = 0;
  for (const StageTime& t : stages) {
    out += fmt::format(" {} {:.3f} s,", t.name, t.seconds);
    total += t.seconds;
  }
  return out + fmt::format(" total {:.3f} s\n", total);
}

}  // namespace sm::interp
