// The stderr progress display (see terminal_progress.h).
#include "cli/terminal_progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

namespace sm::cli {

namespace {

// A live line is redrawn at most this often (seconds): ten times a second.
constexpr double kRedrawInterval = 0.1;

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

TerminalProgress::TerminalProgress(std::FILE* out, Style style, Clock now)
    : out_(out), style_(style), now_(now ? std::move(now) : Clock(steady_seconds)) {}

TerminalProgress::~TerminalProgress() { end(); }

TerminalProgress::Style TerminalProgress::style_for(std::FILE* out) {
  return ::isatty(::fileno(out)) ? Style::Live : Style::Lines;
}

void TerminalProgress::begin(std::string_view name, std::uint64_t total) {
  end();
  open_ = true;
  name_ = name;
  total_ = total;
  done_ = 0;
  start_ = last_draw_ = now_();
  drawn_width_ = 0;
  if (style_ == Style::Lines) {
    if (total_ > 0) fmt::print(out_, "stereomesh: {}: start ({})\n", name_, total_);
    else fmt::print(out_, "stereomesh: {}: start\n", name_);
    std::fflush(out_);
  } else {
    draw();
  }
}

void TerminalProgress::update(std::uint64_t done) {
  if (!open_) return;
  done_ = done;
  if (style_ != Style::Live) return;
  const double t = now_();
  if (t - last_draw_ < kRedrawInterval) return;
  last_draw_ = t;
  draw();
}

void TerminalProgress::end() {
  if (!open_) return;
  const double seconds = now_() - start_;
  if (style_ == Style::Lines) {
    fmt::print(out_, "stereomesh: {}: done in {:.3f} s\n", name_, seconds);
  } else {
    if (total_ > 0) done_ = std::max(done_, total_);
    draw();
    std::fputc('\n', out_);
  }
  std::fflush(out_);
  open_ = false;
}

std::string TerminalProgress::live_text() const {
  const double seconds = now_() - start_;
  if (total_ == 0) return fmt::format("{}  {:.1f} s", name_, seconds);
  const double pct = 100.0 * static_cast<double>(std::min(done_, total_)) / static_cast<double>(total_);
  return fmt::format("{}  {}/{}  {:.0f}%  {:.1f} s", name_, done_, total_, pct, seconds);
}

void TerminalProgress::draw() {
  std::string text = live_text();
  // Pad over the previous, longer text instead of relying on terminal escapes.
  const std::size_t width = text.size();
  if (width < drawn_width_) text.append(drawn_width_ - width, ' ');
  drawn_width_ = width;
  fmt::print(out_, "\r{}", text);
  std::fflush(out_);
}

}  // namespace sm::cli
