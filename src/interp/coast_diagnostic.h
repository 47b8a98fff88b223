// The coast kernel's errors in the script's words: a coast::CoastError's place in its file
// (the file, the record, the lon/lat) fills a kind of lang/diag_kinds.def, one kind per
// combination of the places it has; the reader's own sentence ends the message.
#pragma once

#include <optional>
#include <string>

#include "coast/coastline.h"
#include "lang/diag_format.h"

namespace sm::interp {

struct CoastDiagnostic {
  lang::Diag kind;
  std::string message;
};

/// The error of Coastline[coastline_id] (coastline-error), or, without an id, of
/// Plugin(GSHHS) (plugin-error).
CoastDiagnostic coast_diagnostic(const coast::CoastError& e, std::optional<int> coastline_id);

}  // namespace sm::interp
