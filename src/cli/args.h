// Command-line parsing for stereomesh: Gmsh's flags where they exist
// (-0 -1 -2 -o -format -setnumber -clmin -algo ...) plus -I and --test.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sm::cli {

struct CliArgs {
  std::vector<std::string> files;        ///< scripts, or --test paths
  int mesh_dim = -1;                     ///< -0: 0, -1: 1, -2: 2; -1 when not given
  std::string output;                    ///< -o
  std::string stats_file;                ///< --stats FILE.json
  std::string diagnostics_file;          ///< --diagnostics FILE: every diagnostic as JSON lines
  std::string format;                    ///< -format
  std::vector<std::pair<std::string, double>> set_numbers;        ///< -setnumber, in order
  std::vector<std::pair<std::string, std::string>> set_strings;   ///< -setstring
  std::vector<std::pair<std::string, double>> option_numbers;     ///< -clmin, -algo, -bin, -nt, -v ...
  std::vector<std::string> include_dirs;                          ///< -I
  bool help = false;
  bool help_fields = false;   ///< --help-fields: the size-field kinds and options
  bool version = false;
  bool test = false;
};

struct ParseOutcome {
  bool ok = true;
  std::string error;   ///< a usage error message when !ok
  CliArgs args;
};

/// Parses argv[1..]; never exits.
ParseOutcome parse_args(const std::vector<std::string>& argv);

/// The text of --help.
std::string usage_text();

}  // namespace sm::cli
