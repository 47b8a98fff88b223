// Expression evaluation: numbers, strings, variables and lists with Gmsh's
// scalar/list conversions, operators with Gmsh's integer and non-short-circuit
// rules, ranges, builtin calls and option reads.
#include <cmath>

#include <fmt/format.h>

#include "interp/kernel/dispatch.h"
#include "interp/format.h"
#include "interp/interpreter.h"
#include "interp/limits.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

std::string_view op_text(Tok op) {
  switch (op) {
    case Tok::Caret: return "^";
    case Tok::Star: return "*";
    case Tok::Slash: return "/";
    case Tok::Percent: return "%";
    case Tok::Pipe: return "|";
    case Tok::Amp: return "&";
    case Tok::Plus: return "+";
    case Tok::Minus: return "-";
    case Tok::Less: return "<";
    case Tok::Greater: return ">";
    case Tok::LessEq: return "<=";
    case Tok::GreaterEq: return ">=";
    case Tok::ShiftLeft: return "<<";
    case Tok::ShiftRight: return ">>";
    case Tok::EqEq: return "==";
    case Tok::NotEq: return "!=";
    case Tok::AmpAmp: return "&&";
    case Tok::PipePipe: return "||";
    case Tok::Not: return "!";
    default: return "?";
  }
}

// A known name close to `name` for "did you mean" hints, or "".
template <class Names>
std::string suggestion(std::string_view name, const Names& names) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const auto& n : names) {
    const std::string_view cand = n.first;
    const std::size_t d = edit_distance(name, cand);
    if (d < best_d) {
      best_d = d;
      best = std::string(cand);
    }
  }
  return best.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", best);
}

}  // namespace

long long Interpreter::to_int(double v, SourceRange r) {
  // Gmsh converts with a C (int) cast; values outside the exactly
  // representable integers are refused instead of being undefined behaviour.
  if (!(std::fabs(v) < 9007199254740992.0))
    fail(r, Diag::NotAnInteger, format_g(v));
  return static_cast<long long>(v);
}

std::string Interpreter::resolve_name(const Name& n) {
  if (n.from_string.valid()) return eval_string(n.from_string);
  std::string name(ast_.str(n.ident));
  for (ExprId suffix : n.suffixes)
    name = suffixed_name(name, static_cast<double>(to_int(eval_number(suffix), ast_.expr(suffix).range)));
  return name;
}

double Interpreter::eval_number(ExprId e) {
  const Value v = eval(e);
  if (!v.is_numeric())
    fail(ast_.expr(e).range, Diag::TypeExpectedNumber, kind_phrase(v));
  if (v.nums().empty())
    fail(ast_.expr(e).range, Diag::TypeExpectedNumber, std::string_view("an empty list"));
  return v.nums()[0];
}

std::string Interpreter::eval_string(ExprId e) {
  if (std::string name; physical_group_name(*this, e, name)) return name;
  const Value v = eval(e);
  if (!v.is_string())
    fail(ast_.expr(e).range, Diag::TypeExpectedString, kind_phrase(v));
  if (v.kind() == Value::Kind::StringList) return join_lines(v.strs());
  return v.strs()[0];
}

Value Interpreter::eval_list_arg(ExprId e) {
  const Expr& x = ast_.expr(e);
  if (const auto* v = std::get_if<VarExpr>(&x.node)) {
    const std::string name = resolve_name(v->name);
    if (const NumSymbol* sym = symbols_.find_num(name); sym && sym->is_list)
      return Value::list(sym->values);
  }
  return eval(e);
}

std::vector<double> Interpreter::eval_numbers(ExprId e) {
  Value v = eval(e);
  if (!v.is_numeric())
    fail(ast_.expr(e).range, Diag::TypeExpectedNumbers, kind_phrase(v));
  return std::move(v.nums());
}

