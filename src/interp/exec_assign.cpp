// Assignments with Gmsh's storage rules: `x = {..}` makes a list unless it has
// exactly one item, `+=`/`-=` append/remove on lists, `L[i] = v` grows a list
// with zeros, options are typed and validated; DefineConstant and Delete.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "interp/format.h"
#include "interp/interpreter.h"
#include "interp/limits.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

bool known_other_category(std::string_view c) {
  return c == "View" || c == "Print" || c == "PostProcessing" || c == "Solver" || c == "Plugin";
}

// Options that change only how Gmsh's window draws post-processing views or prints it.
bool display_category(std::string_view c) { return c == "View" || c == "Print" || c == "PostProcessing"; }

}  // namespace

std::string Interpreter::option_name(const OptionRef& o) {
  std::string name(ast_.str(o.category));
  if (o.index.valid())
    name += fmt::format("[{}]", to_int(eval_number(o.index), ast_.expr(o.index).range));
  name += '.';
  name += ast_.str(o.member);
  if (o.sub_member.valid()) {
    name += '.';
    name += ast_.str(o.sub_member);
  }
  return name;
}

Value Interpreter::read_option(const OptionRef& o) {
  const std::string name = option_name(o);
  const OptionInfo* info = options_.find(name);
  if (!info) {
    if (known_other_category(ast_.str(o.category)))
      fail_fmt(o.range, Diag::NotSupportedYet, fmt::format("{}.* options", ast_.str(o.category)), "");
    fail_fmt(o.range, Diag::UnknownOption, name, fmt::format(" (did you mean '{}'?)", options_.closest(name)));
  }
  switch (info->kind) {
    case OptionKind::Number: return Value::number(options_.number(info->name));
    case OptionKind::String: return Value::string(options_.string(info->name));
    case OptionKind::Color: {
      const Color& c = options_.color(info->name);
      return Value::list({c[0], c[1], c[2], c[3]});
    }
    case OptionKind::Box: {
      const LonLatBox& b = options_.box(info->name);
      return Value::list({b[0], b[1], b[2], b[3]});
    }
  }
  return Value();
}

void Interpreter::assign_option(const LValue& t, AffOp op, ExprId value, SourceRange r) {
  const OptionRef& o = t.option;
  const std::string name = option_name(o);
  const OptionInfo* info = options_.find(name);
  if (!info) {
    if (display_category(ast_.str(o.category))) {
      // Views' drawing and printing options only matter to Gmsh's window: the value is
      // evaluated (its mistakes are the script's), then skipped with one note per run.
      (void)eval(value);
      display_only_stmt(current_stmt_, fmt::format("{}.* options", ast_.str(o.category)));
      return;
    }
    if (known_other_category(ast_.str(o.category))) {
      // Solver and plugin options would change what a run computes: not supported yet.
      not_supported_stmt(current_stmt_, fmt::format("{}.* options", ast_.str(o.category)));
      return;
    }
    fail_fmt(o.range, Diag::UnknownOption, name, fmt::format(" (did you mean '{}'?)", options_.closest(name)));
  }
  const SourceRange vr = ast_.expr(value).range;
  OptionRefusal err;
  switch (info->kind) {
    case OptionKind::Number: {
      const double v = eval_number(value);
      double cur = options_.number(info->name);
      switch (op) {
        case AffOp::Assign: cur = v; break;
        case AffOp::Add: cur += v; break;
        case AffOp::Sub: cur -= v; break;
        case AffOp::Mul: cur *= v; break;
        case AffOp::Div:
          if (v == 0) fail_fmt(vr, Diag::DivisionByZero);
          cur /= v;
          break;
      }
      err = options_.set_number(name, cur);
      break;
    }
    case OptionKind::String: {
      if (op != AffOp::Assign)
        fail(r, Diag::OptionOnlyAssign, std::string_view("string"), name);
      err = options_.set_string(name, eval_string(value));
      break;
    }
    case OptionKind::Color: {
      if (op != AffOp::Assign)
        fail(r, Diag::OptionOnlyAssign, std::string_view("color"), name);
      Color c{0, 0, 0, 255};
      const Expr& ve = ast_.expr(value);
      // `= Red`: a colour name written as an identifier or a string.
      std::string cname;
      if (const auto* v = std::get_if<VarExpr>(&ve.node); v && !v->name.from_string.valid() &&
                                                           v->name.suffixes.empty())
        cname = std::string(ast_.str(v->name.ident));
      else if (const auto* s = std::get_if<StringExpr>(&ve.node))
        cname = std::string(ast_.str(s->text));
      if (!cname.empty()) {
        if (!named_color(cname, c))
          fail(vr, Diag::OptionUnknownColorName, cname);
      } else {
        const std::vector<double> rgba = eval_numbers(value);
        if (rgba.size() != 3 && rgba.size() != 4)
          fail(vr, Diag::OptionColorSize, rgba.size());
        std::copy(rgba.begin(), rgba.end(), c.begin());
      }
      err = options_.set_color(name, c);
      break;
    }
    case OptionKind::Box: {
      if (op != AffOp::Assign)
        fail(r, Diag::OptionOnlyAssign, std::string_view("box"), name);
      const std::vector<double> v = eval_numbers(value);
      if (v.size() != 4)
        fail(vr, Diag::OptionBoxSize, name, v.size());
      err = options_.set_box(name, {v[0], v[1], v[2], v[3]});
      break;
    }
  }
  if (!err.empty()) fail_message(vr, err.kind, std::move(err.message));
  kernel_.option_set_at[std::string(info->name)] = r;
}

