// The files that `Printf(...) > "f"` and `>> "f"` write: each is kept open as
// one base::OutputFile for the whole run and put in place when the run ends
// without errors, so a failed script or a full disk never leaves a partial
// file, and a loop of `>>` costs one write per line, not a copy of the file.
// Before an Include, or a builtin that reads the file (ListFromFile,
// FileExists, ...), a pending file is put in place, so a script that writes a
// file and then reads it works as in Gmsh.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/output_file.h"
#include "lang/source.h"

namespace sm::interp {

class RedirectFiles {
 public:
  struct Failure {
    lang::SourceRange where;   ///< the file name of the last Printf that wrote it
    std::string path;
    std::string reason;
  };

  /// Writes one line to `path`: `append` (>>) continues the file (its old
  /// content first, when this run has not written it yet); otherwise (>) the
  /// file starts again. False with `reason` when the file cannot be opened.
  bool write_line(const std::string& path, bool append, std::string_view line, lang::SourceRange where,
                  std::string* reason);

  /// Puts `path` in place now if this run has it pending (a builtin is about
  /// to read it); a failure is kept for commit_all() to return.
  void publish(const std::string& path);
  /// Puts every pending file in place; the ones that fail (now or in an
  /// earlier publish) are returned.
  std::vector<Failure> commit_all();
  /// Drops every pending file: the targets stay as they were.
  void abandon_all();
  bool empty() const { return files_.empty(); }

 private:
  struct Pending {
    base::OutputFile file;
    lang::SourceRange where;
  };
  std::map<std::string, std::unique_ptr<Pending>, std::less<>> files_;
  std::vector<Failure> failed_;
};

}  // namespace sm::interp
