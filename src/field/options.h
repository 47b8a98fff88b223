// Field option declarations (name, type, default, help, deprecated aliases)
// and the option values of one Field[n] definition.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace sm::field {

enum class OptionType { Number, String, List };

/// What a Number/List option means beyond its type: a reference to another
/// field id (resolved at build time, checked for cycles) or a plain value.
enum class OptionRole { Plain, FieldRef, FieldRefList };

using OptionValue = std::variant<double, std::string, std::vector<double>>;

struct OptionSpec {
  std::string name;
  OptionType type = OptionType::Number;
  OptionValue def;
  std::string help;
  std::vector<std::string> aliases;  ///< deprecated names sharing the same storage
  OptionRole role = OptionRole::Plain;
};

/// Shorthands for kind declarations.
OptionSpec num_opt(std::string name, double def, std::string help,
                   std::vector<std::string> aliases = {});
OptionSpec field_opt(std::string name, double def, std::string help,
                     std::vector<std::string> aliases = {});
OptionSpec str_opt(std::string name, std::string def, std::string help,
                   std::vector<std::string> aliases = {});
OptionSpec list_opt(std::string name, std::string help, std::vector<std::string> aliases = {},
                    OptionRole role = OptionRole::Plain);

struct KindSpec;

/// Option values of one field instance. Values are stored per canonical
/// option; an alias reads and writes the same slot.
class Options {
 public:
  explicit Options(const KindSpec& kind);

  const KindSpec& kind() const { return *kind_; }
  /// Index of `name` (canonical or alias), or -1.
  int find(std::string_view name) const;
  /// Throws FieldError UnknownOption (with the closest name) or WrongOptionType.
  void set(std::string_view name, OptionValue value);

  double number(std::string_view name) const;
  const std::string& string(std::string_view name) const;
  const std::vector<double>& list(std::string_view name) const;
  bool was_set(std::string_view name) const;
  const OptionValue& value(int index) const { return values_[static_cast<std::size_t>(index)]; }
  int size() const { return static_cast<int>(values_.size()); }

 private:
  int index_or_die(std::string_view name) const;

  const KindSpec* kind_;
  std::vector<OptionValue> values_;
  std::vector<bool> set_;
};

}  // namespace sm::field
