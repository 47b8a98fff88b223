// Report lines as diagnostic items (see coastline_report.h).
#include "interp/kernel/coastline_report.h"

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

}  // namespace sm::interp
