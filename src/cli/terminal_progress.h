// The progress display on stderr: on a terminal one live line per stage, redrawn
// at most ten times a second ("2D  12/40  30%  1.2 s"), a nested stage shown after its
// outer one on the same line ("2D  0/1  0%  3.1 s  >  2D refine  5/16  31%  2.0 s");
// elsewhere (a log file, a pipe, CI) one plain line when a stage starts and one when it
// ends, with its time.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/progress.h"

namespace sm::cli {

class TerminalProgress final : public Progress {
 public:
  enum class Style {
    Live,   // \r-redrawn line, finished with a newline at the end of the stage
    Lines,  // "stereomesh: NAME: start (N)" and "stereomesh: NAME: done in T s" lines
  };
  /// Seconds since any fixed origin; the steady clock unless a test supplies its own.
  using Clock = std::function<double()>;

  TerminalProgress(std::FILE* out, Style style, Clock now = {});
  ~TerminalProgress() override;   // finishes the stages left open
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  /// Opens a stage; while one is open, a nested stage inside it (ended first).
  void begin(std::string_view name, std::uint64_t total) override;
  /// Progress of the innermost open stage.
  void update(std::uint64_t done) override;
  /// Ends the innermost open stage: the live line then shows the outer one again and
  /// ends with a newline only when the outermost stage ends.
  void end() override;

  /// A stream flushed before each write (stdout): Printf output written before a stage
  /// shows before its progress when both streams go to one pipe or terminal.
  void flush_first(std::FILE* other) { flush_first_ = other; }

  /// Other text for the same stream (a diagnostic) goes between suspend() and resume():
  /// on a terminal the live line is cleared first and redrawn after, so the text starts
  /// on a clean line and the progress stays below it. No-ops in the Lines style.
  void suspend();
  void resume();

  /// Live on a terminal, Lines otherwise.
  static Style style_for(std::FILE* out);

 private:
  struct Stage {
    std::string name;
    std::uint64_t total = 0, done = 0;
    double start = 0;
  };

  void draw();
  void flush_other() const {
    if (flush_first_) std::fflush(flush_first_);
  }
  std::string live_text() const;

  std::FILE* out_;
  std::FILE* flush_first_ = nullptr;
  Style style_;
  Clock now_;
  std::vector<Stage> open_;       // outermost first
  double last_draw_ = 0;
  std::size_t drawn_width_ = 0;   // characters of the live line on screen
};

}  // namespace sm::cli
