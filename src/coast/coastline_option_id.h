// The coastline options by name, for code that names one (an error pointing at the option
// at fault, the interpreter's records) without the table itself (coastline_options.h):
// each is spelled only in coastline_options.def.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace sm::coast {

enum class CoastOpt : std::size_t {
#define SM_COAST_OPTION(name, ...) name,
#include "coast/coastline_options.def"
#undef SM_COAST_OPTION
};

/// The name the script spells ("MinChannelWidth").
std::string_view coast_option_name(CoastOpt o);
/// The same as a string, for CoastError::option.
inline std::string coast_option_string(CoastOpt o) { return std::string(coast_option_name(o)); }

}  // namespace sm::coast
