// stereomesh entry point: runs scripts or the script tests and maps the outcome
// to the exit status (0 ok, 1 script error, 2 usage error, 3 internal error).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string_view>

#include <fmt/format.h>

#include "base/file_identity.h"
#include "base/interrupt_cleanup.h"
#include "base/output_file.h"
#include "base/share_dir.h"
#include "cli/args.h"
#include "cli/diagnostic_stream.h"
#include "cli/terminal_progress.h"
#include "field/registry.h"
#include "interp/kernel/mesh_commands.h"
#include "interp/interpreter.h"
#include "interp/script_test.h"
#include "lang/diagnostics_json.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitScriptError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

std::vector<std::string> split_path_list(const char* s) {
  std::vector<std::string> out;
  if (!s) return out;
  std::string cur;
  for (const char* p = s;; ++p) {
    if (*p == ':' || *p == '\0') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      if (*p == '\0') break;
    } else {
      cur += *p;
    }
  }
  return out;
}

// --diagnostics FILE: every diagnostic as a JSON line, written atomically.
bool write_diagnostics(const sm::lang::Diagnostics& diags, const std::string& path) {
  sm::base::OutputFile out;
  bool ok = out.open(path);
  for (const sm::lang::Diagnostic& d : diags.all()) {
    if (!ok) break;
    ok = out.write(sm::lang::diagnostic_json_line(diags.sources(), d));
  }
  if (ok && out.commit()) return true;
  std::fprintf(stderr, "stereomesh: error: cannot write '%s': %s\n", path.c_str(), out.error().c_str());
  return false;
}

// Outputs that would replace an input or each other, known before the run: -o (or the
// mesh's default name, beside the first script), --stats and --diagnostics against the
// scripts and against each other (the same file through any links or names; a device or
// FIFO such as /dev/null may be shared), and "-" for more than one of them. Included and
// data files are known only as they are read: OutputFile refuses those when the output
// is written. "" when all is well.
std::string clobber_check(const sm::cli::CliArgs& a) {
  if (a.test) return {};
  struct Out {
    const char* flag;
    std::string path;
  };
  std::vector<Out> outs;
  if (!a.output.empty()) outs.push_back({"-o", a.output});
  else if (a.mesh_dim >= 1 && !a.files.empty())
    outs.push_back({"the mesh (no -o)", sm::interp::default_mesh_output(a.files.front(), a.format)});
  if (!a.stats_file.empty()) outs.push_back({"--stats", a.stats_file});
  if (!a.diagnostics_file.empty()) outs.push_back({"--diagnostics", a.diagnostics_file});
  for (std::size_t i = 0; i < outs.size(); ++i) {
    const std::string id = sm::base::file_identity(outs[i].path);
    for (const std::string& f : a.files)
      if (id == sm::base::file_identity(f))
        return std::string_view(outs[i].flag) == "the mesh (no -o)"
                   ? fmt::format("the mesh would be written to '{}', which is the script: name the mesh file with -o",
                                 outs[i].path)
                   : fmt::format("{} '{}' is the script '{}': an output may not replace an input", outs[i].flag,
                                 outs[i].path, f);
    // Two outputs to one device or FIFO (/dev/null) write in turn, in place: only '-' and
    // files (replaced whole at commit) may not be shared.
    if (outs[i].path != "-" && sm::base::writes_in_place(outs[i].path)) continue;
    for (std::size_t j = 0; j < i; ++j)
      if (id == sm::base::file_identity(outs[j].path))
        return outs[i].path == "-"
                   ? fmt::format("{} and {} both write to standard output ('-'): only one output may", outs[j].flag,
                                 outs[i].flag)
                   : fmt::format("{} '{}' and {} '{}' are the same file: each output needs its own", outs[j].flag,
                                 outs[j].path, outs[i].flag, outs[i].path);
  }
  return {};
}