Value Interpreter::eval(ExprId id) {
  const Expr& e = ast_.expr(id);
  const DepthGuard depth(*this, e.range);
  return std::visit(
      [&](const auto& n) -> Value {
        using T = std::decay_t<decltype(n)>;
        if constexpr (std::is_same_v<T, ErrorExpr>) {
          fail(e.range, Diag::EvalSyntaxError);
        } else if constexpr (std::is_same_v<T, NumberExpr>) {
          return Value::number(n.value);
        } else if constexpr (std::is_same_v<T, StringExpr>) {
          return Value::string(std::string(ast_.str(n.text)));
        } else if constexpr (std::is_same_v<T, VarExpr>) {
          return eval_var(e, n);
        } else if constexpr (std::is_same_v<T, ConstantExpr>) {
          if (constant_is_string(n.which)) {
            std::string s;
            builtin_string_constant(constant_text(n.which), env_, s);
            return Value::string(std::move(s));
          }
          switch (n.which) {
            case Constant::NewP: case Constant::NewL: case Constant::NewC: case Constant::NewLL:
            case Constant::NewCL: case Constant::NewS: case Constant::NewSL: case Constant::NewV:
            case Constant::NewReg: case Constant::NewF:
              return Value::number(new_tag_constant(*this, n.which));
            default: break;
          }
          double v = 0;
          if (!builtin_number_constant(constant_text(n.which), v))
            fail_fmt(e.range, Diag::UnknownVariable, constant_text(n.which), "");
          return Value::number(v);
        } else if constexpr (std::is_same_v<T, UnaryExpr>) {
          return eval_unary(e, n);
        } else if constexpr (std::is_same_v<T, BinaryExpr>) {
          return eval_binary(e, n);
        } else if constexpr (std::is_same_v<T, TernaryExpr>) {
          // Only the chosen branch is evaluated (Gmsh's yacc evaluates both).
          return eval_number(n.cond) != 0 ? eval(n.then_expr) : eval(n.else_expr);
        } else if constexpr (std::is_same_v<T, PostfixExpr>) {
          return eval_postfix(e, n);
        } else if constexpr (std::is_same_v<T, IndexExpr>) {
          return eval_index(e, n.name, n.index);
        } else if constexpr (std::is_same_v<T, WholeListExpr>) {
          return eval_whole(e, n.name);
        } else if constexpr (std::is_same_v<T, SliceExpr>) {
          const Value whole = eval_whole(e, n.name);
          const std::string name = resolve_name(n.name);
          std::vector<double> out;
          std::vector<std::string> sout;
          for (ExprId ie : n.indices) {
            for (double d : eval_numbers(ie)) {
              const long long i = to_int(d, ast_.expr(ie).range);
              const std::size_t size = whole.is_numeric() ? whole.nums().size() : whole.strs().size();
              if (i < 0 || static_cast<std::size_t>(i) >= size)
                fail_fmt(ast_.expr(ie).range, Diag::IndexOutOfRange, i, name, size);
              if (whole.is_numeric())
                out.push_back(whole.nums()[static_cast<std::size_t>(i)]);
              else
                sout.push_back(whole.strs()[static_cast<std::size_t>(i)]);
            }
          }
          return whole.is_numeric() ? Value::list(std::move(out)) : Value::string_list(std::move(sout));
        } else if constexpr (std::is_same_v<T, LengthExpr>) {
          const Value v = eval_list_arg(n.list);
          return Value::number(static_cast<double>(v.is_numeric() ? v.nums().size() : v.strs().size()));
        } else if constexpr (std::is_same_v<T, ListExpr>) {
          return eval_list(e, n);
        } else if constexpr (std::is_same_v<T, RangeExpr>) {
          return eval_range(e, n);
        } else if constexpr (std::is_same_v<T, CallExpr>) {
          return eval_call(e, n);
        } else if constexpr (std::is_same_v<T, OptionExpr>) {
          return read_option(n.option);
        } else {
          return eval_model_expr(*this, id);
        }
      },
      e.node);
}

std::string Interpreter::unknown_name_hint(const std::string& name) const {
  std::string hint = suggestion(name, symbols_.nums());
  if (hint.empty()) hint = suggestion(name, symbols_.strs());
  if (hint.empty()) {
    // `Sqr(2)` parses as indexing a variable 'Sqr': point at the function.
    std::vector<std::pair<std::string_view, int>> fns;
    for (const auto& b : lang::builtin_functions()) fns.emplace_back(b.name, 0);
    hint = suggestion(name, fns);
    if (!hint.empty()) hint.insert(hint.find('\'') , "the function ");
  }
  return hint;
}

Value Interpreter::eval_var(const Expr& e, const VarExpr& v) {
  const std::string name = resolve_name(v.name);
  if (const NumSymbol* sym = symbols_.find_num(name)) {
    // A list used as a scalar gives its element 0 (Gmsh).
    if (sym->values.empty())
      fail(e.range, Diag::TypeEmptyListNotNumber, name);
    return Value::number(sym->values[0]);
  }
  if (const auto* strs = symbols_.find_str(name)) {
    if (strs->empty())
      fail(e.range, Diag::TypeEmptyStringList, name);
    return Value::string((*strs)[0]);
  }
  fail_fmt(e.range, Diag::UnknownVariable, name, unknown_name_hint(name));
}

