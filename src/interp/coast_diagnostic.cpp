// Coast kernel errors worded through the diagnostic table (see coast_diagnostic.h).
#include "interp/coast_diagnostic.h"

#include <type_traits>

namespace sm::interp {

using lang::Diag;

namespace {

template <class... Args>
CoastDiagnostic coast_worded(std::type_identity_t<lang::DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), lang::format_diag<Args...>(kind, args...)};
}

}  // namespace

CoastDiagnostic coast_diagnostic(const coast::CoastError& e, std::optional<int> coastline_id) {
  // An error of no file (the import's own) names the coastline.
  const std::string file = e.file.empty() ? std::string("coastline") : e.file;
  const bool record = e.record >= 0;
  if (coastline_id) {
    const int id = *coastline_id;
    if (record && e.where)
      return coast_worded(Diag::CoastlineRecordPlaceError, id, file, e.record, e.where->lon, e.where->lat, e.message);
    if (record) return coast_worded(Diag::CoastlineRecordError, id, file, e.record, e.message);
    if (e.where) return coast_worded(Diag::CoastlinePlaceError, id, file, e.where->lon, e.where->lat, e.message);
    return coast_worded(Diag::CoastlineFileError, id, file, e.message);
  }
  if (record && e.where)
    return coast_worded(Diag::PluginRecordPlaceError, file, e.record, e.where->lon, e.where->lat, e.message);
  if (record) return coast_worded(Diag::PluginRecordError, file, e.record, e.message);
  if (e.where) return coast_worded(Diag::PluginPlaceError, file, e.where->lon, e.where->lat, e.message);
  return coast_worded(Diag::PluginFileError, file, e.message);
}

}  // namespace sm::interp
