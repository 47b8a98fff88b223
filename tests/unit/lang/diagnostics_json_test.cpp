// --diagnostics FILE's lines: location, severity, kind, message, place and figure, notes.
#include <doctest/doctest.h>

#include "lang/diagnostics.h"
#include "lang/diagnostics_json.h"
#include "lang/source.h"

TEST_CASE("diagnostics json: every field, nulls without a location") {
  sm::lang::SourceManager sources;
  const sm::lang::FileId f = sources.add_buffer("dir/w \"1\".geo", "x = 1;\nL[] = Coastline{1};\n").file;
  sm::lang::Diagnostics diags(sources);
  diags
      .report_message(sm::lang::SourceRange{f, 13, 25}, sm::lang::Diag::CoastlinePassageClosedAt,
                      "Coastline[1]: passage")
      .item({"passage closed", "width 42 m", true, 12.5, -0.25})
      .note(sm::lang::SourceRange{f, 0, 1}, "set here");
  diags.report_message(sm::lang::SourceRange{}, sm::lang::Diag::MeshBoundaryOffPlane, "tab\there");
  CHECK(sm::lang::diagnostic_json_line(sources, diags.all()[0]) ==
        "{\"file\": \"dir/w \\\"1\\\".geo\", \"line\": 2, \"col\": 7, \"severity\": \"warning\", "
        "\"kind\": \"coastline-passage\", \"message\": \"Coastline[1]: passage\", \"lon\": 12.5, \"lat\": -0.25, "
        "\"what\": \"passage closed\", \"figure\": \"width 42 m\", "
        "\"notes\": [{\"file\": \"dir/w \\\"1\\\".geo\", \"line\": 1, \"col\": 1, \"message\": \"set here\"}]}\n");
  CHECK(sm::lang::diagnostic_json_line(sources, diags.all()[1]) ==
        "{\"file\": null, \"line\": null, \"col\": null, \"severity\": \"warning\", \"kind\": \"mesh-warning\", "
        "\"message\": \"tab\\u0009here\"}\n");
}