void Interpreter::exec_assign(const Stmt& s, const AssignStmt& a) {
  const LValue& t = a.target;
  if (t.kind == LValue::Kind::Option) {
    assign_option(t, a.op, a.value, s.range);
    return;
  }
  const std::string name = resolve_name(t.name);
  const SourceRange vr = ast_.expr(a.value).range;
  auto grow_check = [&](std::size_t n) {
    if (n > settings_.limits.max_list_size)
      fail(s.range, Diag::LimitListGrowth, name, settings_.limits.max_list_size);
  };
  auto arith = [&](double cur, double v) -> double {
    switch (a.op) {
      case AffOp::Assign: return v;
      case AffOp::Add: return cur + v;
      case AffOp::Sub: return cur - v;
      case AffOp::Mul: return cur * v;
      case AffOp::Div:
        if (v == 0) fail_fmt(vr, Diag::DivisionByZero);
        return cur / v;
    }
    return v;
  };
  auto list_update = [&](std::vector<double>& list, const std::vector<double>& items) {
    if (a.op == AffOp::Add) {
      grow_check(list.size() + items.size());
      list.insert(list.end(), items.begin(), items.end());
    } else if (a.op == AffOp::Sub) {
      // Removes the first occurrence of each item (Gmsh).
      for (double x : items) {
        auto it = std::find(list.begin(), list.end(), x);
        if (it != list.end()) list.erase(it);
      }
    } else {
      fail(s.range, Diag::OperatorOnList, affop_text(a.op), name);
    }
  };

  switch (t.kind) {
    case LValue::Kind::Var:
    case LValue::Kind::WholeList: {
      const bool whole = t.kind == LValue::Kind::WholeList;
      Value v = whole ? eval_list_arg(a.value) : eval(a.value);
      if (v.is_string()) {
        std::vector<std::string> strs = v.strs();
        if (!whole && strs.size() != 1) strs = {join_lines(strs)};
        if (a.op == AffOp::Assign) {
          symbols_.set_str(name, std::move(strs));
        } else if (a.op == AffOp::Add && whole) {
          std::vector<std::string> cur;
          if (const auto* old = symbols_.find_str(name)) cur = *old;
          cur.insert(cur.end(), strs.begin(), strs.end());
          symbols_.set_str(name, std::move(cur));
        } else {
          fail(s.range, Diag::OperatorOnStrings, affop_text(a.op));
        }
        return;
      }
      const bool rhs_list = v.kind() == Value::Kind::List && v.nums().size() != 1;
      if (a.op == AffOp::Assign) {
        // `x = {a, b}` is a list, `x = {a}` a scalar; `L[] = ...` always a list.
        symbols_.set_num(name, NumSymbol{std::move(v.nums()), whole || rhs_list});
        return;
      }
      NumSymbol* sym = symbols_.find_num(name);
      if (!sym) {
        if (whole || (rhs_list && a.op == AffOp::Add)) {
          if (a.op != AffOp::Add)
            fail_fmt(t.range, Diag::UnknownVariable, name, "");
          symbols_.set_num(name, NumSymbol{std::move(v.nums()), true});
          return;
        }
        if (symbols_.find_str(name))
          fail(t.range, Diag::TypeStringNotNumber, name);
        fail_fmt(t.range, Diag::UnknownVariable, name, "");
      }
      if (whole || sym->is_list || rhs_list) {
        list_update(sym->values, v.nums());
        sym->is_list = true;
        return;
      }
      if (v.nums().empty()) fail(vr, Diag::TypeExpectedNumber, std::string_view("an empty list"));
      sym->values.resize(1);
      sym->values[0] = arith(sym->values[0], v.nums()[0]);
      return;
    }
    case LValue::Kind::Element:
    case LValue::Kind::SubList: {
      std::vector<std::pair<long long, SourceRange>> idx;
      if (t.kind == LValue::Kind::Element) {
        idx.emplace_back(to_int(eval_number(t.index), ast_.expr(t.index).range), ast_.expr(t.index).range);
      } else {
        for (ExprId ie : t.indices)
          for (double d : eval_numbers(ie)) idx.emplace_back(to_int(d, ast_.expr(ie).range), ast_.expr(ie).range);
      }
      const Value v = eval(a.value);
      if (v.is_string()) {
        // Elements of a string list.
        const auto* old = symbols_.find_str(name);
        if (a.op != AffOp::Assign || !old || idx.size() != v.strs().size())
          fail(s.range, Diag::TypeStringsIntoElements, name);
        std::vector<std::string> cur = *old;
        for (std::size_t k = 0; k < idx.size(); ++k) {
          if (idx[k].first < 0 || static_cast<std::size_t>(idx[k].first) >= cur.size())
            fail_fmt(idx[k].second, Diag::IndexOutOfRange, idx[k].first, name, cur.size());
          cur[static_cast<std::size_t>(idx[k].first)] = v.strs()[k];
        }
        symbols_.set_str(name, std::move(cur));
        return;
      }
      if (v.nums().size() != idx.size())
        fail(s.range, Diag::ListIndicesValues, idx.size(), v.nums().size());
      NumSymbol* sym = symbols_.find_num(name);
      if (!sym) {
        if (symbols_.find_str(name))
          fail(t.range, Diag::TypeStringNotNumericList, name);
        symbols_.set_num(name, NumSymbol{{}, true});   // a missing list is created
        sym = symbols_.find_num(name);
      } else if (!sym->is_list) {
        fail_fmt(t.range, Diag::NotAList, name, name);
      }
      for (std::size_t k = 0; k < idx.size(); ++k) {
        const long long i = idx[k].first;
        if (i < 0) fail_fmt(idx[k].second, Diag::IndexOutOfRange, i, name, sym->values.size());
        grow_check(static_cast<std::size_t>(i) + 1);
        if (static_cast<std::size_t>(i) >= sym->values.size()) sym->values.resize(static_cast<std::size_t>(i) + 1, 0.0);
        double& slot = sym->values[static_cast<std::size_t>(i)];
        slot = arith(slot, v.nums()[k]);
      }
      return;
    }
    case LValue::Kind::Option:
      break;
  }
}

