// Report lines as diagnostic items (see coastline_report.h).
#include "interp/kernel/coastline_report.h"

#include <cmath>
#include <cstdint>
#include <type_traits>

#include <fmt/format.h>

#include "base/check.h"

namespace sm::interp {

lang::DiagItem coastline_item(const coast::ReportLine& line) {
  lang::DiagItem item;
  item.what = line.what;
  item.figure = line.figure;
  item.has_lonlat = line.has_place;
  item.lon = line.where.lon;
  item.lat = line.where.lat;
  item.rank = line.rank;
  return item;
}

namespace {

// The change's kind with its source record (the first of `with`) or without one.
template <class... Figures>
lang::Diagnostics::Handle report_placed(
    lang::Diagnostics& diags, lang::SourceRange at, int id, const coast::RepairEntry& e,
    std::type_identity_t<lang::DiagFormat<int, std::size_t, std::int64_t, double, double, Figures...>> with,
    std::type_identity_t<lang::DiagFormat<int, double, double, Figures...>> without, const Figures&... figures) {
  // Changes of no source record (the Region's own pieces) say only their place.
  if (e.record == static_cast<std::size_t>(-1))
    return diags.report(at, without, id, e.where.lon, e.where.lat, figures...);
  return diags.report(at, with, id, e.record, e.id, e.where.lon, e.where.lat, figures...);
}

}  // namespace

lang::Diagnostics::Handle report_passage_change(lang::Diagnostics& diags, lang::SourceRange at, int id,
                                                const coast::ReportLine& line) {
  using lang::Diag;
  using coast::RepairKind;
  SM_ASSERT(line.entry.has_value(), "a passage change without its repair entry");
  const coast::RepairEntry& e = *line.entry;
  const bool step = !std::isnan(e.step);   // with Mesh.MinTimeStep: the Courant step across it
  auto h = [&]() -> lang::Diagnostics::Handle {
    switch (e.kind) {
      case RepairKind::ClosedPassage:
        if (step)
          return report_placed(diags, at, id, e, Diag::CoastlinePassageClosedStep, Diag::CoastlinePassageClosedStepAt,
                               e.value, e.step);
        return report_placed(diags, at, id, e, Diag::CoastlinePassageClosed, Diag::CoastlinePassageClosedAt, e.value);
      case RepairKind::NarrowWater:
        return report_placed(diags, at, id, e, Diag::CoastlineNarrowWaterRemoved, Diag::CoastlineNarrowWaterRemovedAt,
                             e.value);
      case RepairKind::DamPlaced:
        return report_placed(diags, at, id, e, Diag::CoastlineDamPlaced, Diag::CoastlineDamPlacedAt, e.value);
      case RepairKind::KeptOpen:
        if (e.step_unmet)
          return report_placed(diags, at, id, e, Diag::CoastlineKeptOpenStepUnmet, Diag::CoastlineKeptOpenStepUnmetAt,
                               e.value, e.step);
        if (step)
          return report_placed(diags, at, id, e, Diag::CoastlineKeptOpenStep, Diag::CoastlineKeptOpenStepAt, e.value,
                               e.step);
        return report_placed(diags, at, id, e, Diag::CoastlineKeptOpen, Diag::CoastlineKeptOpenAt, e.value);
      case RepairKind::DroppedSea:
        return report_placed(diags, at, id, e, Diag::CoastlineSeaDropped, Diag::CoastlineSeaDroppedAt, e.value);
      default: break;
    }
    SM_ASSERT(false, "report_passage_change: not a passage, dam, kept-open passage or dropped sea");
    return diags.report(at, Diag::CoastlineRepair, fmt::format("Coastline[{}]", id), line.text);
  }();
  return h.item(coastline_item(line));
}

}  // namespace sm::interp