Value Interpreter::eval_whole(const Expr& e, const Name& n) {
  const std::string name = resolve_name(n);
  if (const NumSymbol* sym = symbols_.find_num(name)) return Value::list(sym->values);
  if (const auto* strs = symbols_.find_str(name)) return Value::string_list(*strs);
  fail_fmt(e.range, Diag::UnknownVariable, name, unknown_name_hint(name));
}

Value Interpreter::eval_index(const Expr& e, const Name& n, ExprId index) {
  // An index that is a number or a variable changes nothing when evaluated, so the list
  // is read in place: a copy of it per element read makes a script's loop over a list of
  // n points (the stdlib's over the shore points, ocean_fields.geo) take n^2 time. Any
  // other index may change the list (`a[a[0]++]`): it is read from a copy taken before.
  const auto& ix = ast_.expr(index).node;
  if (std::holds_alternative<NumberExpr>(ix) || std::holds_alternative<VarExpr>(ix) ||
      std::holds_alternative<ConstantExpr>(ix)) {
    const std::string name = resolve_name(n);
    const NumSymbol* sym = symbols_.find_num(name);
    const std::vector<std::string>* strs = sym ? nullptr : symbols_.find_str(name);
    if (!sym && !strs) fail_fmt(e.range, Diag::UnknownVariable, name, unknown_name_hint(name));
    const long long i = to_int(eval_number(index), ast_.expr(index).range);
    const std::size_t size = sym ? sym->values.size() : strs->size();
    if (i < 0 || static_cast<std::size_t>(i) >= size)
      fail_fmt(ast_.expr(index).range, Diag::IndexOutOfRange, i, name, size);
    if (sym) return Value::number(sym->values[static_cast<std::size_t>(i)]);
    return Value::string((*strs)[static_cast<std::size_t>(i)]);
  }
  const Value whole = eval_whole(e, n);
  const long long i = to_int(eval_number(index), ast_.expr(index).range);
  const std::size_t size = whole.is_numeric() ? whole.nums().size() : whole.strs().size();
  if (i < 0 || static_cast<std::size_t>(i) >= size)
    fail_fmt(ast_.expr(index).range, Diag::IndexOutOfRange, i, resolve_name(n), size);
  if (whole.is_numeric()) return Value::number(whole.nums()[static_cast<std::size_t>(i)]);
  return Value::string(whole.strs()[static_cast<std::size_t>(i)]);
}

Value Interpreter::eval_unary(const Expr& e, const UnaryExpr& u) {
  Value v = eval(u.operand);
  if (!v.is_numeric())
    fail(e.range, Diag::TypeOperatorOperand, op_text(u.op), kind_phrase(v));
  for (double& x : v.nums()) {
    if (u.op == Tok::Minus) x = -x;
    else if (u.op == Tok::Not) x = (x == 0) ? 1 : 0;
  }
  return v;
}

Value Interpreter::eval_binary(const Expr& e, const BinaryExpr& b) {
  // A long left-associative chain (`1+1+1+...`, 50 000 terms) is as deep as
  // it is long: walk its left spine with a loop instead of recursing.
  std::vector<const Expr*> spine{&e};
  ExprId leftmost = b.lhs;
  while (const auto* inner = std::get_if<BinaryExpr>(&ast_.expr(leftmost).node)) {
    spine.push_back(&ast_.expr(leftmost));
    leftmost = inner->lhs;
  }
  Value acc = eval(leftmost);
  for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
    const auto& node = std::get<BinaryExpr>((*it)->node);
    // Both sides are always evaluated: && and || do not short-circuit (Gmsh).
    const Value r = eval(node.rhs);
    acc = apply_binary(**it, node, acc, r);
  }
  return acc;
}