void Interpreter::exec_incdec(const Stmt& s, const IncDecStmt& a) {
  const double delta = a.increment ? 1 : -1;
  const LValue& t = a.target;
  switch (t.kind) {
    case LValue::Kind::Option: {
      const std::string name = option_name(t.option);
      const Value cur = read_option(t.option);
      if (cur.kind() != Value::Kind::Number)
        fail(t.range, Diag::TypeNotNumberOption, name);
      if (auto err = options_.set_number(name, cur.nums()[0] + delta); !err.empty())
        fail_message(s.range, err.kind, std::move(err.message));
      return;
    }
    case LValue::Kind::Var: {
      const std::string name = resolve_name(t.name);
      NumSymbol* sym = symbols_.find_num(name);
      if (!sym) fail_fmt(t.range, Diag::UnknownVariable, name, "");
      if (sym->is_list || sym->values.size() != 1)
        fail(t.range, Diag::IncDecOnList, name);
      sym->values[0] += delta;
      return;
    }
    case LValue::Kind::Element: {
      const std::string name = resolve_name(t.name);
      NumSymbol* sym = symbols_.find_num(name);
      if (!sym) fail_fmt(t.range, Diag::UnknownVariable, name, "");
      const long long i = to_int(eval_number(t.index), ast_.expr(t.index).range);
      if (i < 0 || static_cast<std::size_t>(i) >= sym->values.size())
        fail_fmt(ast_.expr(t.index).range, Diag::IndexOutOfRange, i, name, sym->values.size());
      sym->values[static_cast<std::size_t>(i)] += delta;
      return;
    }
    default:
      fail(s.range, Diag::IncDecTarget);
  }
}

namespace {

// Values as a script would write them, for messages: 30000, {1, 2}, "a".
std::string numbers_text(const std::vector<double>& v, bool list) {
  if (!list && v.size() == 1) return fmt::format("{:g}", v[0]);
  return fmt::format("{{{:g}}}", fmt::join(v, ", "));
}

std::string strings_text(const std::vector<std::string>& v) {
  return v.size() == 1 ? "\"" + v.front() + "\"" : "a string list";
}

}  // namespace

std::string Interpreter::value_text(std::string_view name) const {
  if (const auto* s = symbols_.find_str(name)) return strings_text(*s);
  const NumSymbol* n = symbols_.find_num(name);
  return n ? numbers_text(n->values, n->is_list) : "nothing";
}

