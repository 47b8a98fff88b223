// Source files of a run: the text of every loaded script, addressed by FileId,
// and byte-offset locations that become line:column only when a message needs them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/id.h"

namespace sm::lang {

using FileId = Id<struct FileTag>;

/// A position: byte offset into one file's text.
struct SourceLoc {
  FileId file;
  std::uint32_t offset = 0;
};

/// A half-open byte range [begin, end) of one file. An invalid file means
/// "no location" (command-line values, synthesized nodes).
struct SourceRange {
  FileId file;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;

  bool valid() const { return file.valid(); }
  SourceLoc begin_loc() const { return {file, begin}; }
  SourceLoc end_loc() const { return {file, end}; }
};

/// The smallest range covering both (same file; otherwise `a`).
SourceRange join(SourceRange a, SourceRange b);

/// 1-based line and column; the column counts bytes.
struct LineCol {
  std::uint32_t line = 0;
  std::uint32_t col = 0;
};

/// Owns the loaded files. Texts never move once loaded, so string_views and
/// token ranges into them stay valid for the manager's lifetime.
class SourceManager {
 public:

  /// Why a file was not loaded; the caller words it (the kinds Script* and Include* of
  /// diag_kinds.def) with the path it asked for.
  enum class LoadFailure : std::uint8_t { None, IsDirectory, CannotOpen, TooLarge, CannotRead };
  static constexpr std::size_t kMaxFileMiB = 256;
  static constexpr std::size_t kMaxFileBytes = kMaxFileMiB << 20;

  struct LoadResult {
    FileId file;                               ///< valid on success
    LoadFailure failure = LoadFailure::None;   ///< set on failure
    std::string reason;                        ///< CannotOpen: the system's words ("No such file or directory")
  };

  SourceManager();
  ~SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  /// Reads a file from disk; never throws. Files larger than kMaxFileBytes are
  /// rejected (LoadFailure::TooLarge). `path` is kept as given for messages.
  LoadResult load_file(const std::string& path);
  /// Adds an in-memory buffer (tests, `-string`, generated text). Buffers
  /// larger than kMaxFileBytes are rejected like files.
  LoadResult add_buffer(std::string name, std::string text);

  std::size_t file_count() const { return files_.size(); }
  /// The path or buffer name as given at load time (used in messages).
  const std::string& path(FileId f) const;
  std::string_view text(FileId f) const;
  /// The file already loaded from the same canonical path, or invalid. The
  /// interpreter uses it to detect Include cycles without reloading.
  FileId find_loaded(const std::string& path) const;

  LineCol line_col(SourceLoc loc) const;
  /// Text of a 1-based line without its line terminator ("\n", "\r\n").
  std::string_view line_text(FileId f, std::uint32_t line) const;
  std::uint32_t line_count(FileId f) const;

 private:
  struct File;
  const File& file(FileId f) const;
  const std::vector<std::uint32_t>& line_starts(FileId f) const;
  std::vector<std::unique_ptr<File>> files_;
};

}  // namespace sm::lang
