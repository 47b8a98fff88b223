// Diagnostics as JSON lines (--diagnostics FILE): one object per diagnostic, every one
// of them, for tools and for reading what the terminal groups and cuts.
#pragma once

#include <string>

#include "lang/diagnostics.h"

namespace sm::lang {

/// One line (ending with '\n'): {"file", "line", "col" (null without a location),
/// "severity", "kind" (the kebab name), "message", and when known "lon", "lat", "what",
/// "figure" (DiagItem), "notes": [{"file", "line", "col", "message"}]}.
std::string diagnostic_json_line(const SourceManager& sources, const Diagnostic& d);

}  // namespace sm::lang
