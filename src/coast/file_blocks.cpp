// Block reading with POSIX read/pread (no stdio buffer in between).
#include "coast/file_blocks.h"
#include "base/file_identity.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sm::coast {

FileBlocks::~FileBlocks() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<CoastError> FileBlocks::open(const std::string& path) {
  path_ = path;
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) return CoastError{path, -1, std::string("cannot open: ") + std::strerror(errno), {}};
  base::note_input_file(path);
  struct stat st {};
  if (::fstat(fd_, &st) != 0) return CoastError{path, -1, std::string("cannot open: ") + std::strerror(errno), {}};
  if (S_ISDIR(st.st_mode)) return CoastError{path, -1, "cannot open: Is a directory", {}};
  regular_ = S_ISREG(st.st_mode);
  size_ = regular_ ? static_cast<std::size_t>(st.st_size) : 0;
#ifdef POSIX_FADV_SEQUENTIAL
  ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL);
#endif
  return std::nullopt;
}

std::optional<Result<std::string>> FileBlocks::last_line() {
  if (size_ == 0) return std::nullopt;
  std::string tail;   // grows backwards, block by block, until a '\n' is met
  std::size_t end = size_;
  char chunk[4096];
  while (end > 0) {
    const std::size_t n = end < sizeof chunk ? end : sizeof chunk;
    const ssize_t got = ::pread(fd_, chunk, n, static_cast<off_t>(end - n));
    if (got != static_cast<ssize_t>(n)) return Result<std::string>(CoastError{path_, -1, "read error", {}});
    if (end == size_ && chunk[n - 1] == '\n') return std::nullopt;
    std::size_t i = n;
    while (i > 0 && chunk[i - 1] != '\n') --i;
    if (i > 0) {
      tail.insert(0, chunk + i, n - i);
      return Result<std::string>(std::move(tail));
    }
    tail.insert(0, chunk, n);
    end -= n;
  }
  return Result<std::string>(std::move(tail));
}

Result<std::string_view> FileBlocks::next() {
  buf_.resize(kBlock);
  std::size_t have = 0;
  while (have < kBlock) {   // a short read is not the end: fill the block or meet the end
    const ssize_t got = ::read(fd_, buf_.data() + have, kBlock - have);
    if (got < 0) {
      if (errno == EINTR) continue;
      return CoastError{path_, -1, std::string("read error: ") + std::strerror(errno), {}};
    }
    if (got == 0) break;
    have += static_cast<std::size_t>(got);
  }
  return std::string_view(buf_.data(), have);
}

}  // namespace sm::coast
