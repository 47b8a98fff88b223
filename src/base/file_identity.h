// Which names mean the same file, and the files a run reads, so that no output of the
// run replaces one of them (`-o` naming the script, --stats naming a data
// file, two outputs naming one file).
#pragma once

#include <string>

namespace sm::base {

/// A key equal for two paths exactly when they name the same file: "-" for standard
/// output; for an existing object (symbolic links followed) its device and inode; for a
/// name that does not exist yet, its parent directory resolved (links followed) and its
/// last component. "" for an empty path.
std::string file_identity(const std::string& path);

/// Input tracking, off unless a program turns it on (the command line does; the Python
/// module, where runs share a process, does not): note_input_file() then remembers
/// each file a run reads (scripts, Included files, data files), and input_named_by()
/// answers which of them a path would replace. Thread-safe.
void track_inputs(bool on);
void note_input_file(const std::string& path);
/// The input (as it was first named) that `path` names, or "" when none (or not tracking).
std::string input_named_by(const std::string& path);

}  // namespace sm::base
