// Diagnostics printed as the run reports them: after the Printf output before them when
// stdout and stderr share one pipe, around the live progress line, under the verbosity.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>

#include "cli/diagnostic_stream.h"
#include "cli/terminal_progress.h"
#include "interp/interpreter.h"
#include "run_binary.h"
#include "scratch_dir.h"

using sm::cli::DiagnosticStream;
using sm::cli::TerminalProgress;

namespace {

// std::cout over stdout as the CLI has it: an ostream writing into a buffered FILE*.
class FileBuf final : public std::streambuf {
 public:
  explicit FileBuf(std::FILE* f) : f_(f) {}

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) std::fputc(c, f_);
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    return static_cast<std::streamsize>(std::fwrite(s, 1, static_cast<std::size_t>(n), f_));
  }

 private:
  std::FILE* f_;
};


// `2>&1`: a "stdout" and a "stderr" FILE* on one open file, each with its own buffer.
struct SharedPipe {
  std::FILE* err = std::tmpfile();
  std::FILE* out = err ? fdopen(dup(fileno(err)), "w") : nullptr;
  SharedPipe() {
    if (out) std::setvbuf(out, nullptr, _IOFBF, 1 << 16);
  }
  ~SharedPipe() {
    if (out) std::fclose(out);
    if (err) std::fclose(err);
  }
  std::string text() {
    std::fflush(out);
    return sm::testing::read_stream(err);
  }
};


// stdout and stderr of a command through one pipe (`2>&1`).
std::string run_merged(const std::string& cmd) { return sm::testing::run_output(cmd, "2>&1"); }

struct Run {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags{sources};
};

}  // namespace

TEST_CASE("diagnostic stream: Printf, a warning and Printf appear in script order on one pipe") {
  SharedPipe pipe;
  REQUIRE(pipe.out);
  FileBuf buf(pipe.out);
  std::ostream out(&buf);
  Run r;
  sm::interp::Interpreter in(r.sources, r.diags, out);
  r.diags.set_sink(DiagnosticStream(r.diags, pipe.err, out, pipe.out));
  in.run_buffer("order.geo", "Printf(\"a\");\nWarning(\"careful\");\nPrintf(\"b\");\n");
  r.diags.emit_pending();
  const std::string s = pipe.text();
  const auto a = s.find("a\n"), w = s.find("order.geo:2:1: warning: careful [user-warning]"), b = s.find("b\n");
  INFO(s);
  REQUIRE(a != std::string::npos);
  REQUIRE(w != std::string::npos);
  REQUIRE(b != std::string::npos);
  CHECK(a < w);
  CHECK(w < b);
  // Still collected for the --test driver and the unit tests, and printed once.
  CHECK(r.diags.all().size() == 1);
  CHECK(r.diags.emit_pending() == 0);
  CHECK(s.find("warning: careful", s.find("warning: careful") + 1) == std::string::npos);
}

TEST_CASE("diagnostic stream: a warning inside a loop is printed when its statement ends") {
  SharedPipe pipe;
  REQUIRE(pipe.out);
  FileBuf buf(pipe.out);
  std::ostream out(&buf);
  Run r;
  sm::interp::Interpreter in(r.sources, r.diags, out);
  r.diags.set_sink(DiagnosticStream(r.diags, pipe.err, out, pipe.out));
  in.run_buffer("loop.geo", "For i In {1:2}\n  Printf(\"p%g\", i);\n  Warning(\"w%g\", i);\nEndFor\n");
  const std::string s = pipe.text();
  INFO(s);
  const auto p1 = s.find("p1\n"), w1 = s.find("warning: w1"), p2 = s.find("p2\n"), w2 = s.find("warning: w2");
  REQUIRE(w2 != std::string::npos);
  CHECK(p1 < w1);
  CHECK(w1 < p2);
  CHECK(p2 < w2);
  // The warning's note names the loop iteration it came from.
  CHECK(s.find("inside this 'For' loop") != std::string::npos);
}

TEST_CASE("diagnostic stream: warnings follow General.Verbosity when printed; errors always print") {
  SharedPipe pipe;
  REQUIRE(pipe.out);
  FileBuf buf(pipe.out);
  std::ostream out(&buf);
  Run r;
  sm::interp::Interpreter in(r.sources, r.diags, out);
  DiagnosticStream stream(r.diags, pipe.err, out, pipe.out);
  stream.set_show_warnings([&in] { return in.options().number("General.Verbosity") >= 2; });
  r.diags.set_sink(stream);
  in.run_buffer("v.geo", "Warning(\"shown\");\nGeneral.Verbosity = 1;\nWarning(\"hidden\");\nError(\"stop\");\n");
  r.diags.emit_pending();
  const std::string s = pipe.text();
  INFO(s);
  CHECK(s.find("shown") != std::string::npos);
  CHECK(s.find("hidden") == std::string::npos);
  CHECK(s.find("error: stop") != std::string::npos);
  CHECK(r.diags.warning_count() == 2);
}

