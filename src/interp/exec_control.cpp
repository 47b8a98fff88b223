// Control flow: If/ElseIf/Else, both For forms with Gmsh's loop-variable rules,
// Macro/Call/Return, Include with its search path and cycle detection, and the
// command statements.
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "interp/kernel/dispatch.h"
#include "interp/format.h"
#include "interp/interpreter.h"
#include "interp/limits.h"
#include "lang/parser.h"

namespace sm::interp {

using namespace sm::lang;
namespace fs = std::filesystem;

namespace {

// Pops a frame however the body is left (normal end, Return, error).
template <class Stack>
struct PopGuard {
  Stack& stack;
  ~PopGuard() { stack.pop_back(); }
};

// An included file the SourceManager did not load, at the Include's path.
[[noreturn]] void fail_include_load(Interpreter& in, SourceRange r, const std::string& path,
                                    const SourceManager::LoadResult& loaded) {
  switch (loaded.failure) {
    case SourceManager::LoadFailure::IsDirectory: in.fail(r, Diag::IncludeIsDirectory, path);
    case SourceManager::LoadFailure::TooLarge: in.fail(r, Diag::IncludeTooLarge, path, SourceManager::kMaxFileMiB);
    case SourceManager::LoadFailure::CannotRead: in.fail(r, Diag::IncludeCannotRead, path);
    case SourceManager::LoadFailure::CannotOpen:
    case SourceManager::LoadFailure::None: break;
  }
  in.fail(r, Diag::IncludeCannotOpen, path, loaded.reason);
}

}  // namespace

Interpreter::Flow Interpreter::exec_if(const IfStmt& s) {
  for (const IfBranch& b : s.branches)
    if (eval_number(b.cond) != 0) return exec_block(b.body);
  if (s.has_else) return exec_block(s.else_body);
  return Flow::Normal;
}

// Gmsh's loop: bounds evaluated once; a start past the end skips the body and
// leaves the variable at the start; after the loop the variable is last value
// + step (`For i In {1:3}` leaves i = 4); a step of 0 runs the body once. The
// counter is kept apart, so assigning the variable in the body does not change
// the iterations.
Interpreter::Flow Interpreter::exec_for(const Stmt& st, const ForStmt& f) {
  const double from = eval_number(f.from);
  const double to = eval_number(f.to);
  const double step = f.step.valid() ? eval_number(f.step) : 1.0;
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step))
    fail(st.keyword, Diag::NonFiniteRange, "loop bounds and step");
  if (step != 0) {
    const double n = std::floor((to - from) / step) + 1;
    if (n > static_cast<double>(settings_.limits.max_list_size))
      fail(st.keyword, Diag::LimitLoopIterations, format_g(from), format_g(to), format_g(step), format_g(n),
           settings_.limits.max_list_size);
  }
  const bool has_var = f.var.valid();
  const std::string var = has_var ? std::string(ast_.str(f.var)) : std::string();
  double x = from;
  if (has_var) symbols_.set_num(var, NumSymbol{{x}, false});
  if ((step > 0 && x > to) || (step < 0 && x < to)) return Flow::Normal;
  frames_.push_back(Frame{st.keyword, var, true, has_var ? x : 1});
  PopGuard<std::vector<Frame>> guard{frames_};
  const std::size_t frame = frames_.size() - 1;
  double iteration = 1;
  for (;;) {
    count_statement(st.keyword);   // empty nested loops count too: no silent 1e12 iterations
    frames_[frame].value = has_var ? x : iteration;
    const Flow fl = exec_block(f.body);
    if (fl != Flow::Normal) return fl;
    x += step;
    iteration += 1;
    if (has_var) symbols_.set_num(var, NumSymbol{{x}, false});
    if (step == 0 || (step > 0 && x > to) || (step < 0 && x < to)) break;
  }
  return Flow::Normal;
}

void Interpreter::exec_macro(const Stmt& s, const MacroStmt& m) {
  const std::string name = m.name.valid() ? std::string(ast_.str(m.name)) : eval_string(m.name_expr);
  if (auto it = macros_.find(name); it != macros_.end()) {
    try {
      fail_fmt(s.keyword, Diag::MacroRedefined, name);
    } catch (RuntimeError& e) {
      e.notes.insert(e.notes.begin(), DiagNote{ast_.stmt(it->second.stmt).keyword, "first defined here"});
      throw;
    }
  }
  macros_.emplace(name, MacroDef{current_stmt_, name});
}

Interpreter::Flow Interpreter::exec_call(const Stmt& s, const CallStmt& c) {
  const std::string name = c.name.valid() ? std::string(ast_.str(c.name)) : eval_string(c.name_expr);
  auto it = macros_.find(name);
  if (it == macros_.end()) {
    std::string hint;
    std::size_t best = std::max<std::size_t>(2, name.size() / 3) + 1;
    for (const auto& [n, def] : macros_) {
      const std::size_t d = edit_distance(name, n);
      if (d < best) {
        best = d;
        hint = fmt::format(" (did you mean '{}'?)", n);
      }
    }
    fail_fmt(s.range, Diag::UnknownMacro, name, hint);
  }
  if (macro_depth_ >= settings_.limits.max_call_depth)
    fail_fmt(s.range, Diag::CallTooDeep, settings_.limits.max_call_depth);
  const auto& body = std::get<MacroStmt>(ast_.stmt(it->second.stmt).node).body;
  frames_.push_back(Frame{s.range, fmt::format("macro '{}'", name)});
  PopGuard<std::vector<Frame>> guard{frames_};
  ++macro_depth_;
  Flow f;
  try {
    f = exec_block(body);
  } catch (...) {
    --macro_depth_;
    throw;
  }
  --macro_depth_;
  return f == Flow::Return ? Flow::Normal : f;
}

