// Builtins of variable names (BuiltinPass::Name): the evaluator passes the
// name written as the argument, `Exists(x)` or `NameToString[x~{2}]`, as a
// string, never the variable's value.
#include "interp/builtins/builtins.h"

namespace sm::interp {

Value f_exists(BuiltinEnv& env, const std::vector<Value>& a) {
  return Value::number(env.symbols.exists(arg_string(a, 0)) ? 1 : 0);
}

Value f_name_to_string(BuiltinEnv&, const std::vector<Value>& a) { return Value::string(arg_string(a, 0)); }

}  // namespace sm::interp
