// A coastline import's report line (coast/import.h) as the parts of a diagnostic, shared
// by Coastline{} and Plugin(GSHHS), which report one diagnostic per line.
#pragma once

#include "coast/import.h"
#include "lang/diagnostics.h"

namespace sm::interp {

/// The sort of change, its figure and its lon/lat, for lang::Diagnostics::Handle::item.
lang::DiagItem coastline_item(const coast::ReportLine& line);

/// Reports a closed passage, a dam, water removed behind one, a passage kept open or a
/// dropped sea of Coastline[id] at `at`, worded by its kind (coast::RepairEntry), with its item.
lang::Diagnostics::Handle report_passage_change(lang::Diagnostics& diags, lang::SourceRange at, int id,
                                                const coast::ReportLine& line);

}  // namespace sm::interp
