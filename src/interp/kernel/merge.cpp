// `Merge "file";` (Gmsh 4.8.4's MergeFile, Common/OpenFile.cpp): the file is read by its
// extension. A mesh (.msh) becomes discrete points, curves and surfaces of the model
// (merge_mesh.cpp), an STL triangulation a discrete surface, a .pos file a
// post-processing view, a .geo or .opt file is parsed as a script. A file that is missing
// or unreadable is an error at its name (Gmsh stops there too), a view is display only
// (as `View` is), an STL file stops the run at its name (what follows it remeshes the
// surface in 3D, which nothing here does), and the other kinds are reported as not
// supported, each saying what Gmsh would have made of the file.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"

namespace sm::interp {

using namespace sm::lang;

void exec_merge(Interpreter& in, StmtId id, const CommandStmt& c) {
  const Stmt& s = in.ast().stmt(id);
  const std::string name = in.eval_string(c.arg);
  const SourceRange at = in.ast().expr(c.arg).range;
  // Relative to the script (Gmsh: relative to the directory of the file being parsed).
  std::filesystem::path p(name);
  if (p.is_relative()) p = std::filesystem::path(in.sources().path(s.range.file)).parent_path() / p;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec))
    in.fail(at, Diag::CannotMerge, name,
            std::string_view(std::filesystem::exists(p, ec) ? "not a regular file" : "no such file"));
  if (std::ifstream f(p, std::ios::binary); !f || f.peek() == std::ifstream::traits_type::eof())
    in.fail(at, Diag::CannotMerge, name, std::string_view("cannot read it, or it is empty"));
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == ".pos") {
    in.display_only_stmt(id, "Merge of a post-processing view (.pos)");
    return;
  }
  if (ext == ".msh") {
    merge_mesh_file(in, p, name, at);
    return;
  }
  if (ext == ".stl") in.fail(at, Diag::MergeStl, name);
  std::string what;
  if (ext == ".geo" || ext == ".opt")
    what = "it is parsed as a script: use Include";
  else
    what = fmt::format("Gmsh reads the file by its extension ('{}'), and stereomesh reads none yet", ext);
  const auto h = in.diags().report(s.keyword.valid() ? s.keyword : s.range, Diag::NotSupportedYet,
                                   fmt::format("Merge \"{}\"", name),
                                   fmt::format(" (in Gmsh {}): the statement is skipped", what));
  (void)h;
}

}  // namespace sm::interp
