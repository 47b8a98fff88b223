// A file read block by block with located errors: the text readers parse a large file
// (the whole GSHHG is 225 MB of text) without holding it, so that the import's memory is
// that of the points it keeps (docs/coastlines.md, "Scale").
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

class FileBlocks {
 public:
  static constexpr std::size_t kBlock = std::size_t{1} << 22;   // 4 MB: a few ms of parsing

  FileBlocks() = default;
  FileBlocks(const FileBlocks&) = delete;
  FileBlocks& operator=(const FileBlocks&) = delete;
  ~FileBlocks();

  /// Opens `path` and takes its size; an error says why it cannot be read.
  std::optional<CoastError> open(const std::string& path);
  std::size_t size() const { return size_; }
  /// False for a pipe or a device: no size known beforehand.
  bool regular() const { return regular_; }
  /// What follows the file's last '\n' when the file does not end with one (the whole
  /// file when it holds none); nullopt for an empty file or one ending with '\n'.
  /// Reads from the end, without moving the block position.
  std::optional<Result<std::string>> last_line();
  /// The next block (at most kBlock bytes), empty at the end of the file. The view is
  /// valid until the next call.
  Result<std::string_view> next();

 private:
  std::string path_;
  int fd_ = -1;
  std::size_t size_ = 0;
  bool regular_ = false;
  std::vector<char> buf_;
};

}  // namespace sm::coast
