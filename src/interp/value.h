// Script values and the global symbol store, after Gmsh's model: a numeric
// symbol is a vector<double> plus an "is a list" flag, a string symbol is a
// vector<string>; every variable is global (docs/language.md).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sm::interp {

/// The value of an expression. A number is a one-element list that is not
/// flagged as a list; Gmsh converts freely between the two (a scalar used as a
/// list has one element, a list used as a scalar gives its element 0).
class Value {
 public:
  enum class Kind { Number, List, String, StringList };

  Value() : kind_(Kind::Number), nums_{0.0} {}
  static Value number(double v) { return Value(Kind::Number, {v}, {}); }
  static Value list(std::vector<double> v) { return Value(Kind::List, std::move(v), {}); }
  static Value string(std::string s) { return Value(Kind::String, {}, {std::move(s)}); }
  static Value string_list(std::vector<std::string> s) {
    return Value(Kind::StringList, {}, std::move(s));
  }

  Kind kind() const { return kind_; }
  bool is_numeric() const { return kind_ == Kind::Number || kind_ == Kind::List; }
  bool is_string() const { return !is_numeric(); }
  bool is_list() const { return kind_ == Kind::List || kind_ == Kind::StringList; }

  /// Numbers of a numeric value (one for a scalar).
  const std::vector<double>& nums() const { return nums_; }
  std::vector<double>& nums() { return nums_; }
  /// Strings of a string value (one for a plain string).
  const std::vector<std::string>& strs() const { return strs_; }

 private:
  Value(Kind k, std::vector<double> n, std::vector<std::string> s)
      : kind_(k), nums_(std::move(n)), strs_(std::move(s)) {}
  Kind kind_;
  std::vector<double> nums_;
  std::vector<std::string> strs_;
};

/// A numeric variable exactly as Gmsh stores it.
struct NumSymbol {
  std::vector<double> values;
  bool is_list = false;
};

/// All script variables. Ordered maps keep every listing deterministic.
class Symbols {
 public:
  const NumSymbol* find_num(std::string_view name) const;
  NumSymbol* find_num(std::string_view name);
  const std::vector<std::string>* find_str(std::string_view name) const;
  bool exists(std::string_view name) const { return find_num(name) || find_str(name); }

  /// Sets a numeric variable, replacing a string variable of the same name.
  void set_num(const std::string& name, NumSymbol sym);
  /// Sets a string variable, replacing a numeric variable of the same name.
  void set_str(const std::string& name, std::vector<std::string> strs);
  /// Removes a variable of either kind; false when there was none.
  bool erase(std::string_view name);
  void clear();

  const std::map<std::string, NumSymbol, std::less<>>& nums() const { return nums_; }
  const std::map<std::string, std::vector<std::string>, std::less<>>& strs() const {
    return strs_;
  }

 private:
  std::map<std::string, NumSymbol, std::less<>> nums_;
  std::map<std::string, std::vector<std::string>, std::less<>> strs_;
};

/// What the value is, for messages: "a number", "a list", "a string", "a string list".
std::string_view kind_phrase(const Value& v);

/// A string list as one string, its items joined with newlines (what a string
/// list becomes where one string is expected: `s = Str("a", "b");`).
std::string join_lines(const std::vector<std::string>& strs);

/// Gmsh's name suffix: `x~{3}` is the identifier "x_3" (the index is truncated
/// toward zero like every index).
std::string suffixed_name(std::string_view base, double index);

}  // namespace sm::interp