TEST_CASE("diagnostic stream: the live progress line is cleared before a diagnostic and redrawn after") {
  SharedPipe pipe;
  REQUIRE(pipe.out);
  FileBuf buf(pipe.out);
  std::ostream out(&buf);
  double t = 0;
  TerminalProgress progress(pipe.err, TerminalProgress::Style::Live, [&] { return t; });
  Run r;
  r.diags.set_sink(DiagnosticStream(r.diags, pipe.err, out, pipe.out, &progress));
  progress.begin("2D", 10);
  progress.update(3);
  t += 1;
  progress.update(4);
  r.diags.report_message(sm::lang::SourceRange{}, sm::lang::Diag::UserWarning, "mid-stage");
  r.diags.emit_pending();
  progress.end();
  const std::string s = pipe.text();
  INFO(s);
  const auto w = s.find("stereomesh: warning: mid-stage");
  REQUIRE(w != std::string::npos);
  // Cleared: the characters right before the warning are "\r<blanks>\r".
  REQUIRE(w >= 2);
  CHECK(s[w - 1] == '\r');
  CHECK(s[w - 2] == ' ');
  // Redrawn after it, and finished with a newline at the end of the stage.
  const auto redraw = s.find("\r2D  4/10", w);
  CHECK(redraw != std::string::npos);
  CHECK(s.back() == '\n');
}

TEST_CASE("diagnostic stream: without a sink nothing is emitted and flush still writes everything") {
  Run r;
  r.diags.report_message(sm::lang::SourceRange{}, sm::lang::Diag::UserWarning, "kept");
  CHECK(r.diags.emit_pending() == 0);
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  CHECK(r.diags.flush(f) == 1);
  CHECK(sm::testing::read_stream(f).find("warning: kept") != std::string::npos);
  std::fclose(f);
}

TEST_CASE("diagnostic stream: the binary shows Printf, the warning and Printf in order through 2>&1") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) {
    MESSAGE("skipped: stereomesh binary not built");
    return;
  }
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_diag_stream_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "order.geo") << "Printf(\"a\");\nWarning(\"between\");\nPrintf(\"b\");\n";
  const std::string s = run_merged(bin + " -0 " + (dir / "order.geo").string());
  INFO(s);
  const auto a = s.find("a\n"), w = s.find("warning: between [user-warning]"), b = s.find("b\n", w);
  REQUIRE(a != std::string::npos);
  REQUIRE(w != std::string::npos);
  CHECK(a < w);
  CHECK(b != std::string::npos);
  CHECK(s.rfind("b\n") > w);  // b is written after the warning, not before it
  fs::remove_all(dir);
}

TEST_CASE("diagnostic stream: progress lines come after the Printf output written before them") {
  SharedPipe pipe;
  REQUIRE(pipe.out);
  double t = 0;
  TerminalProgress progress(pipe.err, TerminalProgress::Style::Lines, [&] { return t; });
  progress.flush_first(pipe.out);
  std::fputs("printed\n", pipe.out);
  progress.begin("2D", 1);
  std::fputs("inside\n", pipe.out);
  progress.end();
  const std::string s = pipe.text();
  INFO(s);
  CHECK(s == "printed\nstereomesh: 2D: start (1)\ninside\nstereomesh: 2D: done in 0.000 s\n");
}

TEST_CASE("diagnostic stream: the binary meshing islands: Printf, progress, summary, one island warning, Printf") {
  const std::string bin = sm::testing::stereomesh_binary();
  if (bin.empty()) {
    MESSAGE("skipped: stereomesh binary not built");
    return;
  }
  const std::string s =
      run_merged(bin + " -0 " + std::string(SM_SOURCE_DIR) + "/tests/scripts/diagnostics/fail_islands_warning.geo");
  INFO(s);
  const auto before = s.find("before\n"), start = s.find("stereomesh: 2D: start"), summary = s.find("Mesh: "),
             w = s.find("warning: surface 1: 3 islands smaller than the mesh size are left out"),
             after = s.rfind("1\n");
  REQUIRE(w != std::string::npos);
  CHECK(before < start);
  CHECK(start < summary);
  CHECK(summary < w);
  CHECK(w < after);
  // One warning, not one per island (the source line shown under it quotes the message as
  // "mesh-warning: surface ...", so a warning is matched by its ": warning: " prefix).
  CHECK(s.find(": warning: surface", w + 1) == std::string::npos);
  CHECK(s.find("[mesh-warning]") != std::string::npos);
}