std::string Interpreter::find_include(const std::string& name, SourceRange r) {
  std::error_code ec;
  const fs::path p(name);
  if (p.is_absolute()) {
    if (fs::is_regular_file(p, ec)) return name;
    fail_fmt(r, Diag::IncludeNotFound, name, "absolute path");
  }
  // The including file's directory, then -I, then $STEREOMESH_PATH, then stdlib/.
  std::vector<std::string> dirs;
  const std::string& including = sources_.path(r.file);
  dirs.push_back(fs::path(including).parent_path().string());
  dirs.insert(dirs.end(), settings_.include_dirs.begin(), settings_.include_dirs.end());
  dirs.insert(dirs.end(), settings_.search_path.begin(), settings_.search_path.end());
  if (!settings_.stdlib_dir.empty()) dirs.push_back(settings_.stdlib_dir);
  std::string searched;
  for (const std::string& d : dirs) {
    const fs::path cand = d.empty() ? p : fs::path(d) / p;
    if (fs::is_regular_file(cand, ec)) return cand.lexically_normal().string();
    searched += fmt::format("{}'{}'", searched.empty() ? "" : ", ", d.empty() ? "." : d);
  }
  fail_fmt(r, Diag::IncludeNotFound, name, searched);
}

Interpreter::Flow Interpreter::exec_include(const Stmt& s, const IncludeStmt& inc) {
  const std::string name = eval_string(inc.path);
  const SourceRange r = ast_.expr(inc.path).range;
  // A file the script wrote with Printf may be the one it includes.
  if (!redirects_.empty()) publish_redirects();
  const std::string path = find_include(name, r);
  std::error_code ec;
  const std::string canon = fs::weakly_canonical(path, ec).string();
  for (const std::string& open : include_stack_) {
    if (open == canon) {
      try {
        fail_fmt(r, Diag::IncludeCycle, name);
      } catch (RuntimeError& e) {
        e.notes.insert(e.notes.begin(), DiagNote{SourceRange{}, fmt::format("include chain: {} -> {}",
                                                                            fmt::join(include_stack_, " -> "), canon)});
        throw;
      }
    }
  }
  if (include_stack_.size() >= settings_.limits.max_include_depth)
    fail_fmt(r, Diag::IncludeTooDeep, settings_.limits.max_include_depth);
  FileId file = sources_.find_loaded(path);
  if (!file.valid()) {
    const auto loaded = sources_.load_file(path);
    if (!loaded.file.valid()) fail_include_load(*this, r, path, loaded);
    file = loaded.file;
  }
  auto parsed = parsed_files_.find(file.value);
  if (parsed == parsed_files_.end()) {
    const std::size_t before = diags_.error_count();
    ParseResult pr = parse_file(sources_, file, ast_, diags_);
    if (!pr.ok || diags_.error_count() > before) {
      fail(r, Diag::IncludeSyntaxErrors, name);
    }
    parsed = parsed_files_.emplace(file.value, std::move(pr.stmts)).first;
  }
  if (file.value != s.range.file.value) included_by_.emplace(file.value, s.range.file.value);
  frames_.push_back(Frame{s.range, fmt::format("included file '{}'", name)});
  PopGuard<std::vector<Frame>> guard{frames_};
  include_stack_.push_back(canon);
  PopGuard<std::vector<std::string>> guard2{include_stack_};
  const StmtList stmts = parsed->second;   // copy: parsed_files_ may grow while running
  return exec_block(stmts);
}

Interpreter::Flow Interpreter::exec_command(const Stmt& s, const CommandStmt& c) {
  const std::string_view name = ast_.str(c.command);
  if (name == "SetNumber" || name == "SetString") {
    // `SetNumber("name", v);`: the ONELAB-style parameter store that
    // GetNumber/GetString read. The parser gives the arguments as a ListExpr.
    const auto* list = c.arg.valid() ? std::get_if<ListExpr>(&ast_.expr(c.arg).node) : nullptr;
    if (!list || list->items.size() != 2)
      fail_fmt(s.range, Diag::WrongArgumentCount, name, "2", "s", list ? list->items.size() : 0);
    std::vector<Value> args{eval(list->items[0]), eval(list->items[1])};
    try {
      find_builtin(name)(env_, args);
    } catch (const BuiltinError& err) {
      const SourceRange where =
          err.arg >= 0 && err.arg < 2 ? ast_.expr(list->items[static_cast<std::size_t>(err.arg)]).range : s.range;
      fail_fmt(where, Diag::BuiltinFailed, name, err.message);
    }
    return Flow::Normal;
  }
  if (name == "Homology" || name == "Cohomology" || name == "Betti") {
    // Gmsh adds the bases it finds to the mesh as physical groups, after meshing: the
    // lists are evaluated (their mistakes are the script's), the request noted once.
    if (c.arg.valid()) (void)eval(c.arg);
    if (reported_unsupported_.insert("(co)homology").second) {   // one note for the three
      auto h = diags_.report(c.command_range, Diag::HomologySkipped, name, " (noted once per run)");
      for (const auto& n : frame_notes()) h.note(n.range, n.message);
    }
    return Flow::Normal;
  }
  if (!exec_mesh_command(*this, current_stmt_, name)) not_supported_stmt(current_stmt_, name);
  return Flow::Normal;
}

}  // namespace sm::interp
