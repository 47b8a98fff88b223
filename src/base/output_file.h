// The one way every output file is written (meshes, pictures, ocean grids, the
// statistics JSON, Printf > file, the GSHHS plugin's .geo): readers never see
// a partial file, a failed or interrupted write leaves the old file as it was,
// and what a path names is respected.
//
//   path names                         bytes go to
//   "-"                                standard output, directly
//   /dev/stdout, /dev/fd/N, ...        that descriptor, directly
//   a FIFO, a device, a socket         the object itself, directly (never renamed over)
//   a regular file, or nothing yet     a temporary file in the directory of the final
//   (through any symbolic links)       target (links resolved), renamed over it at commit
//
// The temporary file is unnamed where the system allows (O_TMPFILE): a new target
// is linked in place directly, and an existing one is replaced through a name held
// only for the instant before the rename. Elsewhere the bytes go to a named
// temporary. Either name is ".<name>.stereomesh-tmp-<pid>-<suffix>" beside the
// target, removed on SIGINT and SIGTERM (base/interrupt_cleanup.h) and when the write
// fails or is abandoned; one a SIGKILL left behind is removed by the next write of
// the same target once its pid is no longer running.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sm::base {

class OutputFile {
 public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();  // abandons the write unless committed

  /// Starts writing `path`. On failure returns false and error() says why
  /// ("Permission denied", "is a directory", "too many levels of symbolic
  /// links"): the reason only, callers say "cannot write 'PATH': REASON" once.
  bool open(const std::string& path);
  /// By default open() refuses a file the run read (base/file_identity.h, when input
  /// tracking is on). Printf > FILE may write one: a script that Includes what it wrote
  /// and writes it again is Gmsh's way of generating files.
  void allow_inputs(bool on = true) { allow_inputs_ = on; }
  bool write(const void* data, std::size_t size);
  bool write(std::string_view text) { return write(text.data(), text.size()); }

  /// Flushes and syncs, then puts the file in place (rename). False with
  /// error() if any write failed or the disk is full; the target is then as
  /// it was (for direct targets such as a FIFO, what was written stays written).
  bool commit();
  void abandon();

  /// The two halves of commit(), for several files that must appear together
  /// (commit_together): prepare() makes the data durable, publish() renames.
  bool prepare();
  bool publish();

  /// True when the bytes go straight to the target (standard output, a FIFO,
  /// a device): no temporary file, no rename.
  bool direct() const { return direct_; }
  /// The file that will hold the bytes once committed (symbolic links resolved).
  const std::string& target() const { return target_; }
  const std::string& error() const { return error_; }

 private:
  bool fail(std::string_view what, int err);
  bool open_temporary();

  int fd_ = -1;
  bool owns_fd_ = true;      // false for standard output and dup'ed descriptors we may not sync
  bool direct_ = false;
  bool anonymous_ = false;   // O_TMPFILE: no name until publish()
  bool prepared_ = false;
  bool failed_ = false;
  bool allow_inputs_ = false;
  int cleanup_slot_ = -1;    // the interrupt-cleanup entry of a named temporary
  std::string target_;
  std::string temp_path_;
  std::string error_;
  std::vector<char> buffer_;   // small writes are gathered into 64 KiB write(2) calls
  bool flush_buffer();
};

/// True when `path` is written in place rather than replaced: "-", a named
/// descriptor, or an existing FIFO, device or socket (through links). Such a
/// path has no extension to choose a format by; callers pick their default.
bool writes_in_place(const std::string& path);

/// Commits several files as one: none is renamed into place until every one
/// was written and synced, so a failure in any leaves all targets as they were.
/// On failure returns the index of the file that failed (its error() says why).
/// Only the renames themselves, run last and back to back, are not undone.
bool commit_together(std::span<OutputFile* const> files, std::size_t* failed_index);

}  // namespace sm::base
