// Writing a file so that readers never see a partial one: the bytes go to a
// temporary file in the target's directory, which is renamed over the target
// only once everything was written and flushed. A failed or abandoned write
// removes the temporary and leaves any previous file untouched.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace sm::io {

class AtomicFile {
 public:
  AtomicFile() = default;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // abandons (removes the temporary) unless committed

  /// Creates the temporary file next to `path`. On failure returns false and
  /// error() says why (e.g. the directory is read-only or missing).
  /// error() is the reason only ("Permission denied"), without the file name:
  /// callers say "cannot write 'PATH': REASON" once.
  bool open(const std::string& path);
  bool write(const void* data, std::size_t size);
  bool write(std::string_view text) { return write(text.data(), text.size()); }
  /// Flushes, closes and renames over the target. False (with error()) if any
  /// earlier write failed or the disk is full; the target is then untouched.
  bool commit();
  void abandon();

  const std::string& error() const { return error_; }

 private:
  bool fail(const std::string& what);

  std::FILE* file_ = nullptr;
  std::string path_;
  std::string temp_path_;
  std::string error_;
  bool failed_ = false;
};

}  // namespace sm::io
