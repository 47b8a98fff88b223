// Front-end invariants checked on every fuzz input: parsing terminates without
// crashing, `ok` agrees with the error count, every diagnostic lies inside the
// file and renders, and the AST dump visits every node.
#include "fuzz_geo_entry.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_geo_eval.h"
#include "lang/ast.h"
#include "lang/diagnostics.h"
#include "lang/parser.h"
#include "lang/source.h"

namespace sm::fuzz {

namespace {

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "fuzz_geo: front-end invariant violated: %s\n", what);
  std::abort();
}

void check_range(const lang::SourceManager& sm, lang::SourceRange r) {
  if (!r.valid()) return;
  if (r.file.value >= sm.file_count()) violated("diagnostic in an unknown file");
  const std::size_t n = sm.text(r.file).size();
  if (r.begin > r.end || r.end > n) violated("diagnostic range outside its file");
}

// The evaluator runs with the interpreter's production limits (1e8 statements,
// lists of 1e8 items), which take minutes under ASan; until the interpreter
// takes per-run limits, only scripts without loops, ranges, macros, includes
// and commands that sleep or spawn are evaluated. The check reads the AST dump
// (a false positive inside a string literal only skips an evaluation).
// The evaluator runs every script the parser accepts, under small per-run
// limits (fuzz_geo_eval.cpp), except statements that touch the file system
// or the clock: they would write files, read arbitrary paths (an Include of
// /dev/zero) or sleep, which is not what the fuzzer is for.
bool safe_to_evaluate(const std::string& dumped) {
  static constexpr const char* kOutside[] = {
      "(include ",          "(call ListFromFile", "(command Sleep", "(command SystemCall",
      "(command NonBlockingSystemCall", "(command Save", "(command Merge", "(command CreateDir",
      "(command Mesh",      "(plugin ",           "(coastline",     "> \"",
      ">> \"",              "(field-option ",     "(call FileExists", "(call GetEnv",
  };
  for (const char* k : kOutside)
    if (dumped.find(k) != std::string::npos) return false;
  return true;
}

}  // namespace

void run_geo_input(const std::uint8_t* data, std::size_t size) {
  lang::SourceManager sources;
  std::string text(reinterpret_cast<const char*>(data), size);
  const auto loaded = sources.add_buffer("fuzz.geo", text);
  if (!loaded.file.valid()) return;  // over the size limit: refused with a message
  lang::Diagnostics diags(sources);
  lang::Ast ast;
  const lang::ParseResult r = lang::parse_file(sources, loaded.file, ast, diags);
  if (r.ok != (diags.error_count() == 0)) violated("ParseResult::ok disagrees with the error count");
  for (const lang::Diagnostic& d : diags.all()) {
    check_range(sources, d.range);
    for (const lang::DiagNote& n : d.notes) check_range(sources, n.range);
    if (d.message.empty()) violated("empty diagnostic message");
  }
  const std::string rendered = diags.render_all();
  if (!diags.all().empty() && rendered.empty()) violated("diagnostics rendered to nothing");
  const std::string dumped = lang::dump(ast, r.stmts);
  if (r.ok && !r.stmts.empty() && dumped.empty()) violated("empty AST dump");
  if (r.ok && safe_to_evaluate(dumped)) evaluate_parsed(text);
}

}  // namespace sm::fuzz
