// SourceManager: loading files (failures as LoadFailure, size limit) and lazily built
// per-file line tables for line:column lookups.
#include "lang/source.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "base/check.h"
#include "base/file_identity.h"

namespace sm::lang {

struct SourceManager::File {
  std::string path;
  std::string canonical;  // for find_loaded; empty for buffers
  std::string text;
  mutable std::optional<std::vector<std::uint32_t>> line_starts;  // built on first use
};

SourceRange join(SourceRange a, SourceRange b) {
  if (!a.valid()) return b;
  if (!b.valid() || a.file != b.file) return a;
  return {a.file, std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

SourceManager::SourceManager() = default;
SourceManager::~SourceManager() = default;

namespace {

std::string canonical_path(const std::string& path) {
  std::error_code ec;
  auto p = std::filesystem::weakly_canonical(std::filesystem::path(path), ec);
  return ec ? path : p.string();
}

}  // namespace

SourceManager::LoadResult SourceManager::load_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {FileId{}, LoadFailure::IsDirectory, {}};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {FileId{}, LoadFailure::CannotOpen, std::strerror(errno)};
  base::note_input_file(path);
  std::string text;
  char buf[1 << 16];
  std::size_t n;
  bool too_big = false;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    if (text.size() + n > kMaxFileBytes) {
      too_big = true;
      break;
    }
    text.append(buf, n);
  }
  const bool read_error = std::ferror(f) != 0;
  std::fclose(f);
  if (too_big) return {FileId{}, LoadFailure::TooLarge, {}};
  if (read_error) return {FileId{}, LoadFailure::CannotRead, {}};
  LoadResult r = add_buffer(path, std::move(text));
  if (r.file.valid()) files_.back()->canonical = canonical_path(path);
  return r;
}

SourceManager::LoadResult SourceManager::add_buffer(std::string name, std::string text) {
  if (text.size() > kMaxFileBytes) return {FileId{}, LoadFailure::TooLarge, {}};
  auto f = std::make_unique<File>();
  f->path = std::move(name);
  f->text = std::move(text);
  files_.push_back(std::move(f));
  return {FileId{static_cast<std::uint32_t>(files_.size() - 1)}, LoadFailure::None, {}};
}

const SourceManager::File& SourceManager::file(FileId f) const {
  SM_ASSERT(f.valid() && f.value < files_.size(), "FileId out of range");
  return *files_[f.value];
}

const std::string& SourceManager::path(FileId f) const { return file(f).path; }
std::string_view SourceManager::text(FileId f) const { return file(f).text; }

FileId SourceManager::find_loaded(const std::string& path) const {
  const std::string c = canonical_path(path);
  for (std::size_t i = 0; i < files_.size(); ++i)
    if (!files_[i]->canonical.empty() && files_[i]->canonical == c) return FileId{static_cast<std::uint32_t>(i)};
  return FileId{};
}

const std::vector<std::uint32_t>& SourceManager::line_starts(FileId id) const {
  const File& f = file(id);
  if (!f.line_starts) {
    std::vector<std::uint32_t> starts{0};
    const char* p = f.text.data();
    const char* end = p + f.text.size();
    while (const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p))) {
      p = static_cast<const char*>(nl) + 1;
      starts.push_back(static_cast<std::uint32_t>(p - f.text.data()));
    }
    f.line_starts = std::move(starts);
  }
  return *f.line_starts;
}

LineCol SourceManager::line_col(SourceLoc loc) const {
  if (!loc.file.valid()) return {};
  const auto& starts = line_starts(loc.file);
  const std::uint32_t off = std::min<std::uint32_t>(loc.offset, static_cast<std::uint32_t>(file(loc.file).text.size()));
  const auto it = std::upper_bound(starts.begin(), starts.end(), off);
  const auto line = static_cast<std::uint32_t>(it - starts.begin());  // >= 1
  return {line, off - starts[line - 1] + 1};
}

std::uint32_t SourceManager::line_count(FileId f) const {
  return static_cast<std::uint32_t>(line_starts(f).size());
}

std::string_view SourceManager::line_text(FileId f, std::uint32_t line) const {
  const auto& starts = line_starts(f);
  if (line == 0 || line > starts.size()) return {};
  std::string_view text = file(f).text;
  const std::uint32_t b = starts[line - 1];
  std::uint32_t e = line < starts.size() ? starts[line] - 1 : static_cast<std::uint32_t>(text.size());
  if (e > b && text[e - 1] == '\r') --e;
  return text.substr(b, e - b);
}

}  // namespace sm::lang
