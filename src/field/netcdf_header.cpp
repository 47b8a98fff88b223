// Walk of a classic netCDF header, big-endian throughout; w is 4 bytes in CDF-1/2 and
// 8 in CDF-5 (counts, lengths, dimension ids, sizes), `begin` 4 bytes in CDF-1 only:
//
//   header   = 'C' 'D' 'F' version  numrecs(w)  dim_list  att_list  var_list
//   list     = tag(4) count(w) item...        (absent: count 0, tag 0 or anything)
//   name     = length(w) bytes padded to 4
//   dim      = name length(w)                                   >= 2w bytes
//   attr     = name type(4) count(w) values padded to 4         >= 2w + 4 bytes
//   var      = name ndims(w) dimid(w)... att_list type(4) vsize(w) begin
//                                                              >= 4w + 8 + |begin| bytes
#include "field/netcdf_header.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <system_error>

#include <fmt/format.h>

namespace sm::field {
namespace {

constexpr std::uint32_t kTagDimension = 0x0A;
constexpr std::uint32_t kTagVariable = 0x0B;
constexpr std::uint32_t kTagAttribute = 0x0C;

// Bytes of one value of a netCDF type (1 NC_BYTE .. 11 NC_UINT64), 0 if unknown.
std::uint64_t value_bytes(std::uint64_t type) {
  constexpr std::uint64_t kSizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
  return type < std::size(kSizes) ? kSizes[type] : 0;
}

// The types a classic file may hold: NC_BYTE .. NC_DOUBLE, and in CDF-5 up to NC_UINT64.
// libnetcdf 4.9 accepts NC_STRING (12, a netCDF-4 type of no fixed size) in a CDF-5
// header and then divides by its size of 0 while checking the variable's size.
std::uint64_t last_type(int w) { return w == 8 ? 11 : 6; }

std::uint64_t pad4(std::uint64_t n) { return n + (4 - n % 4) % 4; }

// Reads the header front to back; `left()` is what the file holds after the cursor.
class HeaderCursor {
 public:
  HeaderCursor(std::FILE* f, std::uint64_t size) : f_(f), size_(size) {}
  std::uint64_t left() const { return size_ - pos_; }
  /// A big-endian unsigned integer of `bytes` bytes (4 or 8); false at the end of the file.
  bool uint(int bytes, std::uint64_t& v) {
    unsigned char b[8];
    if (left() < static_cast<std::uint64_t>(bytes) || std::fread(b, 1, static_cast<std::size_t>(bytes), f_) !=
                                                          static_cast<std::size_t>(bytes))
      return false;
    pos_ += static_cast<std::uint64_t>(bytes);
    v = 0;
    for (int k = 0; k < bytes; ++k) v = v << 8 | b[k];
    return true;
  }
  /// Skips n bytes; false if the file holds fewer.
  bool skip(std::uint64_t n) {
    if (n > left() || std::fseek(f_, static_cast<long>(pos_ + n), SEEK_SET) != 0) return false;
    pos_ += n;
    return true;
  }

 private:
  std::FILE* f_;
  std::uint64_t size_;
  std::uint64_t pos_ = 0;
};

// The walk stops at the first count that cannot fit or the end of the file inside the
// header (`refused`), or at a header libnetcdf will refuse on its own (a non-empty list
// with the wrong tag: `done` without a reason): each ends the check.
struct Walk {
  HeaderCursor& in;
  int w;            // bytes of a count
  int begin_bytes;  // bytes of a variable's data offset
  std::optional<std::string> refused;
  bool done = false;

