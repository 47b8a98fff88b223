// fuzz_readers_replay READER DIR...: runs one reader's fuzz entry over every file of
// the given directories (its seed corpus and crash regressions), in sorted order,
// with any compiler; a crash or invariant violation fails the test.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_floor_entry.h"
#include "fuzz_reader_entries.h"

namespace {

using Entry = void (*)(const std::uint8_t*, std::size_t);

struct Reader {
  const char* name;
  Entry run;
};

constexpr Reader kReaders[] = {
    {"gshhs", &sm::fuzz::run_gshhs_input},       {"lonlat_text", &sm::fuzz::run_lonlat_text_input},
    {"loops2", &sm::fuzz::run_loops2_input},     {"shapefile", &sm::fuzz::run_shapefile_input},
    {"netcdf", &sm::fuzz::run_netcdf_input},     {"esri", &sm::fuzz::run_esri_input},
    {"floor", &sm::fuzz::run_floor_input},   // not a reader: the quality floor on random coasts
    {"gshhg_binned", &sm::fuzz::run_gshhg_binned_input},
};

}  // namespace

int main(int argc, char** argv) {
  const Reader* reader = nullptr;
  if (argc >= 2)
    for (const Reader& r : kReaders)
      if (std::strcmp(argv[1], r.name) == 0) reader = &r;
  if (!reader) {
    std::fprintf(
        stderr,
        "usage: fuzz_readers_replay gshhs|lonlat_text|loops2|shapefile|netcdf|esri|gshhg_binned|floor DIR...\n");
    return 2;
  }
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i) {
    std::error_code ec;
    if (!std::filesystem::exists(argv[i], ec)) continue;   // crashes_<reader>/ may not exist yet
    for (const auto& e : std::filesystem::recursive_directory_iterator(argv[i], ec))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
    if (ec) {
      std::fprintf(stderr, "fuzz_readers_replay: cannot read '%s': %s\n", argv[i], ec.message().c_str());
      return 2;
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay %s (%zu bytes)\n", f.c_str(), data.size());
    reader->run(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::printf("fuzz_readers_replay %s: %zu inputs ran cleanly\n", reader->name, files.size());
  return files.empty() ? 1 : 0;
}
