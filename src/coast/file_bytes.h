// Whole-file reading with a located error (the readers validate sizes against it).
#pragma once

#include <string>
#include <vector>

#include "coast/coastline.h"

namespace sm::coast {

Result<std::vector<unsigned char>> read_file_bytes(const std::string& path);

}  // namespace sm::coast
