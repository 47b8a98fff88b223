// A statement's many diagnostics of one location: one header with the caret, counts per
// kind and per sort, a few places and figures, and the line saying how to see them all.
#include <doctest/doctest.h>

#include <string>

#include "lang/diagnostic_groups.h"
#include "lang/diagnostics.h"
#include "lang/source.h"

namespace {

// Count of `needle` in `s`.
std::size_t occurrences(const std::string& s, const std::string& needle) {
  std::size_t n = 0;
  for (auto p = s.find(needle); p != std::string::npos; p = s.find(needle, p + 1)) ++n;
  return n;
}

// 7 narrow straits and 2 closed passages at one statement, then one warning elsewhere.
struct ImportLike {
  sm::lang::SourceManager sources;
  sm::lang::FileId f = sources.add_buffer("w.geo", "x = 1;\nL[] = Coastline{1};\n").file;
  sm::lang::Diagnostics diags{sources};
  ImportLike() {
    const sm::lang::SourceRange at{f, 13, 25};  // Coastline{1}
    diags.report(at, sm::lang::Diag::CoastlineRepair, "Coastline[1]", "cleaning: 3 spikes removed");
    for (int i = 0; i < 7; ++i)
      diags.report(at, sm::lang::Diag::CoastlineRepair, "Coastline[1]", "record ... strait")
          .item({"strait kept open", "width " + std::to_string(100 + i) + " m", true, 10.0 + i, -5.5});
    // Two kinds of one kebab name (a passage with and without its source record): one kind
    // and one sort to the reader.
    for (const sm::lang::Diag kind : {sm::lang::Diag::CoastlinePassageClosed, sm::lang::Diag::CoastlinePassageClosedAt})
      diags.report_message(at, kind, "Coastline[1]: passage").item({"passage closed", "width 42 m", true, 1, 2});
    diags.report(sm::lang::SourceRange{f, 0, 1}, sm::lang::Diag::UserWarning, fmt::arg("text", "elsewhere"));
  }
};

}  // namespace

TEST_CASE("diagnostic groups: one caret, counts per kind and sort, cut with a way to see all") {
  ImportLike r;
  sm::lang::GroupRenderOptions opt;
  opt.how_to_see_all = "see all";
  const std::string s = sm::lang::render_grouped(r.diags, r.diags.all(), opt);
  INFO(s);
  CHECK(s.find("w.geo:2:7: warning: 10 warnings from this statement: 8 [coastline-repair], 2 [coastline-passage]\n"
               "    2 | L[] = Coastline{1};\n"
               "      |       ^~~~~~~~~~~~\n") == 0);
  CHECK(occurrences(s, "L[] = Coastline{1};") == 1);
  CHECK(s.find("  Coastline[1]: cleaning: 3 spikes removed [coastline-repair]\n") != std::string::npos);
  CHECK(s.find("  7 x strait kept open [coastline-repair]\n"
               "      lon 10.0000, lat -5.5000: width 100 m\n"
               "      lon 11.0000, lat -5.5000: width 101 m\n"
               "      lon 12.0000, lat -5.5000: width 102 m\n"
               "      ... and 4 more\n") != std::string::npos);
  CHECK(s.find("  2 x passage closed [coastline-passage]\n") != std::string::npos);
  CHECK(s.find("  (4 of 10 not listed: see all)\n") != std::string::npos);
  // The other statement's warning is rendered alone, as before.
  CHECK(s.find("w.geo:1:1: warning: elsewhere [user-warning]\n") != std::string::npos);

  opt.list_all = true;
  const std::string all = sm::lang::render_grouped(r.diags, r.diags.all(), opt);
  CHECK(all.find("width 106 m") != std::string::npos);
  CHECK(all.find("not listed") == std::string::npos);
  CHECK(occurrences(all, "L[] = Coastline{1};") == 1);
}

TEST_CASE("diagnostic groups: a lone diagnostic, and those without a location, are rendered as before") {
  sm::lang::SourceManager sources;
  sm::lang::Diagnostics diags(sources);
  diags.report_message(sm::lang::SourceRange{}, sm::lang::Diag::MeshBoundaryOffPlane, "one");
  diags.report_message(sm::lang::SourceRange{}, sm::lang::Diag::MeshBoundaryOffPlane, "two");
  sm::lang::GroupRenderOptions opt;
  opt.unlocated_prefix = "prog: ";
  CHECK(sm::lang::render_grouped(diags, diags.all(), opt) ==
        "prog: warning: one [mesh-warning]\n"
        "prog: warning: two [mesh-warning]\n");
  // Same place, different notes: two groups of one.
  const sm::lang::FileId f = sources.add_buffer("n.geo", "Warning(\"x\");\n").file;
  const sm::lang::SourceRange at{f, 0, 7};
  diags.report_message(at, sm::lang::Diag::UserWarning, "a").note(sm::lang::SourceRange{f, 0, 1}, "first");
  diags.report_message(at, sm::lang::Diag::UserWarning, "b").note(sm::lang::SourceRange{f, 0, 1}, "second");
  const std::string s = sm::lang::render_grouped(diags, std::span(diags.all()).subspan(2), opt);
  CHECK(s.find("from this statement") == std::string::npos);
  CHECK(s.find("n.geo:1:1: warning: a [user-warning]") == 0);
}

TEST_CASE("diagnostic groups: a ranked sort lists its largest five, largest first") {
  sm::lang::SourceManager sources;
  const sm::lang::FileId f = sources.add_buffer("w.geo", "L[] = Coastline{1};\n").file;
  sm::lang::Diagnostics diags{sources};
  const sm::lang::SourceRange at{f, 6, 18};
  const double widths[] = {300, 1900, 40, 1200, 800, 1500, 90};
  for (double w : widths) {
    sm::lang::DiagItem item{"passage closed", "width " + std::to_string(static_cast<int>(w)) + " m", true, w / 100, 0};
    item.rank = w;
    diags.report_message(at, sm::lang::Diag::CoastlinePassageClosedAt, "Coastline[1]: passage").item(item);
  }
  sm::lang::GroupRenderOptions opt;
  opt.how_to_see_all = "see all";
  const std::string s = sm::lang::render_grouped(diags, diags.all(), opt);
  INFO(s);
  CHECK(s.find("  7 x passage closed [coastline-passage]\n"
               "      lon 19.0000, lat 0.0000: width 1900 m\n"
               "      lon 15.0000, lat 0.0000: width 1500 m\n"
               "      lon 12.0000, lat 0.0000: width 1200 m\n"
               "      lon 8.0000, lat 0.0000: width 800 m\n"
               "      lon 3.0000, lat 0.0000: width 300 m\n"
               "      ... and 2 more\n") != std::string::npos);
  opt.list_all = true;   // every one, in the order reported
  const std::string all = sm::lang::render_grouped(diags, diags.all(), opt);
  CHECK(all.find("width 300 m\n      lon 19.0000, lat 0.0000: width 1900 m\n      lon 0.4000") != std::string::npos);
}
