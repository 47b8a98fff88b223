// OutputFile: where the bytes of an output path go, and how they are put in
// place (see output_file.h for the table of cases).
#include "base/output_file.h"

#include "base/file_identity.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>

#include <fmt/format.h>

#include "base/interrupt_cleanup.h"

namespace sm::base {

namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
constexpr int kMaxLinkHops = 40;   // as the kernel's own limit (ELOOP)
constexpr int kMaxSweepEntries = 1 << 24;

std::string dir_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// The file a path finally names: symbolic links followed (also a dangling
// one, whose target is then created), so that the rename replaces the file a
// link points to and never the link itself. Empty with errno on failure.
std::string resolve_links(std::string path) {
  for (int hop = 0; hop <= kMaxLinkHops; ++hop) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
      if (errno == ENOENT) return path;   // to be created
      return {};
    }
    if (!S_ISLNK(st.st_mode)) return path;
    std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(path.c_str(), link.data(), link.size());
    if (n < 0) return {};
    link.resize(static_cast<std::size_t>(n));
    path = (!link.empty() && link.front() == '/') ? link : dir_of(path) + "/" + link;
  }
  errno = ELOOP;
  return {};
}

// A descriptor named as a path (/dev/stdout, /dev/fd/3, /proc/self/fd/1):
// written as it is, never replaced. -1 if the path names none.
int named_descriptor(const std::string& path) {
  if (path == "/dev/stdout") return STDOUT_FILENO;
  if (path == "/dev/stderr") return STDERR_FILENO;
  for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (path.rfind(prefix, 0) != 0) continue;
    int fd = -1;
    const char* first = path.data() + prefix.size();
    const char* last = path.data() + path.size();
    const auto r = std::from_chars(first, last, fd);
    if (r.ec == std::errc() && r.ptr == last && fd >= 0) return fd;
  }
  return -1;
}

// The mode a new file gets from open(2): 0666 less the umask. umask(2) can
// only be read by setting it, so it is set back at once.
mode_t new_file_mode() {
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return 0666 & ~mask;
}

// Temporary names: "<dir>/.<name>.stereomesh-tmp-<pid>-<suffix>" beside the target
// "<dir>/<name>". A SIGKILL can leave one behind (the fallback writes under it; the
// unnamed file has it for the instant before the rename), so every open of the same
// target first removes those whose process is gone: the prefix says which target a
// file was for, the pid whether its writer may still be running.
std::string temporary_prefix(const std::string& target) {
  const std::size_t slash = target.find_last_of('/');
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  return "." + name + ".stereomesh-tmp-";
}

// The pid of a temporary named `entry` for the target with that prefix, or 0 when the name
// is not exactly prefix, decimal pid, '-', letters and digits (what this file makes).
pid_t temporary_owner(std::string_view entry, std::string_view prefix) {
  if (entry.size() <= prefix.size() || entry.substr(0, prefix.size()) != prefix) return 0;
  const char* first = entry.data() + prefix.size();
  const char* last = entry.data() + entry.size();
  long pid = 0;
  const auto r = std::from_chars(first, last, pid);
  if (r.ec != std::errc() || r.ptr == first || pid <= 0 || r.ptr == last || *r.ptr != '-') return 0;
  const char* suffix = r.ptr + 1;
  if (suffix == last) return 0;
  for (const char* c = suffix; c != last; ++c)
    if (!std::isalnum(static_cast<unsigned char>(*c))) return 0;
  return static_cast<pid_t>(pid);
}

