// The flag table (see flags.h). A flag's behaviour is in args.cpp's parse_args; what it
// does for the user is said here once.
#include "cli/flags.h"

#include <fmt/format.h>

#include "cli/diagnostic_stream.h"
#include "io/output_format.h"
#include "mesh/mesh2d_algorithms.h"

namespace sm::cli {

const std::vector<CliFlag>& cli_flags() {
  static const std::vector<CliFlag> kFlags = {
      {{"-0"}, "-0", "evaluate the scripts only, write nothing"},
      {{"-1", "-2"}, "-1, -2",
       "mesh the curves / the surfaces after the scripts, print the mesh summary and write the mesh (-o FILE)"},
      {{"-o"}, "-o FILE", "output mesh file ('-' for standard output)"},
      {{"-format"}, "-format NAME",
       // output_format_help lists io/output_format.h's rows; the words are rewrapped here.
       io::output_format_help(0, 1000)},
      {{"-bin"}, "-bin", "binary output (Mesh.Binary = 1)"},
      {{"-coords"}, "-coords NAME",
       "node coordinates of MSH/VTK files: xyz (3D, default), lonlat (degrees, z = 0) or stereo (stereographic "
       "plane) (Mesh.NodeCoordinates)"},
      {{"-setnumber"}, "-setnumber NAME V", "define variable NAME (wins over DefineConstant) or set option NAME"},
      {{"-setstring"}, "-setstring NAME S", "the same with a string"},
      {{"-clmin", "-clmax"}, "-clmin X, -clmax X", "Mesh.MeshSizeMin / Mesh.MeshSizeMax"},
      {{"-clscale"}, "-clscale X", "Mesh.MeshSizeFactor"},
      {{"-algo"}, "-algo NAME", mesh2d_algorithm_help()},
      {{"-part"}, "-part N", "partition the 2D mesh into N parts with METIS (Mesh.NbPartitions)"},
      {{"-nt"}, "-nt N", "General.NumThreads"},
      {{"-v"}, "-v N",
       fmt::format("General.Verbosity (0 silent ... 5 default, <2 hides warnings, <4 hides the progress display "
                   "and the mesh summary, >={:g} lists every one of a statement's many warnings where 5 counts "
                   "them and shows a few)",
                   kVerbosityListAll)},
      {{"--stats"}, "--stats FILE.json",
       "after -1 or -2 (or 'Mesh 1;' / 'Mesh 2;'), write the last mesh's statistics as JSON"},
      {{"--diagnostics"}, "--diagnostics FILE",
       "write every diagnostic of the run as JSON lines (file, line, col, severity, kind, message, lon/lat when "
       "known), nothing grouped or cut"},
      {{"-I"}, "-I DIR", "add DIR to the Include search path (also -IDIR)"},
      {{"--test"}, "--test PATH...", "run the script tests under PATH (see docs/interpreter.md)"},
      {{"--help-fields"}, "--help-fields", "list the size-field kinds and their options (docs/fields.md)"},
      {{"--help", "-help", "-h"}, "--help, -h", "this text"},
      {{"--version", "-version"}, "--version", "the version"},
  };
  return kFlags;
}

const CliFlag* find_flag(std::string_view name) {
  for (const CliFlag& f : cli_flags())
    for (std::string_view n : f.names)
      if (n == name) return &f;
  return nullptr;
}

}  // namespace sm::cli
