// Interpreter core: running files, statement dispatch, error reporting with the
// Call/Include stack, and the hang-prevention counters (limits.h).
#include "interp/interpreter.h"

#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "interp/kernel/statements.h"
#include "interp/format.h"
#include "interp/limits.h"
#include "lang/parser.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// The main script (a file or a buffer) the SourceManager did not load, by its name.
void report_script_load(Diagnostics& diags, const std::string& name, const SourceManager::LoadResult& loaded) {
  switch (loaded.failure) {
    case SourceManager::LoadFailure::IsDirectory: diags.report(SourceRange{}, Diag::ScriptIsDirectory, name); return;
    case SourceManager::LoadFailure::TooLarge:
      diags.report(SourceRange{}, Diag::ScriptTooLarge, name, SourceManager::kMaxFileMiB);
      return;
    case SourceManager::LoadFailure::CannotRead: diags.report(SourceRange{}, Diag::ScriptCannotRead, name); return;
    case SourceManager::LoadFailure::CannotOpen:
    case SourceManager::LoadFailure::None: break;
  }
  diags.report(SourceRange{}, Diag::ScriptCannotOpen, name, loaded.reason);
}

}  // namespace

Interpreter::Interpreter(SourceManager& sources, Diagnostics& diags, std::ostream& out,
                         RunSettings settings)
    : sources_(sources),
      diags_(diags),
      out_(out),
      settings_(std::move(settings)),
      env_{symbols_, options_, onelab_numbers_, onelab_strings_, "", rand_state_, &settings_.limits, &redirects_} {}

OptionRefusal Interpreter::preset_number(const std::string& name, double v) {
  if (name.find('.') != std::string::npos) {
    if (!options_.find(name)) return option_refusal(Diag::OptionNotKnownDidYouMean, name, options_.closest(name));
    return options_.set_number(name, v);
  }
  symbols_.set_num(name, NumSymbol{{v}, false});
  return {};
}

OptionRefusal Interpreter::preset_string(const std::string& name, const std::string& v) {
  if (name.find('.') != std::string::npos) {
    if (!options_.find(name)) return option_refusal(Diag::OptionNotKnownDidYouMean, name, options_.closest(name));
    if (options_.find(name)->kind == OptionKind::Box) return preset_box(name, v);
    return options_.set_string(name, v);
  }
  symbols_.set_str(name, {v});
  return {};
}

// `-setstring Mesh.PictureBox "W,E,S,N"`: four numbers separated by commas or spaces.
OptionRefusal Interpreter::preset_box(const std::string& name, const std::string& v) {
  std::vector<double> numbers;
  std::string item;
  bool bad = false;
  auto take = [&] {
    if (item.empty()) return;
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    bad |= end != item.c_str() + item.size();
    numbers.push_back(x);
    item.clear();
  };
  for (char c : v) {
    if (c == ',' || c == ' ' || c == '{' || c == '}') take();
    else item += c;
  }
  take();
  if (bad || numbers.size() != 4) return option_refusal(Diag::OptionBoxText, name, v);
  return options_.set_box(name, {numbers[0], numbers[1], numbers[2], numbers[3]});
}

RunStatus Interpreter::run_file(const std::string& path) {
  const auto loaded = sources_.load_file(path);
  if (!loaded.file.valid()) {
    report_script_load(diags_, path, loaded);
    return RunStatus::Errors;
  }
  std::error_code ec;
  include_stack_.push_back(std::filesystem::weakly_canonical(path, ec).string());
  const RunStatus st = finish_run(run_loaded(loaded.file));
  include_stack_.pop_back();
  return st;
}

RunStatus Interpreter::run_buffer(const std::string& name, const std::string& text) {
  const auto loaded = sources_.add_buffer(name, text);
  if (!loaded.file.valid()) {
    report_script_load(diags_, name, loaded);
    return RunStatus::Errors;
  }
  include_stack_.push_back(name);
  const RunStatus st = finish_run(run_loaded(loaded.file));
  include_stack_.pop_back();
  return st;
}

