// The global symbol store of a script run (see value.h).
#include "interp/value.h"

#include <cmath>

#include <fmt/format.h>

namespace sm::interp {

const NumSymbol* Symbols::find_num(std::string_view name) const {
  auto it = nums_.find(name);
  return it == nums_.end() ? nullptr : &it->second;
}

NumSymbol* Symbols::find_num(std::string_view name) {
  auto it = nums_.find(name);
  return it == nums_.end() ? nullptr : &it->second;
}

const std::vector<std::string>* Symbols::find_str(std::string_view name) const {
  auto it = strs_.find(name);
  return it == strs_.end() ? nullptr : &it->second;
}

void Symbols::set_num(const std::string& name, NumSymbol sym) {
  if (auto it = strs_.find(name); it != strs_.end()) strs_.erase(it);
  nums_[name] = std::move(sym);
}

void Symbols::set_str(const std::string& name, std::vector<std::string> strs) {
  if (auto it = nums_.find(name); it != nums_.end()) nums_.erase(it);
  strs_[name] = std::move(strs);
}

bool Symbols::erase(std::string_view name) {
  bool found = false;
  if (auto it = nums_.find(name); it != nums_.end()) {
    nums_.erase(it);
    found = true;
  }
  if (auto it = strs_.find(name); it != strs_.end()) {
    strs_.erase(it);
    found = true;
  }
  return found;
}

void Symbols::clear() {
  nums_.clear();
  strs_.clear();
}

std::string join_lines(const std::vector<std::string>& strs) {
  std::string s;
  for (std::size_t i = 0; i < strs.size(); ++i) {
    if (i) s += '\n';
    s += strs[i];
  }
  return s;
}

std::string_view kind_phrase(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::Number: return "a number";
    case Value::Kind::List: return "a list";
    case Value::Kind::String: return "a string";
    case Value::Kind::StringList: return "a string list";
  }
  return "?";
}

std::string suffixed_name(std::string_view base, double index) {
  return fmt::format("{}_{}", base, static_cast<long long>(std::trunc(index)));
}

}  // namespace sm::interp
