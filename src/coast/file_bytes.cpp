// Whole-file reading with a located error.
#include "coast/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace sm::coast {

Result<std::vector<unsigned char>> read_file_bytes(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return CoastError{path, -1, std::string("cannot open: ") + std::strerror(errno), {}};
  std::vector<unsigned char> out;
  unsigned char buf[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(buf, 1, sizeof buf, f.get());
    out.insert(out.end(), buf, buf + got);
    if (got < sizeof buf) break;
  }
  if (std::ferror(f.get())) return CoastError{path, -1, "read error", {}};
  return out;
}

}  // namespace sm::coast