RunStatus Interpreter::finish_run(RunStatus st) {
  if (st == RunStatus::Errors) {
    redirects_.abandon_all();
    return st;
  }
  const std::size_t errors_before = diags_.error_count();
  publish_redirects();
  return diags_.error_count() > errors_before ? RunStatus::Errors : st;
}

void Interpreter::publish_redirects() {
  for (const RedirectFiles::Failure& f : redirects_.commit_all())
    diags_.report(f.where, Diag::FileWriteError, f.path, f.reason);
}

RunStatus Interpreter::run_loaded(FileId file) {
  const std::size_t errors_before = diags_.error_count();
  if (stopped_) return RunStatus::Ok;
  const ParseResult parsed = parse_file(sources_, file, ast_, diags_);
  if (!parsed.ok || diags_.error_count() > errors_before) return RunStatus::Errors;
  parsed_files_[file.value] = parsed.stmts;
  try {
    run_statements(parsed.stmts);
  } catch (const RuntimeError& e) {
    report(e);
  }
  return diags_.error_count() > errors_before ? RunStatus::Errors : RunStatus::Ok;
}

Interpreter::Flow Interpreter::run_statements(const StmtList& stmts) {
  for (StmtId s : stmts) {
    const Flow f = exec(s);
    // Warnings reach the user when the statement that caused them ends, in order with
    // Printf output and the progress display, not after the whole run.
    diags_.emit_pending();
    if (f == Flow::Stop) return f;
    if (f == Flow::Return)
      fail_fmt(ast_.stmt(s).range, Diag::ReturnOutsideMacro);
  }
  return Flow::Normal;
}

Interpreter::Flow Interpreter::exec_block(const StmtList& body) {
  for (StmtId s : body) {
    const Flow f = exec(s);
    diags_.emit_pending();
    if (f != Flow::Normal) return f;
  }
  return Flow::Normal;
}

void Interpreter::count_statement(SourceRange r) {
  if (++statements_run_ > settings_.limits.max_statements)
    fail(r, Diag::LimitStatements, settings_.limits.max_statements);
}

Interpreter::DepthGuard::DepthGuard(Interpreter& in, SourceRange r) : in_(in) {
  if (++in_.depth_ > in_.settings_.limits.max_eval_depth) {
    --in_.depth_;   // the destructor does not run when the constructor throws
    in_.fail(r, Diag::LimitEvalDepth, in_.settings_.limits.max_eval_depth);
  }
}

Interpreter::Flow Interpreter::exec(StmtId id) {
  const Stmt& s = ast_.stmt(id);
  const DepthGuard depth(*this, s.keyword.valid() ? s.keyword : s.range);
  count_statement(s.range);
  current_stmt_ = id;
  if (s.range.valid()) {
    const std::string& p = sources_.path(s.range.file);
    if (env_.script_path != p) env_.script_path = p;
  }
  return std::visit(
      [&](const auto& n) -> Flow {
        using T = std::decay_t<decltype(n)>;
        if constexpr (std::is_same_v<T, AssignStmt>) {
          exec_assign(s, n);
        } else if constexpr (std::is_same_v<T, IncDecStmt>) {
          exec_incdec(s, n);
        } else if constexpr (std::is_same_v<T, DefineConstantStmt>) {
          exec_define_constant(n);
        } else if constexpr (std::is_same_v<T, DeleteStmt>) {
          exec_delete(s, n);
        } else if constexpr (std::is_same_v<T, PrintStmt>) {
          exec_print(s, n);
        } else if constexpr (std::is_same_v<T, IfStmt>) {
          return exec_if(n);
        } else if constexpr (std::is_same_v<T, ForStmt>) {
          return exec_for(s, n);
        } else if constexpr (std::is_same_v<T, MacroStmt>) {
          exec_macro(s, n);
        } else if constexpr (std::is_same_v<T, CallStmt>) {
          return exec_call(s, n);
        } else if constexpr (std::is_same_v<T, ReturnStmt>) {
          return Flow::Return;
        } else if constexpr (std::is_same_v<T, ExitStmt>) {
          // `Exit;` is status 0, or 1 when errors were reported (Gmsh).
          exit_code_ = n.code.valid() ? static_cast<int>(to_int(eval_number(n.code), s.range))
                                      : (diags_.error_count() > 0 ? 1 : 0);
          stopped_ = true;
          return Flow::Stop;
        } else if constexpr (std::is_same_v<T, AbortStmt>) {
          stopped_ = true;
          return Flow::Stop;
        } else if constexpr (std::is_same_v<T, AssertStmt>) {
          exec_assert(s, n);
        } else if constexpr (std::is_same_v<T, IncludeStmt>) {
          return exec_include(s, n);
        } else if constexpr (std::is_same_v<T, CommandStmt>) {
          return exec_command(s, n);
        } else {   // the kernel's statements: one row each in kernel/statements.def
          exec_kernel_stmt(*this, id);
        }
        return Flow::Normal;
      },
      s.node);
}

