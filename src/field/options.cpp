// Option values of one field instance, with alias resolution and type checks.
#include "field/options.h"

#include <cmath>

#include <fmt/format.h>

#include "field/error.h"
#include "field/registry.h"

namespace sm::field {

OptionSpec num_opt(std::string name, double def, std::string help, std::vector<std::string> aliases) {
  return {std::move(name), OptionType::Number, def, std::move(help), std::move(aliases),
          OptionRole::Plain};
}

OptionSpec field_opt(std::string name, double def, std::string help,
                     std::vector<std::string> aliases) {
  return {std::move(name), OptionType::Number, def, std::move(help), std::move(aliases),
          OptionRole::FieldRef};
}

OptionSpec str_opt(std::string name, std::string def, std::string help,
                   std::vector<std::string> aliases) {
  return {std::move(name), OptionType::String, std::move(def), std::move(help), std::move(aliases),
          OptionRole::Plain};
}

OptionSpec list_opt(std::string name, std::string help, std::vector<std::string> aliases,
                    OptionRole role) {
  return {std::move(name), OptionType::List, std::vector<double>{}, std::move(help),
          std::move(aliases), role};
}

Options::Options(const KindSpec& kind) : kind_(&kind) {
  for (const OptionSpec& o : kind.options) values_.push_back(o.def);
  set_.assign(values_.size(), false);
}

int Options::find(std::string_view name) const {
  for (std::size_t i = 0; i < kind_->options.size(); ++i) {
    const OptionSpec& o = kind_->options[i];
    if (o.name == name) return static_cast<int>(i);
    for (const std::string& a : o.aliases)
      if (a == name) return static_cast<int>(i);
  }
  return -1;
}

namespace {

const char* type_name(OptionType t) {
  switch (t) {
    case OptionType::Number: return "a number";
    case OptionType::String: return "a string";
    case OptionType::List: return "a list in braces";
  }
  return "?";
}

OptionType type_of(const OptionValue& v) {
  if (std::holds_alternative<double>(v)) return OptionType::Number;
  if (std::holds_alternative<std::string>(v)) return OptionType::String;
  return OptionType::List;
}

}  // namespace

void Options::set(std::string_view name, OptionValue value) {
  const int i = find(name);
  if (i < 0) {
    std::vector<std::string> names;
    for (const OptionSpec& o : kind_->options) {
      names.push_back(o.name);
      for (const std::string& a : o.aliases) names.push_back(a);
    }
    FieldError e(FieldErrc::UnknownOption,
                 fmt::format("unknown option '{}' for field kind '{}'", name, kind_->name));
    e.option = std::string(name);
    e.name = kind_->name;
    e.suggestion = closest_name(name, names);
    throw e;
  }
  const OptionSpec& spec = kind_->options[static_cast<std::size_t>(i)];
  if (type_of(value) != spec.type) {
    FieldError e(FieldErrc::WrongOptionType,
                 fmt::format("option '{}' of field kind '{}' expects {}, got {}", name,
                             kind_->name, type_name(spec.type), type_name(type_of(value))));
    e.option = std::string(name);
    e.name = kind_->name;
    e.expected = spec.type;
    e.given = type_of(value);
    throw e;
  }
  if (spec.role != OptionRole::Plain) {
    // Field ids are whole numbers: 2.5 is a mistake, not field 2.
    std::vector<double> ids;
    if (const double* d = std::get_if<double>(&value)) ids = {*d};
    else ids = std::get<std::vector<double>>(value);
    for (double id : ids)
      if (!std::isfinite(id) || id != std::floor(id) || std::fabs(id) > 2e9) {
        FieldError e(FieldErrc::BadValue,
                     fmt::format("option '{}' of field kind '{}' expects field ids, got {}", name,
                                 kind_->name, id));
        e.option = std::string(name);
        e.name = kind_->name;
        e.bad = BadValueWhat::NotFieldIds;
        e.value = id;
        throw e;
      }
  }
  values_[static_cast<std::size_t>(i)] = std::move(value);
  set_[static_cast<std::size_t>(i)] = true;
}

int Options::index_or_die(std::string_view name) const {
  const int i = find(name);
  if (i < 0) {
    FieldError e(FieldErrc::UnknownOption,
                 fmt::format("internal: kind '{}' has no option '{}'", kind_->name, name));
    e.option = std::string(name);
    e.name = kind_->name;
    throw e;
  }
  return i;
}

double Options::number(std::string_view name) const {
  return std::get<double>(values_[static_cast<std::size_t>(index_or_die(name))]);
}

const std::string& Options::string(std::string_view name) const {
  return std::get<std::string>(values_[static_cast<std::size_t>(index_or_die(name))]);
}

const std::vector<double>& Options::list(std::string_view name) const {
  return std::get<std::vector<double>>(values_[static_cast<std::size_t>(index_or_die(name))]);
}

bool Options::was_set(std::string_view name) const {
  return set_[static_cast<std::size_t>(index_or_die(name))];
}

}  // namespace sm::field
