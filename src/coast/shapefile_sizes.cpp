// The .shp/.shx size checks made before shapelib is called. Layouts (all lengths and
// offsets in 16-bit words, big-endian):
//
//   .shp and .shx header, 100 bytes     .shp record            .shx entry (from byte 100)
//    0  int32 file code 9994             0 int32 number         0 int32 offset of the record
//   24  int32 file length                4 int32 content len    4 int32 content length
//   28  int32 version (little-endian)    8 content: shape type (int32 LE), then the shape
//   32  int32 shape type (little-endian)
#include "coast/shapefile_sizes.h"
#include "base/file_identity.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "coast/big_endian.h"

namespace sm::coast {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kHeaderBytes = 100;
constexpr std::uint64_t kRecordHeaderBytes = 8;
constexpr std::int64_t kMinContentWords = 2;   // a record's content starts with its 4-byte shape type

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

CoastError error_in(const fs::path& file, std::int64_t record, std::string message) {
  return CoastError{file.string(), record, std::move(message), {}};
}

// Opens `file` and reads its 100-byte header; `size` gets the bytes the file holds and
// `claimed` the length its header states.
std::optional<CoastError> read_header(const fs::path& file, File& f, std::uint64_t& size, std::uint64_t& claimed) {
  std::error_code ec;
  size = fs::file_size(file, ec);
  if (ec) return error_in(file, -1, "cannot read its size: " + ec.message());
  f.reset(std::fopen(file.c_str(), "rb"));
  if (!f) return error_in(file, -1, std::string("cannot open: ") + std::strerror(errno));
  base::note_input_file(file.string());
  if (size < kHeaderBytes)
    return error_in(file, -1, fmt::format("the file holds {} bytes, less than the {}-byte header", size, kHeaderBytes));
  unsigned char h[kHeaderBytes];
  if (std::fread(h, 1, sizeof h, f.get()) != sizeof h) return error_in(file, -1, "cannot read the 100-byte header");
  // The length word is unsigned in practice (files up to 8 GB); the sign bit is kept as
  // a magnitude so a hostile 0xFFFFFFFF reads as 8 GB, not as a negative length.
  claimed = 2 * static_cast<std::uint64_t>(static_cast<std::uint32_t>(be32(h + 24)));
  if (claimed > size)
    return error_in(file, -1, fmt::format("header claims {} bytes, the file holds {} bytes", claimed, size));
  return std::nullopt;
}

// A record of `words` content words at byte `offset` must start after the header and
// end inside the .shp's claimed length.
std::optional<CoastError> check_record(const fs::path& file, std::int64_t k, std::int64_t offset, std::int64_t words,
                                       std::uint64_t shp_claimed, const char* what) {
  if (words < kMinContentWords)
    return error_in(file, k, fmt::format("{} claims a record of {} bytes, less than its 4-byte shape type", what,
                                         2 * words));
  const std::uint64_t end =
      static_cast<std::uint64_t>(offset) + kRecordHeaderBytes + 2 * static_cast<std::uint64_t>(words);
  if (offset < static_cast<std::int64_t>(kHeaderBytes) || end > shp_claimed)
    return error_in(file, k, fmt::format("{} claims a record at bytes {} to {}, outside the {} bytes of records "
                                         "the .shp header claims", what, offset, end, shp_claimed));
  return std::nullopt;
}

}  // namespace

std::optional<CoastError> check_shapefile_sizes(const fs::path& shp, const fs::path& shx) {
  File shp_f(nullptr, &std::fclose);
  std::uint64_t shp_size = 0, shp_claimed = 0;
  if (auto e = read_header(shp, shp_f, shp_size, shp_claimed)) return e;

  if (!shx.empty()) {
    File shx_f(nullptr, &std::fclose);
    std::uint64_t shx_size = 0, shx_claimed = 0;
    if (auto e = read_header(shx, shx_f, shx_size, shx_claimed)) return e;
    // shx_claimed <= the file's size, so the entries read here fit in memory as the file does.
    const std::uint64_t entries = (shx_claimed - std::min(shx_claimed, kHeaderBytes)) / 8;
    std::vector<unsigned char> index(static_cast<std::size_t>(entries * 8));
    if (!index.empty() && std::fread(index.data(), 1, index.size(), shx_f.get()) != index.size())
      return error_in(shx, -1, "cannot read the index entries");
    for (std::uint64_t k = 0; k < entries; ++k) {
      const unsigned char* p = index.data() + 8 * k;
      const std::int64_t offset = 2 * std::int64_t{be32(p)};   // widen first: 2 * 2^30 overflows int32
      if (auto e = check_record(shx, static_cast<std::int64_t>(k), offset, be32(p + 4), shp_claimed, "the index entry"))
        return e;
    }
    return std::nullopt;
  }

  // No index: walk the record headers as SHPRestoreSHX will.
  std::uint64_t offset = kHeaderBytes;
  for (std::int64_t k = 0; offset < shp_claimed; ++k) {
    unsigned char h[kRecordHeaderBytes];
    if (offset + kRecordHeaderBytes > shp_claimed ||
        std::fseek(shp_f.get(), static_cast<long>(offset), SEEK_SET) != 0 ||
        std::fread(h, 1, sizeof h, shp_f.get()) != sizeof h)
      return error_in(shp, k, fmt::format("the record header at byte {} runs past the {} bytes the header claims",
                                          offset, shp_claimed));
    const std::int64_t words = be32(h + 4);
    if (auto e = check_record(shp, k, static_cast<std::int64_t>(offset), words, shp_claimed, "the record header"))
      return e;
    offset += kRecordHeaderBytes + 2 * static_cast<std::uint64_t>(words);
  }
  return std::nullopt;
}

}  // namespace sm::coast
