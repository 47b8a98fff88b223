// Coast kernel errors worded through the diagnostic table: the file, record and place the
// error has choose the kind; the kebab names are those the script tests match on.
#include <doctest/doctest.h>

#include <string>

#include "interp/coast_diagnostic.h"
#include "lang/diagnostics.h"

using sm::coast::CoastError;
using sm::interp::coast_diagnostic;
using sm::lang::Diag;
using sm::lang::diag_info;

TEST_CASE("coast_diagnostic: one kind per place the error has, as the coastline's or the plugin's") {
  CoastError e;
  e.file = "coast.gshhs";
  e.message = "truncated header";
  CHECK(coast_diagnostic(e, 3).kind == Diag::CoastlineFileError);
  CHECK(coast_diagnostic(e, 3).message == "Coastline[3]: coast.gshhs: truncated header");
  CHECK(coast_diagnostic(e, std::nullopt).message == "coast.gshhs: truncated header");
  e.record = 12;
  CHECK(coast_diagnostic(e, 3).message == "Coastline[3]: coast.gshhs: record 12: truncated header");
  e.where = sm::geo::LonLat{-4.5, 53.25};
  CHECK(coast_diagnostic(e, 3).message ==
        "Coastline[3]: coast.gshhs: record 12 (lon -4.500000, lat 53.250000): truncated header");
  CHECK(coast_diagnostic(e, std::nullopt).kind == Diag::PluginRecordPlaceError);
  e.record = -1;
  e.file.clear();   // the import's own error: no file
  CHECK(coast_diagnostic(e, 1).message == "Coastline[1]: coastline (lon -4.500000, lat 53.250000): truncated header");
  CHECK(std::string(diag_info(coast_diagnostic(e, 1).kind).kebab) == "coastline-error");
  CHECK(std::string(diag_info(coast_diagnostic(e, std::nullopt).kind).kebab) == "plugin-error");
  // The kernel's own wording, which the table reproduces for each shape.
  for (const std::int64_t record : {std::int64_t{-1}, std::int64_t{5}})
    for (const bool place : {false, true}) {
      CoastError k;
      k.file = "f.shp";
      k.record = record;
      if (place) k.where = sm::geo::LonLat{1.0, 2.0};
      k.message = "bad";
      CHECK(coast_diagnostic(k, std::nullopt).message == k.to_string());
      CHECK(coast_diagnostic(k, 7).message == "Coastline[7]: " + k.to_string());
    }
}
