// The one output writer: new and replaced files, symbolic links, FIFOs and
// devices written in place, failures that leave the old file, several files
// committed together, and nothing left behind by signals.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "base/interrupt_cleanup.h"
#include "base/output_file.h"
#include "scratch_dir.h"

namespace fs = std::filesystem;
using sm::base::OutputFile;
using sm::testing::read_all;
using sm::testing::ScratchDir;

namespace {

void write_plain(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool write_file(const std::string& path, const std::string& text, std::string* error = nullptr) {
  OutputFile f;
  const bool ok = f.open(path) && f.write(text) && f.commit();
  if (error) *error = f.error();
  return ok;
}

}  // namespace

TEST_CASE("output file: a new file, then a replaced one, keep no temporary") {
  ScratchDir d;
  REQUIRE(write_file(d / "a.msh", "one\n"));
  CHECK(read_all(d / "a.msh") == "one\n");
  ::chmod((d / "a.msh").c_str(), 0640);
  REQUIRE(write_file(d / "a.msh", std::string(200000, 'x')));   // larger than the buffer
  CHECK(read_all(d / "a.msh") == std::string(200000, 'x'));
  struct stat st {};
  REQUIRE(::stat((d / "a.msh").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0640);   // a replaced file keeps its permissions
  CHECK(d.names() == std::vector<std::string>{"a.msh"});
}

TEST_CASE("output file: abandoned or failed writes leave the old file") {
  ScratchDir d;
  write_plain(d / "a.msh", "old\n");
  {
    OutputFile f;
    REQUIRE(f.open(d / "a.msh"));
    REQUIRE(f.write("new, never committed\n"));
  }   // destroyed without commit
  CHECK(read_all(d / "a.msh") == "old\n");
  CHECK(d.names() == std::vector<std::string>{"a.msh"});

  std::string why;
  CHECK_FALSE(write_file(d / "missing-dir/a.msh", "x", &why));
  CHECK(why == "No such file or directory");
  CHECK_FALSE(write_file(d.path.string(), "x", &why));
  CHECK(why == "it is a directory");
  CHECK_FALSE(write_file("", "x", &why));
  CHECK(d.names() == std::vector<std::string>{"a.msh"});
}

TEST_CASE("output file: a symbolic link stays a link, its target gets the bytes") {
  ScratchDir d;
  write_plain(d / "real.msh", "old\n");
  fs::create_symlink("real.msh", d / "link.msh");
  REQUIRE(write_file(d / "link.msh", "new\n"));
  CHECK(fs::is_symlink(d / "link.msh"));
  CHECK(read_all(d / "real.msh") == "new\n");

  // A dangling link: its target is created, the link kept.
  fs::create_symlink("later.msh", d / "dangling.msh");
  REQUIRE(write_file(d / "dangling.msh", "made\n"));
  CHECK(fs::is_symlink(d / "dangling.msh"));
  CHECK(read_all(d / "later.msh") == "made\n");

  // A loop of links is an error, not a hang.
  fs::create_symlink("loop2", d / "loop1");
  fs::create_symlink("loop1", d / "loop2");
  std::string why;
  CHECK_FALSE(write_file(d / "loop1", "x", &why));
  CHECK(why == "Too many levels of symbolic links");
  CHECK(d.names() == std::vector<std::string>{"dangling.msh", "later.msh", "link.msh", "loop1", "loop2", "real.msh"});
}

TEST_CASE("output file: a FIFO is written in place, never replaced") {
  ScratchDir d;
  const std::string fifo = d / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string got;
  std::thread reader([&] { got = read_all(fifo); });
  const bool ok = write_file(fifo, "through the pipe\n");
  reader.join();
  CHECK(ok);
  CHECK(got == "through the pipe\n");
  struct stat st {};
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(d.names() == std::vector<std::string>{"pipe"});
}

TEST_CASE("output file: a device is written in place; a full one is an error") {
  std::string why;
  CHECK(write_file("/dev/null", "gone\n"));
  OutputFile f;
  REQUIRE(f.open("/dev/full"));
  CHECK(f.direct());
  f.write("no room\n");
  CHECK_FALSE(f.commit());
  CHECK(f.error() == "No space left on device");
  struct stat st {};
  REQUIRE(::stat("/dev/full", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));   // still the device, not a regular file renamed over it
}

TEST_CASE("output file: '-' and /dev/fd/N are the descriptors themselves") {
  OutputFile f;
  REQUIRE(f.open("-"));
  CHECK(f.direct());
  CHECK(f.target() == "standard output");
  f.abandon();
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const std::string path = "/dev/fd/" + std::to_string(fds[1]);
  REQUIRE(f.open(path));
  CHECK(f.direct());
  REQUIRE(f.write("abc"));
  REQUIRE(f.commit());
  char buf[4] = {};
  CHECK(::read(fds[0], buf, 3) == 3);
  CHECK(std::string(buf) == "abc");
  ::close(fds[0]);
  ::close(fds[1]);
}

TEST_CASE("output file: several files appear together or not at all") {
  ScratchDir d;
  write_plain(d / "hgrid.gr3", "old gr3\n");
  {
    OutputFile a, b;
    REQUIRE(a.open(d / "hgrid.gr3"));
    REQUIRE(b.open("/dev/full"));   // fails when its bytes are flushed
    a.write("new gr3\n");
    b.write("new ll\n");
    OutputFile* const both[] = {&a, &b};
    std::size_t failed = 99;
    CHECK_FALSE(sm::base::commit_together(both, &failed));
    CHECK(failed == 1);
  }
  CHECK(read_all(d / "hgrid.gr3") == "old gr3\n");
  CHECK(d.names() == std::vector<std::string>{"hgrid.gr3"});

  OutputFile a, b;
  REQUIRE(a.open(d / "hgrid.gr3"));
  REQUIRE(b.open(d / "hgrid.ll"));
  a.write("new gr3\n");
  b.write("new ll\n");
  OutputFile* const both[] = {&a, &b};
  CHECK(sm::base::commit_together(both, nullptr));
  CHECK(read_all(d / "hgrid.gr3") == "new gr3\n");
  CHECK(read_all(d / "hgrid.ll") == "new ll\n");
}

TEST_CASE("output file: SIGKILL during a write leaves nothing behind") {
  ScratchDir d;
  write_plain(d / "a.msh", "old\n");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    OutputFile f;
    if (!f.open(d / "a.msh")) ::_exit(2);
    f.write(std::string(300000, 'y'));
    ::raise(SIGKILL);
    ::_exit(3);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  CHECK(read_all(d / "a.msh") == "old\n");
  CHECK(d.names() == std::vector<std::string>{"a.msh"});   // the temporary had no name
}

TEST_CASE("interrupt cleanup: SIGINT and SIGTERM remove registered temporaries, then end the program") {
  for (int sig : {SIGINT, SIGTERM}) {
    ScratchDir d;
    const std::string temp = d / "x.msh.tmp-123456";
    write_plain(temp, "partial");
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      sm::base::install_interrupt_cleanup();
      if (sm::base::register_temporary(temp.c_str()) < 0) ::_exit(2);
      ::raise(sig);
      ::_exit(3);   // not reached: the signal's default action ends the child
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(d.names().empty());
  }
}