int run(const std::vector<std::string>& argv) {
  const sm::cli::ParseOutcome parsed = sm::cli::parse_args(argv);
  if (!parsed.ok) {
    std::fprintf(stderr, "stereomesh: %s\n%s", parsed.error.c_str(), "try 'stereomesh --help'\n");
    return kExitUsage;
  }
  const sm::cli::CliArgs& a = parsed.args;
  if (a.help) {
    std::fputs(sm::cli::usage_text().c_str(), stdout);
    return kExitOk;
  }
  if (a.help_fields) {
    std::fputs(sm::field::registry_markdown().c_str(), stdout);
    return kExitOk;
  }
  // The stdlib and the shipped data sit beside the binary (installed prefix or build tree).
  const std::filesystem::path share = sm::base::find_share_dir(sm::base::executable_path());
  if (a.version) {
    std::printf("stereomesh %s (Gmsh 4.8.4-compatible .geo language)\n", STEREOMESH_VERSION);
    if (share.empty()) {
      std::printf("stdlib: not found (no share/stereomesh/stdlib beside %s)\n",
                  sm::base::executable_path().string().c_str());
    } else {
      std::printf("stdlib: %s\ndata:   %s\n", (share / "stdlib").string().c_str(),
                  (share / "data").string().c_str());
    }
    return kExitOk;
  }
  if (const std::string why = clobber_check(a); !why.empty()) {
    std::fprintf(stderr, "stereomesh: %s\n%s", why.c_str(), "try 'stereomesh --help'\n");
    return kExitUsage;
  }
  sm::interp::RunSettings settings;
  settings.include_dirs = a.include_dirs;
  if (!share.empty()) settings.stdlib_dir = (share / "stdlib").string();
  settings.search_path = split_path_list(std::getenv("STEREOMESH_PATH"));
  if (a.test) {
    const int failed = sm::interp::run_script_tests(a.files, settings, std::cout);
    std::cout.flush();
    if (failed < 0) return kExitUsage;
    return failed == 0 ? kExitOk : kExitScriptError;
  }

  // From here on every file the run reads is noted, and no output may replace one. (Not
  // for --test above: its scripts are separate runs in one process.)
  sm::base::track_inputs(true);
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  // Long stages (coastline import, 1D, 2D) report here; General.Verbosity < 4 silences it.
  sm::cli::TerminalProgress progress(stderr, sm::cli::TerminalProgress::style_for(stderr));
  // With '-o -' the mesh is standard output, so Printf's lines go to stderr.
  const bool mesh_to_stdout = a.output == "-";
  std::ostream& printf_out = mesh_to_stdout ? std::cerr : std::cout;
  sm::interp::Interpreter interp(sources, diags, printf_out, settings);
  progress.flush_first(stdout);
  interp.kernel().progress = &progress;
  // Diagnostics are printed when the statement that caused them ends (flushing Printf's
  // stdout first and clearing the live progress line), not after the whole run.
  sm::cli::DiagnosticStream stream(diags, stderr, printf_out, stdout, &progress);
  stream.set_show_warnings([&interp] { return interp.options().number("General.Verbosity") >= 2; });
  stream.set_list_all(
      [&interp] { return interp.options().number("General.Verbosity") >= sm::cli::kVerbosityListAll; });
  diags.set_sink(stream);
  for (const auto& [name, v] : a.option_numbers) {
    if (auto err = interp.options().set_number(name, v); !err.empty()) {
      std::fprintf(stderr, "stereomesh: %s\n", err.message.c_str());
      return kExitUsage;
    }
  }
  for (const auto& [name, v] : a.set_numbers) {
    if (auto err = interp.preset_number(name, v); !err.empty()) {
      std::fprintf(stderr, "stereomesh: -setnumber: %s\n", err.message.c_str());
      return kExitUsage;
    }
  }
  for (const auto& [name, v] : a.set_strings) {
    if (auto err = interp.preset_string(name, v); !err.empty()) {
      std::fprintf(stderr, "stereomesh: -setstring: %s\n", err.message.c_str());
      return kExitUsage;
    }
  }
  bool errors = false;
  for (const std::string& f : a.files) {
    if (interp.run_file(f) == sm::interp::RunStatus::Errors) errors = true;
    diags.emit_pending();
    if (errors || interp.stopped()) break;
  }
  // -1: mesh what the scripts built and write it (unless they failed or called Exit).
  if (!errors && !interp.stopped() && interp.exit_request() < 0 && a.mesh_dim >= 1 && !a.files.empty() &&
      !sm::interp::mesh_from_command_line(interp, a.mesh_dim, a.output, a.format, a.files.front()))
    errors = true;
  // The run's time account (the Time: line; a failed run ends with its errors instead),
  // and the statistics with it as JSON for --stats, written atomically.
  const std::string json = sm::interp::finish_run(interp, !errors);
  if (!errors && !a.stats_file.empty()) {
    sm::base::OutputFile out;
    if (json.empty()) {
      std::fprintf(stderr, "stereomesh: --stats: no mesh was made (use -1, -2, 'Mesh 1;' or 'Mesh 2;')\n");
      errors = true;
    } else if (!out.open(a.stats_file) || !out.write(json) || !out.write("\n") || !out.commit()) {
      std::fprintf(stderr, "stereomesh: error: cannot write '%s': %s\n", a.stats_file.c_str(), out.error().c_str());
      errors = true;
    }
  }
  diags.emit_pending();
  // Every diagnostic of the run, nothing grouped or cut, whatever the verbosity; written
  // when the run failed too, since that is when they are wanted.
  if (!a.diagnostics_file.empty() && !write_diagnostics(diags, a.diagnostics_file)) errors = true;
  std::cout.flush();
  if (interp.exit_request() >= 0) return interp.exit_request();
  if (errors) return kExitScriptError;
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or a kill during a write removes the named temporary file (where the
  // system has no unnamed ones); the exit status still says which signal it was.
  sm::base::install_interrupt_cleanup();
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::bad_alloc&) {
    std::fputs("stereomesh: internal error: out of memory\n", stderr);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereomesh: internal error: %s\n", e.what());
  }
  return kExitInternal;
}
