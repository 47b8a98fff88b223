// fuzz_corpus_replay DIR...: runs the fuzz entry over every file of the given
// directories (seed corpus and crash regressions), in sorted order, with any
// compiler; a crash or invariant violation fails the test.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_geo_entry.h"

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(argv[i], ec)) {
      files.emplace_back(argv[i]);
      continue;
    }
    for (const auto& e : std::filesystem::recursive_directory_iterator(argv[i], ec))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
    if (ec) {
      std::fprintf(stderr, "fuzz_corpus_replay: cannot read '%s': %s\n", argv[i], ec.message().c_str());
      return 2;
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay %s (%zu bytes)\n", f.c_str(), data.size());
    sm::fuzz::run_geo_input(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::printf("fuzz_corpus_replay: %zu inputs ran cleanly\n", files.size());
  return files.empty() ? 1 : 0;
}