// Removes the temporaries of `target` left by runs that were killed: regular files of
// ours, named by our pattern, whose pid is not a live process. A temporary of a live
// process (another run writing the same file, or this one) is never touched; a pid
// reused since only keeps a stale file until the next run. Best effort: a directory
// that cannot be listed changes nothing (open_temporary reports the real problem).
void sweep_stale_temporaries(const std::string& target) {
  const std::string dir = dir_of(target);
  const std::string prefix = temporary_prefix(target);
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  const uid_t me = ::geteuid();
  // readdir ends at the directory's last entry; the bound only guards a directory that
  // keeps growing while it is listed.
  for (int k = 0; k < kMaxSweepEntries; ++k) {
    const dirent* e = ::readdir(d);
    if (e == nullptr) break;
    const pid_t pid = temporary_owner(e->d_name, prefix);
    if (pid == 0 || pid == ::getpid()) continue;
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;   // alive, or not ours to ask about
    struct stat st {};
    if (::fstatat(::dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    if (!S_ISREG(st.st_mode) || st.st_uid != me) continue;
    ::unlinkat(::dirfd(d), e->d_name, 0);
  }
  ::closedir(d);
}

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

OutputFile::~OutputFile() { abandon(); }

bool OutputFile::fail(std::string_view what, int err) {
  if (!failed_)
    error_ = what.empty() ? std::string(std::strerror(err)) : fmt::format("{}: {}", what, std::strerror(err));
  failed_ = true;
  return false;
}

bool OutputFile::open(const std::string& path) {
  abandon();
  owns_fd_ = true;
  direct_ = false;
  anonymous_ = false;
  prepared_ = false;
  failed_ = false;
  target_.clear();
  error_.clear();
  buffer_.reserve(kBufferBytes);
  if (path.empty()) {
    error_ = "the file name is empty";
    failed_ = true;
    return false;
  }
  if (path == "-" || named_descriptor(path) >= 0) {
    const int fd = path == "-" ? STDOUT_FILENO : named_descriptor(path);
    if (::fcntl(fd, F_GETFD) < 0) return fail("no such open descriptor", errno);
    fd_ = fd;
    owns_fd_ = false;
    direct_ = true;
    target_ = path == "-" ? "standard output" : path;
    return true;
  }
  target_ = resolve_links(path);
  if (target_.empty()) return fail("", errno);
  // A file this run read (the script, an Included file, a data file) is never replaced.
  if (const std::string in = allow_inputs_ ? std::string() : input_named_by(path); !in.empty()) {
    error_ = in == path ? "it is an input of this run" : "it is '" + in + "', an input of this run";
    failed_ = true;
    return false;
  }
  struct stat st {};
  const bool exists = ::stat(target_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) {
    error_ = "it is a directory";
    failed_ = true;
    return false;
  }
  if (exists && !S_ISREG(st.st_mode)) {
    // A FIFO, a terminal, a device: written in place, as a shell redirection would.
    fd_ = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd_ < 0) return fail("", errno);
    direct_ = true;
    return true;
  }
  if (!open_temporary()) return false;
  // A replaced file keeps its permissions; a new one gets what open(2) would give it.
  const mode_t mode = exists ? (st.st_mode & 07777) : new_file_mode();
  if (::fchmod(fd_, mode) != 0 && exists) return fail("", errno);
  return true;
}

bool OutputFile::open_temporary() {
  const std::string dir = dir_of(target_);
  sweep_stale_temporaries(target_);
#ifdef O_TMPFILE
  fd_ = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd_ >= 0) {
    anonymous_ = true;
    return true;
  }
  // File systems without unnamed temporaries answer EOPNOTSUPP (EISDIR on old
  // kernels); anything else (no such directory, no permission) is the answer.
  if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) return fail("", errno);
#endif
  std::string templ = dir + "/" + temporary_prefix(target_) + std::to_string(::getpid()) + "-XXXXXX";
  fd_ = ::mkostemp(templ.data(), O_CLOEXEC);
  if (fd_ < 0) return fail("", errno);
  temp_path_ = templ;
  cleanup_slot_ = register_temporary(temp_path_.c_str());
  return true;
}

bool OutputFile::flush_buffer() {
  if (buffer_.empty()) return true;
  const bool ok = write_all(fd_, buffer_.data(), buffer_.size());
  buffer_.clear();
  return ok || fail("", errno);
}

