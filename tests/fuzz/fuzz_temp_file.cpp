// Scratch files of the reader fuzz targets: one directory per process, so parallel
// fuzzing jobs (-jobs=N) and the replay test never share a file.
#include "fuzz_temp_file.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

#include <unistd.h>

namespace sm::fuzz {
namespace {

struct ScratchDir {
  std::filesystem::path dir;
  ScratchDir() {
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    dir = (ec ? std::filesystem::path("/tmp") : base) / ("sm-fuzz-reader-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir, ec);
    if (ec) {
      std::fprintf(stderr, "fuzz: cannot make %s: %s\n", dir.c_str(), ec.message().c_str());
      std::abort();
    }
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

}  // namespace

std::filesystem::path scratch_path(const char* name) {
  static const ScratchDir scratch;
  return scratch.dir / name;
}

void write_file(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

}  // namespace sm::fuzz
