// The stderr progress display with a test clock: plain lines off a terminal, a throttled
// \r-redrawn line on one, each stage finished with a newline.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "cli/terminal_progress.h"
#include "scratch_dir.h"

using sm::cli::TerminalProgress;

namespace {

// Everything written to a temporary FILE*.

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

TEST_CASE("progress: plain lines, one at the start and one at the end of each stage") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  double t = 10;
  {
    TerminalProgress p(f, TerminalProgress::Style::Lines, [&] { return t; });
    p.begin("1D", 250);
    for (int i = 1; i <= 250; ++i) t += 0.01, p.update(i);
    p.end();
    p.begin("1D repair", 0);
    t += 0.5;
    p.end();
    p.begin("2D", 3);
    p.update(1);
    t += 1;
    // Left open: the destructor finishes it (a failing stage still gets its line).
  }
  CHECK(sm::testing::read_stream(f) ==
        "stereomesh: 1D: start (250)\n"
        "stereomesh: 1D: done in 2.500 s\n"
        "stereomesh: 1D repair: start\n"
        "stereomesh: 1D repair: done in 0.500 s\n"
        "stereomesh: 2D: start (3)\n"
        "stereomesh: 2D: done in 1.000 s\n");
  std::fclose(f);
}

TEST_CASE("progress: a live line redrawn at most ten times a second") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  double t = 0;
  TerminalProgress p(f, TerminalProgress::Style::Live, [&] { return t; });
  p.begin("2D", 1000);
  // 1000 updates over 2 s: at most 20 redraws, plus the first and the last.
  for (int i = 1; i <= 1000; ++i) t += 0.002, p.update(i);
  p.end();
  const std::string s = sm::testing::read_stream(f);
  const std::size_t draws = count(s, "\r");
  CHECK(draws >= 15);
  CHECK(draws <= 22);
  CHECK(count(s, "\n") == 1);
  CHECK(s.back() == '\n');
  CHECK(s.rfind("\r2D  1000/1000  100%  2.0 s\n") != std::string::npos);
  CHECK(s.rfind("\r2D  0/1000  0%  0.0 s", 0) == 0);
  // Every redraw reads "2D  done/1000  pct%", done and pct never going down.
  int last_done = -1, last_pct = -1, parsed = 0;
  bool monotonic = true;
  for (std::size_t at = s.find('\r'); at != std::string::npos; at = s.find('\r', at + 1)) {
    int done = 0, total = 0, pct = 0;
    if (std::sscanf(s.c_str() + at, "\r2D  %d/%d  %d%%", &done, &total, &pct) != 3) continue;
    ++parsed;
    monotonic = monotonic && done >= last_done && pct >= last_pct && total == 1000;
    last_done = done, last_pct = pct;
  }
  CHECK(parsed == static_cast<int>(draws));
  CHECK(monotonic);
  std::fclose(f);
}

TEST_CASE("progress: a stage without a total shows its elapsed time") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  double t = 0;
  {
    TerminalProgress p(f, TerminalProgress::Style::Live, [&] { return t; });
    p.begin("1D repair", 0);
    t = 12.3;
    p.end();
    p.begin("2D", 0);
    p.end();
  }
  CHECK(sm::testing::read_stream(f) == "\r1D repair  0.0 s\r1D repair  12.3 s\n\r2D  0.0 s\r2D  0.0 s\n");
  std::fclose(f);
}

TEST_CASE("progress: files are not terminals") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  CHECK(TerminalProgress::style_for(f) == TerminalProgress::Style::Lines);
  std::fclose(f);
}

TEST_CASE("progress: a nested stage, in plain lines and on a live line") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  double t = 0;
  {
    TerminalProgress p(f, TerminalProgress::Style::Lines, [&] { return t; });
    p.begin("2D", 2);
    p.update(1);
    p.begin("2D refine", 4);
    for (int i = 1; i <= 4; ++i) t += 0.5, p.update(i);
    p.end();
    t += 1;
    p.update(2);
    p.end();
  }
  CHECK(sm::testing::read_stream(f) ==
        "stereomesh: 2D: start (2)\n"
        "stereomesh: 2D refine: start (4)\n"
        "stereomesh: 2D refine: done in 2.000 s\n"
        "stereomesh: 2D: done in 3.000 s\n");
  std::fclose(f);

  f = std::tmpfile();
  REQUIRE(f);
  t = 0;
  {
    TerminalProgress p(f, TerminalProgress::Style::Live, [&] { return t; });
    p.begin("2D", 1);
    t = 1;
    p.begin("2D refine", 4);
    t = 1.5, p.update(2);
    p.end();
    // Left open: the destructor ends the stages still open.
  }
  const std::string s = sm::testing::read_stream(f);
  // Back to the outer stage alone: padded over the longer nested line.
  const std::string longest = "2D  0/1  0%  1.5 s  >  2D refine  4/4  100%  0.5 s", outer = "2D  0/1  0%  1.5 s";
  CHECK(s == "\r2D  0/1  0%  0.0 s"
             "\r2D  0/1  0%  1.0 s  >  2D refine  0/4  0%  0.0 s"
             "\r2D  0/1  0%  1.5 s  >  2D refine  2/4  50%  0.5 s"
             "\r" + longest + "\r" + outer + std::string(longest.size() - outer.size(), ' ') +
                 "\r2D  1/1  100%  1.5 s\n");
  CHECK(count(s, "\n") == 1);
  std::fclose(f);
}
