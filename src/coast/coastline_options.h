// The options of a coastline (`Coastline[n].Option = value;`) described by one table
// (coastline_options.def), as the field kinds describe theirs (field/registry.h): each
// row gives the name, the type, the check, one line of help and the member of
// CoastlineSettings it sets. The interpreter reads, checks and applies options through
// it; docs/interpreter.md's option table is generated from it (coast_options_markdown).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "coast/coastline_option_id.h"
#include "coast/import.h"
#include "coast/read_loops2.h"

namespace sm::coast {

/// Everything the options of one coastline set: how its file is read and how it is
/// imported. The members the caller finishes itself are said so.
struct CoastlineSettings {
  std::string file_name;               ///< the caller resolves it against the script
  std::string resolution = "l";        ///< GSHHG: the system's binned file when file_name is empty
  /// The size field giving gamma(x): the caller builds it into import.gamma (required).
  std::optional<int> accuracy_field;
  std::string region_file;             ///< read by the caller into the Region (a polygon)
  std::string patch_file;              ///< read by the caller into import.patch
  Loops2Options loops2;
  ImportOptions import;
};

enum class CoastOptionType { Number, Flag, String, Path, List };

/// A value as the script gives it: numbers, or strings (`str` the first).
struct CoastOptionValue {
  std::span<const double> nums;
  std::string_view str;
  bool is_string = false;
  std::size_t strings = 0;
};

struct CoastOptionSpec {
  std::string_view name;
  CoastOptionType type;
  std::string_view only;     ///< "" for every format, else the one it applies to
  std::string_view values;   ///< the values it takes (docs)
  void (*apply)(CoastlineSettings&, const CoastOptionValue&);
  std::string (*default_of)(const CoastlineSettings&);   ///< the default, read from CoastlineSettings{}
  std::string_view target;   ///< the member(s) it sets, as the kernel spells them
  /// Why a value of the right type is refused ("must be 0, 5 or 6, not 3"), or nullopt.
  std::optional<std::string> (*check)(const CoastOptionValue&);
  std::string_view help;
};

/// Every option, in the table's order.
std::span<const CoastOptionSpec> coast_options();
const CoastOptionSpec& coast_option(CoastOpt o);
/// Exact (case-sensitive) lookup; nullptr if unknown.
const CoastOptionSpec* find_coast_option(std::string_view name);
/// Why `v` is not a value of `o`'s type or passes not its check ("takes one number, not a
/// list of 2"), or nullopt: the whole check, for the message "Coastline[n].Name <why>".
std::optional<std::string> check_coast_option(const CoastOptionSpec& o, const CoastOptionValue& v);
/// The markdown table of every option (docs/interpreter.md's generated part).
std::string coast_options_markdown();

}  // namespace sm::coast