std::string_view Interpreter::text_of(SourceRange r) const {
  if (!r.valid()) return {};
  const std::string_view t = sources_.text(r.file);
  if (r.begin > t.size() || r.end > t.size() || r.end < r.begin) return {};
  return t.substr(r.begin, r.end - r.begin);
}

std::vector<DiagNote> Interpreter::frame_notes() const {
  // Innermost first; a deep recursion shows its 8 innermost and 4 outermost
  // frames rather than 200 identical notes.
  constexpr std::size_t kInner = 8, kOuter = 4;
  std::vector<DiagNote> notes;
  const std::size_t n = frames_.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (n > kInner + kOuter && k == kInner) {
      notes.push_back(DiagNote{SourceRange{}, fmt::format("... {} more frames ...", n - kInner - kOuter)});
      k = n - kOuter;
    }
    const Frame& f = frames_[n - 1 - k];
    if (f.loop)
      notes.push_back(DiagNote{
          f.site, f.what.empty() ? fmt::format("inside this 'For' loop (iteration {})", format_g(f.value))
                                 : fmt::format("inside this 'For' loop ({} = {})", f.what, format_g(f.value))});
    else
      notes.push_back(DiagNote{f.site, fmt::format("called from here ({})", f.what)});
  }
  return notes;
}

void Interpreter::fail_message(SourceRange range, Diag kind, std::string message) {
  throw RuntimeError{range, kind, std::move(message), frame_notes()};
}

void Interpreter::fail_message_with_notes(SourceRange range, Diag kind, std::string message,
                                          std::vector<DiagNote> notes) {
  for (auto& n : frame_notes()) notes.push_back(std::move(n));
  throw RuntimeError{range, kind, std::move(message), std::move(notes)};
}

void Interpreter::report(const RuntimeError& e) {
  auto h = diags_.report_message(e.range, e.kind, e.message);
  for (const auto& n : e.notes) h.note(n.range, n.message);
}

void Interpreter::not_supported_stmt(StmtId id, std::string_view what) {
  const Stmt& s = ast_.stmt(id);
  const std::string key(what);
  if (!reported_unsupported_.insert(key).second) return;
  auto h = diags_.report(s.keyword.valid() ? s.keyword : s.range, Diag::NotSupportedYet, what,
                         ": the statement is skipped (reported once per run)");
  for (const auto& n : frame_notes()) h.note(n.range, n.message);
}

void Interpreter::display_only_stmt(StmtId id, std::string_view what) {
  const Stmt& s = ast_.stmt(id);
  if (!reported_unsupported_.insert(std::string(what)).second) return;
  auto h = diags_.report(s.keyword.valid() ? s.keyword : s.range, Diag::DisplayOnly, what, " (noted once per run)");
  for (const auto& n : frame_notes()) h.note(n.range, n.message);
}

void Interpreter::not_supported_expr(ExprId e, std::string_view what) {
  fail_fmt(ast_.expr(e).range, Diag::NotSupportedYet, what, " (it needs the geometry model)");
}

}  // namespace sm::interp