Value Interpreter::apply_binary(const Expr& e, const BinaryExpr& b, const Value& l, const Value& r) {
  if (!l.is_numeric() || !r.is_numeric())
    fail(e.range, Diag::TypeOperatorOperands, op_text(b.op), kind_phrase(l), kind_phrase(r));
  const SourceRange rr = ast_.expr(b.rhs).range;
  const SourceRange lr = ast_.expr(b.lhs).range;
  auto apply = [&](double x, double y) -> double {
    switch (b.op) {
      case Tok::Caret: return std::pow(x, y);
      case Tok::Star: return x * y;
      case Tok::Slash:
        if (y == 0) fail_fmt(rr, Diag::DivisionByZero);
        return x / y;
      case Tok::Percent: {
        // Integer modulo on (int)-converted operands, sign of the left (C).
        const long long yi = to_int(y, rr);
        if (yi == 0) fail_fmt(rr, Diag::DivisionByZero);
        return static_cast<double>(to_int(x, lr) % yi);
      }
      case Tok::Pipe: return static_cast<double>(to_int(x, lr) | to_int(y, rr));
      case Tok::Amp: return static_cast<double>(to_int(x, lr) & to_int(y, rr));
      case Tok::ShiftLeft:
      case Tok::ShiftRight: {
        const long long xi = to_int(x, lr), yi = to_int(y, rr);
        if (yi < 0 || yi > 52)
          fail(rr, Diag::ShiftCountRange, yi);
        if (b.op == Tok::ShiftRight) return static_cast<double>(xi >> yi);
        return static_cast<double>(xi) * std::ldexp(1.0, static_cast<int>(yi));
      }
      case Tok::Plus: return x + y;
      case Tok::Minus: return x - y;
      case Tok::Less: return x < y;
      case Tok::Greater: return x > y;
      case Tok::LessEq: return x <= y;
      case Tok::GreaterEq: return x >= y;
      case Tok::EqEq: return x == y;
      case Tok::NotEq: return x != y;
      case Tok::AmpAmp: return (x != 0) && (y != 0);
      case Tok::PipePipe: return (x != 0) || (y != 0);
      default:
        fail(e.range, Diag::UnknownOperator, op_text(b.op));
    }
  };
  const bool ll = l.kind() == Value::Kind::List, rl = r.kind() == Value::Kind::List;
  if (!ll && !rl) return Value::number(apply(l.nums()[0], r.nums()[0]));
  // `k*{...}`, `-{...}`, `{...}+1`: element by element, a scalar broadcast.
  const auto& a = l.nums();
  const auto& c = r.nums();
  if (ll && rl && a.size() != c.size())
    fail(e.range, Diag::ListOperandSizes, op_text(b.op), a.size(), c.size());
  const std::size_t n = ll ? a.size() : c.size();
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = apply(ll ? a[i] : a[0], rl ? c[i] : c[0]);
  return Value::list(std::move(out));
}

Value Interpreter::eval_range(const Expr& e, const RangeExpr& r) {
  const double a = eval_number(r.from);
  const double b = eval_number(r.to);
  if (!std::isfinite(a) || !std::isfinite(b))
    fail(e.range, Diag::NonFiniteRange, "range bounds");
  double step;
  if (r.step.valid()) {
    step = eval_number(r.step);
    if (step == 0) fail(ast_.expr(r.step).range, Diag::InvalidRange);
    if (!std::isfinite(step)) fail(ast_.expr(r.step).range, Diag::NonFiniteRange, "range step");
  } else {
    step = (a <= b) ? 1.0 : -1.0;   // `5:1` counts down
  }
  const double count = std::floor((b - a) / step) + 1;
  const std::size_t max_list = settings_.limits.max_list_size;
  if (count > static_cast<double>(max_list))
    fail(e.range, Diag::LimitRange, format_g(a), format_g(b), format_g(step), format_g(count), max_list);
  std::vector<double> out;
  if (count > 0) out.reserve(static_cast<std::size_t>(count) + 1);
  // Accumulated like Gmsh (d += step, no tolerance): 0:0.3:0.1 gives 0, 0.1, 0.2.
  for (double d = a; step > 0 ? d <= b : d >= b; d += step) {
    out.push_back(d);
    if (out.size() > max_list) break;
  }
  return Value::list(std::move(out));
}

Value Interpreter::eval_list(const Expr& e, const ListExpr& l) {
  std::vector<double> nums;
  std::vector<std::string> strs;
  for (ExprId item : l.items) {
    const Value v = eval(item);
    if (v.is_numeric()) {
      nums.insert(nums.end(), v.nums().begin(), v.nums().end());
    } else {
      strs.insert(strs.end(), v.strs().begin(), v.strs().end());
    }
    if (!nums.empty() && !strs.empty())
      fail(ast_.expr(item).range, Diag::TypeMixedList);
    if (nums.size() > settings_.limits.max_list_size)
      fail(e.range, Diag::LimitListLength, settings_.limits.max_list_size);
  }
  if (!strs.empty()) return Value::string_list(std::move(strs));
  return Value::list(std::move(nums));
}

