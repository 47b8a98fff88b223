// The evaluator half of the fuzz target (see fuzz_geo_eval.h).
#include "fuzz_geo_eval.h"

#ifdef SM_FUZZ_WITH_INTERP
#include <ostream>
#include <streambuf>

#include "interp/interpreter.h"
#include "lang/diagnostics.h"
#include "lang/source.h"
#endif

namespace sm::fuzz {

#ifdef SM_FUZZ_WITH_INTERP
namespace {
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};
}  // namespace

void evaluate_parsed(const std::string& text) {
  NullBuffer null_buffer;
  std::ostream null_out(&null_buffer);
  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  // Small limits keep every input fast under ASan (loops, ranges, macro
  // recursion and huge lists all hit a limit with a clean diagnostic).
  interp::RunSettings settings;
  settings.limits.max_statements = 100000;
  settings.limits.max_list_size = 100000;
  settings.limits.max_string_size = 100000;
  settings.limits.max_call_depth = 64;
  settings.limits.max_include_depth = 4;
  interp::Interpreter interpreter(sources, diags, null_out, settings);
  interpreter.run_buffer("fuzz.geo", text);
  (void)diags.render_all();
}
#else
void evaluate_parsed(const std::string&) {}
#endif

}  // namespace sm::fuzz