void Interpreter::note_ignored_define(const DefineEntry& entry, const std::string& name) {
  // Only where a template the script included set the name first and the script then asks
  // for another value: the other order (the script's value first, the template's default
  // ignored) is how templates are meant to be used.
  const auto at = defined_at_.find(name);
  if (at == defined_at_.end() || !entry.value.valid() || at->second.file.value == entry.range.file.value) return;
  if (options_.number("General.WarnOnIgnoredDefineConstant") == 0 || options_.number("General.Verbosity") < 5) return;
  bool included = false;
  for (auto it = included_by_.find(at->second.file.value); it != included_by_.end() && !included;
       it = included_by_.find(it->second))
    included = it->second == entry.range.file.value;
  if (!included || reported_define_ignored_.count(name)) return;
  std::string asked;
  try {
    const Value v = eval(entry.value);
    if (v.is_string()) {
      const auto* kept = symbols_.find_str(name);
      if (kept && v.strs() == *kept) return;
      asked = strings_text(v.strs());
    } else {
      const NumSymbol* kept = symbols_.find_num(name);
      if (kept && kept->values == v.nums()) return;
      asked = numbers_text(v.nums(), v.nums().size() != 1);
    }
  } catch (const RuntimeError&) {
    return;   // a value Gmsh would not evaluate either: nothing to compare
  }
  reported_define_ignored_.insert(name);
  const lang::LineCol lc = sources_.line_col(at->second.begin_loc());
  diags_.report(entry.range, Diag::DefineConstantIgnored, name, value_text(name),
                std::filesystem::path(sources_.path(at->second.file)).filename().string(), lc.line, asked);
}

void Interpreter::exec_define_constant(const DefineConstantStmt& d) {
  for (const DefineEntry& entry : d.entries) {
    const std::string name = resolve_name(entry.name);
    // First definition wins; -setnumber values were defined before the script.
    if (symbols_.exists(name)) {
      note_ignored_define(entry, name);
      continue;
    }
    defined_at_.emplace(name, entry.range);
    if (!entry.value.valid()) {
      symbols_.set_num(name, NumSymbol{{0.0}, false});
      continue;
    }
    Value v = eval(entry.value);
    // `Name "Parameters/x"` makes it a ONELAB parameter: an existing parameter
    // (SetNumber/SetString) gives its value, else the parameter is created.
    // The other attributes (Min, Max, Choices...) only matter to a GUI.
    std::string onelab;
    for (const OnelabAttr& attr : entry.attrs)
      if (ast_.str(attr.key) == "Name" && attr.value.valid()) onelab = eval_string(attr.value);
    if (!onelab.empty() && v.is_numeric() && !v.nums().empty()) {
      auto [it, fresh] = onelab_numbers_.emplace(onelab, v.nums()[0]);
      if (!fresh) v = Value::number(it->second);
    } else if (!onelab.empty() && v.is_string() && !v.strs().empty()) {
      auto [it, fresh] = onelab_strings_.emplace(onelab, v.strs()[0]);
      if (!fresh) v = Value::string(it->second);
    }
    if (v.is_string()) {
      symbols_.set_str(name, v.strs());
    } else {
      const bool list = v.kind() == Value::Kind::List && v.nums().size() != 1;
      symbols_.set_num(name, NumSymbol{std::move(v.nums()), list});
    }
  }
}

void Interpreter::exec_delete(const Stmt& s, const DeleteStmt& d) {
  switch (d.what) {
    case DeleteWhat::Variable: {
      const std::string name = resolve_name(d.name);
      if (!symbols_.erase(name)) fail_fmt(d.name.range, Diag::UnknownVariableDeleted, name);
      return;
    }
    case DeleteWhat::Variables: symbols_.clear(); return;
    case DeleteWhat::Options: options_.reset(); return;
    case DeleteWhat::Model:
    case DeleteWhat::All:
      // Gmsh 4.8.4 destroys the geometry with its tags and the fields: newp, newreg and newf
      // start again at 1. The run's time account and the progress display are the
      // run's, not the model's: they carry on.
      {
        StageClock clock = std::move(kernel_.clock);
        std::vector<StageTime> parts = std::move(kernel_.mesh2d_parts);
        Progress* progress = kernel_.progress;
        kernel_ = KernelState{};
        kernel_.clock = std::move(clock);
        kernel_.mesh2d_parts = std::move(parts);
        kernel_.progress = progress;
      }
      return;
    case DeleteWhat::Physicals: kernel_.model.clear_physicals(); return;
    default: break;
  }
  // Meshes.
  std::string what = "Delete";
  switch (d.what) {
    case DeleteWhat::Model: what = "Delete Model"; break;
    case DeleteWhat::Physicals: what = "Delete Physicals"; break;
    case DeleteWhat::Meshes: what = "Delete Meshes"; break;
    case DeleteWhat::All: what = "Delete All"; break;
    default: break;
  }
  not_supported_stmt(current_stmt_, what);
}

}  // namespace sm::interp
