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
  interp::Interpreter interpreter(sources, diags, null_out);
  interpreter.run_buffer("fuzz.geo", text);
  (void)diags.render_all();
}
#else
void evaluate_parsed(const std::string&) {}
#endif

}  // namespace sm::fuzz