bool OutputFile::write(const void* data, std::size_t size) {
  if (failed_ || fd_ < 0 || prepared_) return false;
  const char* p = static_cast<const char*>(data);
  if (buffer_.size() + size <= kBufferBytes) {
    buffer_.insert(buffer_.end(), p, p + size);
    return true;
  }
  if (!flush_buffer()) return false;
  if (size >= kBufferBytes) return write_all(fd_, p, size) || fail("", errno);
  buffer_.insert(buffer_.end(), p, p + size);
  return true;
}

bool OutputFile::prepare() {
  if (prepared_) return !failed_;
  if (fd_ < 0) return failed_ ? false : fail("the file is not open", EBADF);
  if (!flush_buffer()) return false;
  if (!direct_ && ::fsync(fd_) != 0) return fail("", errno);
  // Nothing more is written: the buffer's memory goes back now, not at publish(), since
  // commit_together may hold a thousand prepared files (one per mesh part).
  std::vector<char>().swap(buffer_);
  prepared_ = true;
  return !failed_;
}

bool OutputFile::publish() {
  if (!prepare()) {
    abandon();
    return false;
  }
  if (direct_) {
    const int fd = fd_;
    fd_ = -1;
    if (owns_fd_ && ::close(fd) != 0) return fail("", errno);
    return true;
  }
  if (anonymous_) {
    const std::string proc = fmt::format("/proc/self/fd/{}", fd_);
    const auto link_to = [&](const std::string& name) {
      return ::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0 ||
             ::linkat(fd_, "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH) == 0;
    };
    // A new target is linked in place at once: the file never has another name, so no
    // moment of the run, SIGKILL included, leaves a temporary behind.
    if (link_to(target_)) {
      const int closed = ::close(fd_);
      const int close_err = errno;
      fd_ = -1;
      // The data were synced by prepare(); a failing close cannot take them back.
      return closed == 0 || fail("", close_err);
    }
    if (errno != EEXIST) {
      const int err = errno;
      abandon();
      return fail("cannot give the new file a name", err);
    }
    // linkat cannot replace a file, so an existing target gets the temporary name for
    // the instant before the rename (swept by the next write of it if killed there).
    const std::string dir = dir_of(target_);
    const std::string prefix = dir + "/" + temporary_prefix(target_) + std::to_string(::getpid()) + "-";
    for (int attempt = 0; attempt < 100 && temp_path_.empty(); ++attempt) {
      std::string name = prefix + std::to_string(attempt);
      const int slot = register_temporary(name.c_str());
      if (link_to(name)) {
        temp_path_ = std::move(name);
        cleanup_slot_ = slot;
        break;
      }
      const int err = errno;
      unregister_temporary(slot);
      if (err != EEXIST) {
        abandon();
        return fail("cannot give the new file a name", err);
      }
    }
    if (temp_path_.empty()) {
      abandon();
      return fail("cannot give the new file a name", EEXIST);
    }
  }
  const int closed = ::close(fd_);
  const int close_err = errno;
  fd_ = -1;
  if (closed != 0) {
    abandon();
    return fail("", close_err);
  }
  if (::rename(temp_path_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    abandon();
    return fail("cannot rename the temporary file over it", err);
  }
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
  temp_path_.clear();
  return true;
}

bool OutputFile::commit() {
  if (failed_) {
    abandon();
    return false;
  }
  return publish();
}

void OutputFile::abandon() {
  if (fd_ >= 0 && owns_fd_) ::close(fd_);
  fd_ = -1;
  buffer_.clear();
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
}

bool writes_in_place(const std::string& path) {
  if (path == "-" || named_descriptor(path) >= 0) return true;
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

bool commit_together(std::span<OutputFile* const> files, std::size_t* failed_index) {
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!files[i]->prepare()) {
      if (failed_index) *failed_index = i;
      for (OutputFile* f : files) f->abandon();
      return false;
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!files[i]->publish()) {
      if (failed_index) *failed_index = i;
      for (std::size_t j = i + 1; j < files.size(); ++j) files[j]->abandon();
      return false;
    }
  }
  return true;
}

}  // namespace sm::base
