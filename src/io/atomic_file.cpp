// Temporary-then-rename file writing (see atomic_file.h).
#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace sm::io {

AtomicFile::~AtomicFile() { abandon(); }

bool AtomicFile::fail(const std::string& what) {
  if (!failed_) error_ = what.empty() ? std::string(std::strerror(errno)) : what + ": " + std::strerror(errno);
  failed_ = true;
  return false;
}

bool AtomicFile::open(const std::string& path) {
  abandon();
  path_ = path;
  error_.clear();
  failed_ = false;
  // mkstemp in the target's own directory, so that the final rename stays on
  // one file system and is atomic.
  std::string templ = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(templ.data());
  if (fd < 0) return fail("");
  ::fchmod(fd, 0644);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    ::close(fd);
    ::unlink(templ.c_str());
    return fail("");
  }
  temp_path_ = templ;
  return true;
}

bool AtomicFile::write(const void* data, std::size_t size) {
  if (failed_ || !file_) return false;
  if (size && std::fwrite(data, 1, size, file_) != size) return fail("");
  return true;
}

bool AtomicFile::commit() {
  if (!file_) return fail("");
  if (!failed_ && std::fflush(file_) != 0) fail("");
  if (!failed_ && ::fsync(::fileno(file_)) != 0) fail("");
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed && !failed_) fail("");
  if (!failed_ && std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    fail("cannot rename the temporary file over it");
  if (failed_) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
    return false;
  }
  temp_path_.clear();
  return true;
}

void AtomicFile::abandon() {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

}  // namespace sm::io
