// A private scratch directory for fuzz targets whose reader needs a file path.
#pragma once

#include <cstddef>
#include <filesystem>

namespace sm::fuzz {

/// `name` inside this process's scratch directory (made on first use, removed at exit).
std::filesystem::path scratch_path(const char* name);
/// Writes bytes to `path` (replacing it); aborts when it cannot.
void write_file(const std::filesystem::path& path, const void* data, std::size_t size);

}  // namespace sm::fuzz
