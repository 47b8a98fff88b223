// file_identity.h: device and inode, or the resolved parent and name.
#include "base/file_identity.h"

#include <sys/stat.h>

#include <atomic>
#include <filesystem>
#include <map>
#include <mutex>

namespace sm::base {
namespace {

std::atomic<bool> g_tracking{false};
std::mutex g_mutex;
std::map<std::string, std::string>& inputs() {   // identity -> the name first read
  static std::map<std::string, std::string> m;
  return m;
}

}  // namespace

std::string file_identity(const std::string& path) {
  if (path.empty()) return {};
  if (path == "-") return "-";
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0)
    return "dev " + std::to_string(static_cast<unsigned long long>(st.st_dev)) + " ino " +
           std::to_string(static_cast<unsigned long long>(st.st_ino));
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::error_code ec;
  fs::path parent = p.parent_path();
  if (parent.empty()) parent = ".";
  const fs::path dir = fs::weakly_canonical(fs::absolute(parent, ec), ec);
  return "path " + (ec ? parent : dir).string() + "/" + p.filename().string();
}

void track_inputs(bool on) { g_tracking = on; }

void note_input_file(const std::string& path) {
  if (!g_tracking) return;
  const std::string id = file_identity(path);
  if (id.empty() || id == "-") return;
  const std::lock_guard<std::mutex> lock(g_mutex);
  inputs().emplace(id, path);
}

std::string input_named_by(const std::string& path) {
  if (!g_tracking) return {};
  const std::string id = file_identity(path);
  const std::lock_guard<std::mutex> lock(g_mutex);
  const auto it = inputs().find(id);
  return it == inputs().end() ? std::string() : it->second;
}

}  // namespace sm::base
