// Whole-file reading with a located error.
#include "coast/file_bytes.h"
#include "base/file_identity.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace sm::coast {

Result<std::vector<unsigned char>> read_file_bytes(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return CoastError{path, -1, std::string("cannot open: ") + std::strerror(errno), {}};
  base::note_input_file(path);
  // Straight into the vector, sized from the file when it has a size (a regular file),
  // grown by doubling otherwise (a pipe): no copy through a small buffer.
  std::vector<unsigned char> out;
  struct stat st {};
  std::size_t cap = 1 << 16;
  if (::fstat(::fileno(f.get()), &st) == 0 && S_ISREG(st.st_mode)) cap = static_cast<std::size_t>(st.st_size) + 1;
  std::size_t have = 0;
  for (;;) {
    out.resize(std::max(cap, have + 1));
    const std::size_t want = out.size() - have;
    const std::size_t got = std::fread(out.data() + have, 1, want, f.get());
    have += got;
    if (got < want) break;
    cap = 2 * out.size();
  }
  out.resize(have);
  if (std::ferror(f.get())) return CoastError{path, -1, "read error", {}};
  return out;
}

}  // namespace sm::coast
