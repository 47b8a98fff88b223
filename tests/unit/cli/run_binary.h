// Running the stereomesh binary built beside the test executables (build/stereomesh next to
// build/tests/), for the CLI tests that check exit statuses and what reaches stderr.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace sm::testing {

/// The stereomesh built with the tests, or "" when it is not built (tests then skip).
inline std::string stereomesh_binary() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const auto bin = self.parent_path().parent_path() / "stereomesh";
  return std::filesystem::exists(bin, ec) ? bin.string() : "";
}

/// What `cmd redirect` writes to its stdout, e.g. redirect "2>&1 >/dev/null" for stderr
/// alone, "2>&1" for both streams through one pipe.
inline std::string run_output(const std::string& cmd, const std::string& redirect) {
  std::FILE* p = ::popen((cmd + " " + redirect).c_str(), "r");
  if (!p) return "popen failed";
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  ::pclose(p);
  return out;
}

/// The exit status of cmd (output dropped), -1 when it did not exit normally.
inline int run_status(const std::string& cmd) {
  const int st = std::system((cmd + " >/dev/null 2>&1").c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace sm::testing
