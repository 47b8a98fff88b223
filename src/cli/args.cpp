// Command-line parsing (see args.h). Numbers must be complete and finite:
// `-clmax 1e3x` is a usage error, not 1000.
#include "cli/args.h"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "cli/flags.h"
#include "io/node_coordinates.h"
#include "io/output_format.h"
#include "mesh/mesh2d_algorithms.h"

namespace sm::cli {

namespace {

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && std::isfinite(out);
}

}  // namespace

std::string usage_text() {
  // Each flag as "  SHOWN" padded to column kHelpColumn, then its help wrapped before
  // kHelpWidth columns and continued at kHelpColumn.
  constexpr std::size_t kHelpColumn = 22, kHelpWidth = 100;
  std::string out =
      "usage: stereomesh [options] FILE.geo...\n"
      "       stereomesh --test DIR|FILE...\n"
      "\n"
      "Runs Gmsh 4.8.4-compatible .geo scripts (Printf output on stdout,\n"
      "diagnostics on stderr).\n"
      "\n";
  for (const CliFlag& f : cli_flags()) {
    std::string line = "  " + std::string(f.shown);
    if (line.size() + 2 > kHelpColumn) {   // too long to share its line with the help
      out += line + "\n";
      line.clear();
    }
    line.resize(kHelpColumn, ' ');
    std::size_t column = kHelpColumn;
    bool first = true;
    for (std::size_t i = 0; i < f.help.size();) {
      const std::size_t j = std::min(f.help.find(' ', i), f.help.size());
      const std::string_view word(f.help.data() + i, j - i);
      i = j + 1;
      if (word.empty()) continue;
      if (!first && column + 1 + word.size() > kHelpWidth) {
        out += line + "\n";
        line.assign(kHelpColumn, ' ');
        column = kHelpColumn;
      } else if (!first) {
        line += ' ';
        ++column;
      }
      line += word;
      column += word.size();
      first = false;
    }
    out += line + "\n";
  }
  out +=
      "\n"
      "Include search order: the including file's directory, -I directories,\n"
      "$STEREOMESH_PATH (':'-separated), the installed stdlib/.\n"
      "Exit status: 0 success, 1 script error, 2 usage error, 3 internal error\n"
      "(Exit n; in a script exits with n).\n";
  return out;
}

