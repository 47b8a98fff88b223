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

TerminalProgress::~TerminalProgress() {
  while (!open_.empty()) end();
}

TerminalProgress::Style TerminalProgress::style_for(std::FILE* out) {
  return ::isatty(::fileno(out)) ? Style::Live : Style::Lines;
}

void TerminalProgress::begin(std::string_view name, std::uint64_t total) {
  const double t = now_();
  open_.push_back({std::string(name), total, 0, t});
  last_draw_ = t;
  flush_other();
  if (style_ == Style::Lines) {
    if (total > 0) fmt::print(out_, "stereomesh: {}: start ({})\n", name, total);
    else fmt::print(out_, "stereomesh: {}: start\n", name);
    std::fflush(out_);
  } else {
    if (open_.size() == 1) drawn_width_ = 0;
    draw();
  }
}

void TerminalProgress::update(std::uint64_t done) {
  if (open_.empty()) return;
  open_.back().done = done;
  if (style_ != Style::Live) return;
  const double t = now_();
  if (t - last_draw_ < kRedrawInterval) return;
  last_draw_ = t;
  draw();
}

void TerminalProgress::end() {
  if (open_.empty()) return;
  Stage& st = open_.back();
  const double seconds = now_() - st.start;
  flush_other();
  if (style_ == Style::Lines) {
    fmt::print(out_, "stereomesh: {}: done in {:.3f} s\n", st.name, seconds);
  } else {
    if (st.total > 0) st.done = std::max(st.done, st.total);
    draw();
    if (open_.size() == 1) std::fputc('\n', out_);
  }
  open_.pop_back();
  // The outer stage's line again, without the finished nested one.
  if (style_ == Style::Live && !open_.empty()) draw();
  std::fflush(out_);
}

void TerminalProgress::suspend() {
  if (style_ != Style::Live || open_.empty() || drawn_width_ == 0) return;
  fmt::print(out_, "\r{}\r", std::string(drawn_width_, ' '));
  drawn_width_ = 0;
  std::fflush(out_);
}

void TerminalProgress::resume() {
  if (style_ == Style::Live && !open_.empty()) draw();
}

std::string TerminalProgress::live_text() const {
  std::string text;
  const double t = now_();
  for (const Stage& st : open_) {
    if (!text.empty()) text += "  >  ";
    const double seconds = t - st.start;
    if (st.total == 0) {
      text += fmt::format("{}  {:.1f} s", st.name, seconds);
    } else {
      const double pct = 100.0 * static_cast<double>(std::min(st.done, st.total)) / static_cast<double>(st.total);
      text += fmt::format("{}  {}/{}  {:.0f}%  {:.1f} s", st.name, st.done, st.total, pct, seconds);
    }
  }
  return text;
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
