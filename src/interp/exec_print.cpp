// Printf, Warning, Error (also redirected to a file with > and >>) and the
// native Assert extension.
#include <fmt/format.h>

#include "interp/format.h"
#include "interp/interpreter.h"

namespace sm::interp {

using namespace sm::lang;

std::string Interpreter::format_args(ExprId format, const ExprList& args, SourceRange r) {
  const std::string f = eval_string(format);
  std::vector<FormatArg> items;
  std::vector<ExprId> origin;   // the expression each flattened item came from
  for (ExprId a : args) {
    const Value v = eval(a);
    if (v.is_numeric()) {
      for (double x : v.nums()) items.emplace_back(x), origin.push_back(a);
    } else {
      for (const auto& s : v.strs()) items.emplace_back(s), origin.push_back(a);
    }
  }
  FormatResult res = format_gmsh(f, items);
  if (!res.ok) {
    SourceRange where = ast_.expr(format).range;
    if (res.arg_index >= 0 && static_cast<std::size_t>(res.arg_index) < origin.size())
      where = ast_.expr(origin[static_cast<std::size_t>(res.arg_index)]).range;
    else if (res.kind == Diag::FormatTooFewArguments)
      where = r;
    fail_message(where, res.kind, std::move(res.error));
  }
  return std::move(res.text);
}

void Interpreter::exec_print(const Stmt& s, const PrintStmt& p) {
  const std::string text = format_args(p.format, p.args, s.range);
  if (p.redirect != Redirect::None) {
    const std::string path = script_relative_path(env_, eval_string(p.file));
    const SourceRange where = ast_.expr(p.file).range;
    std::string reason;
    if (!redirects_.write_line(path, p.redirect == Redirect::Append, text, where, &reason))
      fail_fmt(where, Diag::FileWriteError, path, reason);
    return;
  }
  using namespace fmt::literals;   // "text"_a: the user-text slot of UserWarning and UserError
  switch (p.kind) {
    case PrintKind::Printf: out_ << text << '\n'; break;
    case PrintKind::Warning: {
      auto h = diags_.report(s.range, Diag::UserWarning, "text"_a = text);
      for (const auto& n : frame_notes()) h.note(n.range, n.message);
      break;
    }
    case PrintKind::Error: {
      // Like Gmsh, the script goes on; the run ends with errors (exit 1).
      auto h = diags_.report(s.range, Diag::UserError, "text"_a = text);
      for (const auto& n : frame_notes()) h.note(n.range, n.message);
      break;
    }
  }
}

void Interpreter::exec_assert(const Stmt& s, const AssertStmt& a) {
  if (eval_number(a.cond) != 0) return;
  std::string msg = "condition is false";
  if (a.message.valid()) msg = format_args(a.message, a.args, s.range);
  fail_fmt(ast_.expr(a.cond).range, Diag::AssertionFailed, msg);
}

}  // namespace sm::interp