ParseOutcome parse_args(const std::vector<std::string>& argv) {
  ParseOutcome r;
  CliArgs& a = r.args;
  auto fail = [&](std::string msg) {
    r.ok = false;
    r.error = std::move(msg);
    return r;
  };
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    auto value = [&](const char* what, std::string& out) {
      if (i + 1 >= argv.size()) return false;
      out = argv[++i];
      (void)what;
      return true;
    };
    auto number_opt = [&](const char* option_name) -> bool {
      std::string v;
      double d = 0;
      if (!value(option_name, v) || !parse_number(v, d)) return false;
      a.option_numbers.emplace_back(option_name, d);
      return true;
    };
    // Only the table's flags exist (the one exception: -IDIR, -I glued to its value).
    const bool flag = !arg.empty() && arg[0] == '-';
    // Gmsh's -3: volumes (Volume, Extrude of a surface) are kept as entities only.
    if (arg == "-3")
      return fail("'-3': 3D meshing is not supported (volumes are kept as entities only): use -2 for the mesh of the "
                  "surfaces");
    if (flag && !find_flag(arg) && !(arg.size() > 2 && arg.rfind("-I", 0) == 0))
      return fail(fmt::format("unknown option '{}'", arg));
    if (a.test && !flag) {
      a.files.push_back(arg);
    } else if (arg == "--help" || arg == "-help" || arg == "-h") {
      a.help = true;
    } else if (arg == "--help-fields") {
      a.help_fields = true;
    } else if (arg == "--version" || arg == "-version") {
      a.version = true;
    } else if (arg == "--test") {
      a.test = true;
    } else if (arg == "-0" || arg == "-1" || arg == "-2") {
      a.mesh_dim = arg[1] - '0';
    } else if (arg == "--stats") {
      if (!value("--stats", a.stats_file)) return fail("'--stats' needs a file name");
      if (a.stats_file.empty()) return fail("'--stats' needs a file name, not an empty one");
    } else if (arg == "--diagnostics") {
      if (!value("--diagnostics", a.diagnostics_file)) return fail("'--diagnostics' needs a file name");
      if (a.diagnostics_file.empty()) return fail("'--diagnostics' needs a file name, not an empty one");
    } else if (arg == "-o") {
      if (!value("-o", a.output)) return fail("'-o' needs a file name");
      if (a.output.empty()) return fail("'-o' needs a file name, not an empty one");
    } else if (arg == "-format") {
      if (!value("-format", a.format)) return fail("'-format' needs a format name");
      const io::OutputFormat* f = io::find_output_format(a.format);
      if (!f) return fail(fmt::format("unknown format '{}' ({})", a.format, io::output_format_names()));
      // Gmsh has no mesh format number for the pictures or the ocean-model
      // grids: they are chosen by name.
      if (f->mesh_format != 0) a.option_numbers.emplace_back("Mesh.Format", f->mesh_format);
      if (f->msh_file_version != 0) a.option_numbers.emplace_back("Mesh.MshFileVersion", f->msh_file_version);
    } else if (arg == "-coords") {
      std::string name;
      if (!value("-coords", name)) return fail("'-coords' needs xyz, lonlat or stereo");
      const std::optional<io::NodeCoordinates> mode = io::node_coordinates_from_name(name);
      if (!mode) return fail(fmt::format("unknown node coordinates '{}' (xyz, lonlat, stereo)", name));
      a.option_numbers.emplace_back("Mesh.NodeCoordinates", static_cast<int>(*mode));
    } else if (arg == "-bin") {
      a.option_numbers.emplace_back("Mesh.Binary", 1);
    } else if (arg == "-setnumber") {
      if (i + 2 >= argv.size()) return fail("'-setnumber' needs a name and a value");
      double d = 0;
      if (!parse_number(argv[i + 2], d))
        return fail(fmt::format("'-setnumber {}': '{}' is not a number", argv[i + 1], argv[i + 2]));
      a.set_numbers.emplace_back(argv[i + 1], d);
      i += 2;
    } else if (arg == "-setstring") {
      if (i + 2 >= argv.size()) return fail("'-setstring' needs a name and a value");
      a.set_strings.emplace_back(argv[i + 1], argv[i + 2]);
      i += 2;
    } else if (arg == "-clmin") {
      if (!number_opt("Mesh.MeshSizeMin")) return fail("'-clmin' needs a number");
    } else if (arg == "-clmax") {
      if (!number_opt("Mesh.MeshSizeMax")) return fail("'-clmax' needs a number");
    } else if (arg == "-clscale") {
      if (!number_opt("Mesh.MeshSizeFactor")) return fail("'-clscale' needs a number");
    } else if (arg == "-part") {
      // Gmsh's -part N: Mesh.NbPartitions = N, the 2D mesh partitioned after meshing.
      std::string text;
      double d = 0;
      if (!value("-part", text) || !parse_number(text, d) || d < 1 || d != std::floor(d) || d > 1e6)
        return fail(fmt::format("'-part' needs a whole number of partitions, 1 or more{}",
                                text.empty() ? "" : fmt::format(" (not '{}')", text)));
      a.option_numbers.emplace_back("Mesh.NbPartitions", d);
    } else if (arg == "-nt") {
      if (!number_opt("General.NumThreads")) return fail("'-nt' needs a number");
    } else if (arg == "-v") {
      if (!number_opt("General.Verbosity")) return fail("'-v' needs a number");
    } else if (arg == "-algo") {
      std::string name;
      if (!value("-algo", name)) return fail("'-algo' needs an algorithm name");
      // A row of mesh/mesh2d_algorithms.h; Gmsh's initial2d, bamg and pack are refused here
      // rather than accepted and refused once the script has run.
      const Mesh2dAlgorithmRow* row = mesh2d_algorithm_named(name);
      if (!row)
        return fail(fmt::format("unknown algorithm '{}': stereomesh has {}", name, mesh2d_algorithm_names(" and ")));
      a.option_numbers.emplace_back("Mesh.Algorithm", row->number);
    } else if (arg == "-I") {
      std::string dir;
      if (!value("-I", dir)) return fail("'-I' needs a directory");
      a.include_dirs.push_back(dir);
    } else if (arg.size() > 2 && arg.rfind("-I", 0) == 0) {
      a.include_dirs.push_back(arg.substr(2));
    } else if (flag) {
      // In the table but handled by no branch above: a flag added to flags.cpp only.
      return fail(fmt::format(
          "internal error: '{}' is in the flag table (cli/flags.cpp) but parse_args has no branch for it", arg));
    } else {
      a.files.push_back(arg);
    }
  }
  if (!a.help && !a.help_fields && !a.version && a.files.empty())
    return fail(a.test ? "'--test' needs a directory or file" : "no input file");
  return r;
}

}  // namespace sm::cli
