// Diagnostics engine: exact rendering, line tables, error limit, long lines, flush.
#include <doctest/doctest.h>

#include "lang/diagnostics.h"
#include "lang/source.h"

using namespace sm::lang;

TEST_CASE("diagnostics: clang-style rendering with caret, tildes and notes") {
  SourceManager sm;
  const FileId f = sm.add_buffer("coast.geo", "For i In {1:3}\n  lon = 1;\n\tPoint(7) = {lon, lat, 0}\nEndFor\n").file;
  Diagnostics diags(sm);
  diags.report(SourceRange{f, 51, 51}, Diag::ExpectedSemicolon).note(SourceRange{f, 0, 3}, "inside this 'For' loop");
  CHECK(diags.error_count() == 1);
  CHECK(diags.render_all() ==
        std::string("coast.geo:3:26: error: expected ';' after statement [expected-semicolon]\n"
                    "    3 | \tPoint(7) = {lon, lat, 0}\n")
        + "      | \t" + std::string(24, ' ') + "^\n"
        "coast.geo:1:1: note: inside this 'For' loop\n");
  Diagnostics d2(sm);
  d2.report(SourceRange{f, 17, 20}, Diag::UnknownCommand, "lon");
  CHECK(d2.render_all() ==
        "coast.geo:2:3: error: unknown command 'lon' [unknown-command]\n"
        "    2 |   lon = 1;\n"
        "      |   ^~~\n");
}

TEST_CASE("diagnostics: line table, CRLF, end of file") {
  SourceManager sm;
  const FileId f = sm.add_buffer("a.geo", "ab\r\ncd\n\nx").file;
  CHECK(sm.line_count(f) == 4);
  CHECK(sm.line_text(f, 1) == "ab");
  CHECK(sm.line_text(f, 4) == "x");
  CHECK(sm.line_col({f, 5}).line == 2);
  CHECK(sm.line_col({f, 5}).col == 2);
  CHECK(sm.line_col({f, 10}).line == 4);
  CHECK(sm.line_col({f, 10}).col == 2);  // one past the last byte
}

TEST_CASE("diagnostics: error limit stops with one message") {
  SourceManager sm;
  const FileId f = sm.add_buffer("a.geo", "x").file;
  Diagnostics diags(sm);
  diags.set_max_errors(3);
  for (int i = 0; i < 10; ++i)
    diags.report(SourceRange{f, 0, 1}, Diag::UnknownCommand, "x").note(SourceRange{}, "dropped?");
  CHECK(diags.too_many_errors());
  CHECK(diags.all().size() == 4);
  CHECK(diags.all().back().message == "too many errors (3), stopping");
  CHECK(diags.all()[2].notes.size() == 1);
}

TEST_CASE("diagnostics: long lines are shown as a window around the caret") {
  SourceManager sm;
  std::string line(1000000, 'a');
  line[500000] = ';';
  const FileId f = sm.add_buffer("long.geo", line).file;
  Diagnostics diags(sm);
  diags.report(SourceRange{f, 500000, 500001}, Diag::ExpectedStatement, "';'");
  const std::string out = diags.render_all();
  CHECK(out.size() < 600);
  CHECK(out.find("long.geo:1:500001: error:") == 0);
  const auto l2 = out.find("    1 | ...");
  REQUIRE(l2 != std::string::npos);
  const auto semi = out.find(';', l2) - l2;
  const auto caret = out.find('^') - out.find('\n', l2) - 1;
  CHECK(semi == caret);
}

TEST_CASE("diagnostics: a file not loaded says why, for the caller to word") {
  SourceManager sm;
  auto r = sm.load_file("/nonexistent/dir/x.geo");
  CHECK_FALSE(r.file.valid());
  CHECK(r.failure == SourceManager::LoadFailure::CannotOpen);
  CHECK(r.reason == "No such file or directory");
  CHECK(format_diag<std::string, std::string>(Diag::ScriptCannotOpen, "/nonexistent/dir/x.geo", r.reason) ==
        "cannot open '/nonexistent/dir/x.geo': No such file or directory");
  r = sm.load_file("/tmp");
  CHECK_FALSE(r.file.valid());
  CHECK(r.failure == SourceManager::LoadFailure::IsDirectory);
  CHECK(format_diag<std::string>(Diag::IncludeIsDirectory, "/tmp") == "cannot read '/tmp': is a directory");
  CHECK(diag_from_kebab("expected-semicolon") == Diag::ExpectedSemicolon);
}

TEST_CASE("diagnostics: caret alignment after UTF-8 and control bytes; multi-line ranges") {
  SourceManager sm;
  const FileId f = sm.add_buffer("u.geo", "s = \"\xc3\xa9t\xc3\xa9\" @;\nx = {1,\n 2};\n").file;
  Diagnostics diags(sm);
  diags.report(SourceRange{f, 12, 13}, Diag::UnexpectedCharacter, "@");
  diags.report(SourceRange{f, 19, 28}, Diag::ExpectedSemicolon);  // from '{' on line 2 into line 3
  CHECK(diags.render_all() ==
        "u.geo:1:13: error: unexpected character '@' [unexpected-character]\n"
        "    1 | s = \"\xc3\xa9t\xc3\xa9\" @;\n"
        "      |           ^\n"
        "u.geo:2:5: error: expected ';' after statement [expected-semicolon]\n"
        "    2 | x = {1,\n"
        "      |     ^~~\n");
  Diagnostics d2(sm);
  const FileId g = sm.add_buffer("c.geo", std::string("a\x01" "b = 1;", 8)).file;
  d2.report(SourceRange{g, 4, 5}, Diag::ExpectedSemicolon).note(SourceRange{}, "no location");
  CHECK(d2.render_all() ==
        "c.geo:1:5: error: expected ';' after statement [expected-semicolon]\n"
        "    1 | a?b = 1;\n"
        "      |     ^\n"
        "note: no location\n");
}

TEST_CASE("diagnostics: flush writes each diagnostic once") {
  SourceManager sm;
  const FileId f = sm.add_buffer("a.geo", "x").file;
  Diagnostics diags(sm);
  diags.report(SourceRange{f, 0, 1}, Diag::UnknownCommand, "x");
  std::FILE* tmp = std::tmpfile();
  REQUIRE(tmp);
  CHECK(diags.flush(tmp) == 1);
  CHECK(diags.flush(tmp) == 0);
  diags.report(SourceRange{}, Diag::StatementAfterCall, "Include");
  CHECK(diags.flush(tmp) == 1);
  CHECK(diags.warning_count() == 1);
  CHECK(std::ftell(tmp) > 0);
  std::fclose(tmp);
}