Value Interpreter::eval_postfix(const Expr& e, const PostfixExpr& p) {
  const double delta = p.op == Tok::PlusPlus ? 1 : -1;
  const Expr& t = ast_.expr(p.target);
  if (const auto* v = std::get_if<VarExpr>(&t.node)) {
    const std::string name = resolve_name(v->name);
    NumSymbol* sym = symbols_.find_num(name);
    if (!sym) {
      if (symbols_.find_str(name))
        fail(t.range, Diag::TypeStringNotNumber, name);
      fail_fmt(t.range, Diag::UnknownVariable, name, unknown_name_hint(name));
    }
    if (sym->values.empty())
      fail(t.range, Diag::TypeEmptyListNotNumber, name);
    const double old = sym->values[0];
    sym->values[0] = old + delta;
    return Value::number(old);
  }
  if (const auto* ix = std::get_if<IndexExpr>(&t.node)) {
    const std::string name = resolve_name(ix->name);
    eval_index(t, ix->name, ix->index);   // checks existence and range
    NumSymbol* sym = symbols_.find_num(name);
    if (!sym) fail(t.range, Diag::TypeNotNumericList, name);
    const auto i = static_cast<std::size_t>(to_int(eval_number(ix->index), t.range));
    const double old = sym->values[i];
    sym->values[i] = old + delta;
    return Value::number(old);
  }
  if (const auto* o = std::get_if<OptionExpr>(&t.node)) {
    const double old = read_option(o->option).nums().at(0);
    const std::string name = option_name(o->option);
    if (auto err = options_.set_number(name, old + delta); !err.empty())
      fail_message(t.range, err.kind, std::move(err.message));
    return Value::number(old);
  }
  fail(e.range, Diag::IncDecExprTarget);
}

Value Interpreter::eval_call(const Expr& e, const CallExpr& c) {
  const lang::BuiltinFunction& fn = lang::builtin_function(c.fn);   // the parser found the row
  if (fn.pass == BuiltinPass::Model) return eval_field_call(*this, e, c);
  const std::size_t lo = static_cast<std::size_t>(fn.min_args);
  const std::size_t hi = fn.max_args < 0 ? static_cast<std::size_t>(-1) : static_cast<std::size_t>(fn.max_args);
  if (c.args.size() < lo || c.args.size() > hi)
    fail_fmt(c.func_range, Diag::WrongArgumentCount, fn.name,
             lo == hi ? fmt::format("{}", lo)
                      : (fn.max_args < 0 ? fmt::format("at least {}", lo) : fmt::format("{} to {}", lo, hi)),
             hi == 1 ? "" : "s", c.args.size());
  std::vector<Value> args;
  args.reserve(c.args.size());
  for (ExprId a : c.args) {
    switch (fn.pass) {
      case BuiltinPass::Name: {
        const Expr& x = ast_.expr(a);
        if (const auto* v = std::get_if<VarExpr>(&x.node)) {
          args.push_back(Value::string(resolve_name(v->name)));
        } else if (const auto* w = std::get_if<WholeListExpr>(&x.node)) {
          args.push_back(Value::string(resolve_name(w->name)));
        } else {
          fail(x.range, Diag::TypeNeedsVariableName, fn.name);
        }
        break;
      }
      case BuiltinPass::Lists:
        args.push_back(eval_list_arg(a));
        break;
      case BuiltinPass::Strings:
        if (std::string name; physical_group_name(*this, a, name))
          args.push_back(Value::string(std::move(name)));   // `StrCat("x", Physical Curve{1})`
        else
          args.push_back(eval(a));
        break;
      default:
        args.push_back(eval(a));
        break;
    }
  }
  try {
    return builtin_impl(c.fn)(env_, args);
  } catch (const BuiltinError& err) {
    const SourceRange where = (err.arg >= 0 && static_cast<std::size_t>(err.arg) < c.args.size())
                                  ? ast_.expr(c.args[static_cast<std::size_t>(err.arg)]).range
                                  : e.range;
    fail_fmt(where, Diag::BuiltinFailed, fn.name, err.message);
  }
}

}  // namespace sm::interp