  bool stop(std::optional<std::string> why = std::nullopt) {
    refused = std::move(why);
    done = true;
    return false;
  }
  // The file ends inside the header. libnetcdf does not refuse such a header on its own:
  // it reads a whole block and decodes past the end of the file, so a variable's rank
  // there can ask for gigabytes (a fuzz finding: a 158-byte file, an 8 GB allocation).
  bool cut(const std::string& inside) {
    return stop(fmt::format("the header is cut short: the file ends inside {}", inside));
  }
  // `count` items of at least `each` bytes must fit in what is left.
  bool fits(std::uint64_t count, std::uint64_t each, const std::string& what) {
    if (count <= in.left() / each) return true;
    return stop(fmt::format("the header declares {} {} (at least {} byte{} each) but the file holds {} more bytes",
                            count, what, each, each == 1 ? "" : "s", in.left()));
  }
  bool name(const std::string& of) {
    std::uint64_t len = 0;
    if (!in.uint(w, len)) return cut("the name of " + of);
    if (len > in.left())
      return stop(fmt::format("the header declares a name of {} bytes for {} but the file holds {} more bytes", len,
                              of, in.left()));
    return in.skip(pad4(len)) || cut("the name of " + of);
  }
  bool known_type(std::uint64_t type, const std::string& of) {
    if (type >= 1 && type <= last_type(w)) return true;
    return stop(fmt::format("{} has type {}, not a type of this format (1 to {})", of, type, last_type(w)));
  }
  // A list's tag and count; false when it is absent (or the walk stopped).
  bool list(std::uint32_t tag, std::uint64_t& count, const std::string& what) {
    std::uint64_t t = 0;
    if (!in.uint(4, t) || !in.uint(w, count)) return cut("the list of " + what);
    // libnetcdf reads an empty list whatever its tag says (a hostile tag with count 0 is
    // not refused), and refuses a non-empty one whose tag is wrong.
    if (count == 0) return false;
    if (t != tag) return stop();
    return true;
  }
  bool attributes(const std::string& of) {
    std::uint64_t n = 0;
    if (!list(kTagAttribute, n, "attributes of " + of)) return !done;
    if (!fits(n, 2 * static_cast<std::uint64_t>(w) + 4, "attributes of " + of)) return false;
    for (std::uint64_t a = 0; a < n; ++a) {
      const std::string what = fmt::format("attribute {} of {}", a, of);
      std::uint64_t type = 0, values = 0;
      if (!name(what)) return false;
      if (!in.uint(4, type) || !in.uint(w, values)) return cut(what);
      if (!known_type(type, what)) return false;
      const std::uint64_t each = value_bytes(type);
      if (!fits(values, each, "values in " + what)) return false;
      if (!in.skip(pad4(values * each))) return cut("the values of " + what);
    }
    return true;
  }
  bool run() {
    std::uint64_t numrecs = 0, n = 0;
    if (!in.uint(w, numrecs)) return cut("the record count");
    if (list(kTagDimension, n, "dimensions")) {
      if (!fits(n, 2 * static_cast<std::uint64_t>(w), "dimensions")) return false;
      for (std::uint64_t d = 0; d < n; ++d) {
        std::uint64_t len = 0;
        const std::string what = fmt::format("dimension {}", d);
        if (!name(what)) return false;
        if (!in.uint(w, len)) return cut(what);
      }
    } else if (done) {
      return false;
    }
    if (!attributes("the file")) return false;
    if (list(kTagVariable, n, "variables")) {
      const std::uint64_t ww = static_cast<std::uint64_t>(w);
      if (!fits(n, 4 * ww + 8 + static_cast<std::uint64_t>(begin_bytes), "variables")) return false;
      for (std::uint64_t v = 0; v < n; ++v) {
        const std::string what = fmt::format("variable {}", v);
        std::uint64_t ndims = 0, type = 0, vsize = 0, begin = 0;
        if (!name(what)) return false;
        if (!in.uint(w, ndims)) return cut(what);
        if (!fits(ndims, ww, "dimension ids of " + what)) return false;
        if (!in.skip(ndims * ww)) return cut("the dimension ids of " + what);
        if (!attributes(what)) return false;
        if (!in.uint(4, type)) return cut(what);
        if (!known_type(type, what)) return false;
        if (!in.uint(w, vsize) || !in.uint(begin_bytes, begin)) return cut(what);
      }
    }
    return !done;
  }
};

}  // namespace

std::optional<std::string> check_netcdf_header_counts(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(file, ec);
  if (ec) return std::nullopt;   // nc_open reports what it cannot read
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) return std::nullopt;
  unsigned char magic[4];
  if (size < 4 || std::fread(magic, 1, 4, f.get()) != 4) return std::nullopt;
  if (magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F' || (magic[3] != 1 && magic[3] != 2 && magic[3] != 5))
    return std::nullopt;
  HeaderCursor in(f.get(), size);
  if (!in.skip(4)) return std::nullopt;
  Walk walk{in, magic[3] == 5 ? 8 : 4, magic[3] == 1 ? 4 : 8, std::nullopt};
  walk.run();
  return walk.refused;
}

}  // namespace sm::field
