// Printf redirections (see redirect_files.h).
#include "interp/redirect_files.h"

#include <fstream>
#include <iterator>

namespace sm::interp {

bool RedirectFiles::write_line(const std::string& path, bool append, std::string_view line, lang::SourceRange where,
                               std::string* reason) {
  auto it = files_.find(path);
  if (it != files_.end() && !append) {
    it->second->file.abandon();
    files_.erase(it);
    it = files_.end();
  }
  if (it == files_.end()) {
    auto p = std::make_unique<Pending>();
    p->file.allow_inputs();   // Printf > FILE may rewrite a file the script Included
    if (!p->file.open(path)) {
      *reason = p->file.error();
      return false;
    }
    // `>>` continues what a regular file held before this run (a FIFO or a
    // device is written as it is).
    if (append && !p->file.direct()) {
      std::ifstream old(p->file.target(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(old)), std::istreambuf_iterator<char>());
      p->file.write(bytes);
    }
    it = files_.emplace(path, std::move(p)).first;
  }
  it->second->where = where;
  if (!it->second->file.write(line) || !it->second->file.write("\n")) {
    *reason = it->second->file.error();
    return false;
  }
  return true;
}

void RedirectFiles::publish(const std::string& path) {
  const auto it = files_.find(path);
  if (it == files_.end()) return;
  if (!it->second->file.commit()) failed_.push_back({it->second->where, path, it->second->file.error()});
  files_.erase(it);
}

std::vector<RedirectFiles::Failure> RedirectFiles::commit_all() {
  std::vector<Failure> failed = std::move(failed_);
  failed_.clear();
  for (auto& [path, p] : files_)
    if (!p->file.commit()) failed.push_back({p->where, path, p->file.error()});
  files_.clear();
  return failed;
}

void RedirectFiles::abandon_all() {
  for (auto& [path, p] : files_) p->file.abandon();
  files_.clear();
  failed_.clear();
}

}  // namespace sm::interp
