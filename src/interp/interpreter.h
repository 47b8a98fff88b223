// The evaluator: walks the AST of a .geo script with normal semantics (loops
// re-evaluate nodes, Call/Include take effect where they stand), holding all
// run state (variables, options, macros, Include stack) in one object.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "interp/builtins/builtins.h"
#include "interp/limits.h"
#include "interp/kernel_state.h"
#include "interp/options.h"
#include "interp/redirect_files.h"
#include "interp/value.h"
#include "lang/ast.h"
#include "lang/diagnostics.h"
#include "lang/source.h"

namespace sm::interp {

/// Settings of one run, from the command line.
struct RunSettings {
  std::vector<std::string> include_dirs;   ///< `-I DIR`, searched after the including file's dir
  std::vector<std::string> search_path;    ///< $STEREOMESH_PATH entries
  std::string stdlib_dir;                  ///< the stdlib templates, searched last (base/share_dir.h)
  Limits limits;                           ///< hang and memory guards (limits.h)
};

/// How a run ended.
enum class RunStatus {
  Ok,        ///< ran to the end (or Abort/Exit without errors)
  Errors,    ///< syntax or runtime errors were reported
};

/// A runtime error on its way to the top: reported once, with the call stack
/// captured where it was raised.
struct RuntimeError {
  lang::SourceRange range;
  lang::Diag kind;
  std::string message;
  std::vector<lang::DiagNote> notes;
};

class Interpreter {
 public:
  /// Printf output goes to `out`; diagnostics to `diags`.
  Interpreter(lang::SourceManager& sources, lang::Diagnostics& diags, std::ostream& out,
              RunSettings settings = {});

  Options& options() { return options_; }
  Symbols& symbols() { return symbols_; }
  /// The model, fields and imports the script has built so far.
  KernelState& kernel() { return kernel_; }

  /// `-setnumber NAME V` / `-setstring NAME S`: an option when NAME has a '.',
  /// else a variable defined before the script (DefineConstant keeps it).
  /// Returns nothing (empty()) or why the value is refused: a kind and its message.
  OptionRefusal preset_number(const std::string& name, double v);
  OptionRefusal preset_string(const std::string& name, const std::string& v);

  /// Loads, parses and runs a file (or an in-memory buffer for tests). A file
  /// with syntax errors is not run. Several files share all state, in order.
  RunStatus run_file(const std::string& path);
  RunStatus run_buffer(const std::string& name, const std::string& text);

  /// Set by `Exit n;` (the process exit status the script asks for), else -1.
  int exit_request() const { return exit_code_; }
  /// True once Exit/Abort stopped the run: later files are not run.
  bool stopped() const { return stopped_; }

  // ---- used by the statement/expression families, builtins/ and kernel/ ----
  enum class Flow { Normal, Return, Stop };

  Value eval(lang::ExprId e);
  double eval_number(lang::ExprId e);
  std::string eval_string(lang::ExprId e);
  /// A list item: a list-flagged variable gives its whole list.
  Value eval_list_arg(lang::ExprId e);
  /// Flattened numbers of list items (ranges, lists, scalars).
  std::vector<double> eval_numbers(lang::ExprId e);
  std::string resolve_name(const lang::Name& n);

  Flow exec(lang::StmtId s);
  Flow exec_block(const lang::StmtList& body);

  /// Counts one executed statement or loop iteration against the statement limit.
  void count_statement(lang::SourceRange r);
  /// Throws the RuntimeError of `kind` with `args` (checked against the kind's format at
  /// compile time, see lang/diag_format.h).
  template <class... Args>
  [[noreturn]] void fail(lang::SourceRange range, std::type_identity_t<lang::DiagFormat<Args...>> kind,
                         const Args&... args) {
    fail_message(range, kind.kind(), lang::format_diag<Args...>(kind, args...));
  }
  /// fail(), the name the older call sites use.
  template <class... Args>
  [[noreturn]] void fail_fmt(lang::SourceRange range, std::type_identity_t<lang::DiagFormat<Args...>> kind,
                             const Args&... args) {
    fail_message(range, kind.kind(), lang::format_diag<Args...>(kind, args...));
  }
  /// fail() with extra notes (e.g. where the entities a kernel error names were created).
  [[noreturn]] void fail_with_notes(lang::SourceRange range, lang::DiagFormat<std::string> kind, std::string message,
                                    std::vector<lang::DiagNote> notes) {
    fail_message_with_notes(range, kind.kind(), lang::format_diag<std::string>(kind, message), std::move(notes));
  }
  template <class... Args>
  [[noreturn]] void fail_with_notes(lang::SourceRange range, std::vector<lang::DiagNote> notes,
                                    std::type_identity_t<lang::DiagFormat<Args...>> kind, const Args&... args) {
    fail_message_with_notes(range, kind.kind(), lang::format_diag<Args...>(kind, args...), std::move(notes));
  }
  /// Throws with a message formatted by a fail() or a typed report before (a RuntimeError
  /// caught and thrown again with more context).
  [[noreturn]] void fail_message(lang::SourceRange range, lang::Diag kind, std::string message);
  [[noreturn]] void fail_message_with_notes(lang::SourceRange range, lang::Diag kind, std::string message,
                                            std::vector<lang::DiagNote> notes);
  /// A statement the kernel cannot run yet: reported once per kind of
  /// statement, then the run goes on (the script's variables stay usable).
  void not_supported_stmt(lang::StmtId s, std::string_view what);
  /// A display statement (Color, Hide, Show, View): a `display-only` note, once per kind a run.
  void display_only_stmt(lang::StmtId s, std::string_view what);
  /// An expression that needs the model: a runtime error (its value is needed).
  [[noreturn]] void not_supported_expr(lang::ExprId e, std::string_view what);

  const lang::Ast& ast() const { return ast_; }
  lang::SourceManager& sources() { return sources_; }
  lang::Diagnostics& diags() { return diags_; }
  std::string_view text_of(lang::SourceRange r) const;
  BuiltinEnv& builtin_env() { return env_; }

 private:
  OptionRefusal preset_box(const std::string& name, const std::string& v);
  RunStatus run_loaded(lang::FileId file);
  /// The end of a top-level run: Printf's files put in place, or dropped after errors.
  RunStatus finish_run(RunStatus st);
  void publish_redirects();
  Flow run_statements(const lang::StmtList& stmts);
  void report(const RuntimeError& e);
  std::vector<lang::DiagNote> frame_notes() const;

  // expressions (eval_expr.cpp)
  Value eval_var(const lang::Expr& e, const lang::VarExpr& v);
  Value eval_unary(const lang::Expr& e, const lang::UnaryExpr& u);
  Value eval_binary(const lang::Expr& e, const lang::BinaryExpr& b);
  Value apply_binary(const lang::Expr& e, const lang::BinaryExpr& b, const Value& l, const Value& r);
  Value eval_call(const lang::Expr& e, const lang::CallExpr& c);
  Value eval_option(const lang::Expr& e, const lang::OptionExpr& o);
  Value eval_range(const lang::Expr& e, const lang::RangeExpr& r);
  Value eval_list(const lang::Expr& e, const lang::ListExpr& l);
  Value eval_index(const lang::Expr& e, const lang::Name& name, lang::ExprId index);
  Value eval_whole(const lang::Expr& e, const lang::Name& name);
  Value eval_postfix(const lang::Expr& e, const lang::PostfixExpr& p);
  long long to_int(double v, lang::SourceRange r);
  std::string unknown_name_hint(const std::string& name) const;

  // assignments (exec_assign.cpp)
  void exec_assign(const lang::Stmt& s, const lang::AssignStmt& a);
  void exec_incdec(const lang::Stmt& s, const lang::IncDecStmt& a);
  void assign_option(const lang::LValue& t, lang::AffOp op, lang::ExprId value, lang::SourceRange r);
  void exec_define_constant(const lang::DefineConstantStmt& d);
  void exec_delete(const lang::Stmt& s, const lang::DeleteStmt& d);
  std::string option_name(const lang::OptionRef& o);
  Value read_option(const lang::OptionRef& o);

  // output (exec_print.cpp)
  void exec_print(const lang::Stmt& s, const lang::PrintStmt& p);
  void exec_assert(const lang::Stmt& s, const lang::AssertStmt& a);
  std::string format_args(lang::ExprId format, const lang::ExprList& args, lang::SourceRange r);

  // control flow (exec_control.cpp)
  Flow exec_if(const lang::IfStmt& s);
  Flow exec_for(const lang::Stmt& st, const lang::ForStmt& f);
  void exec_macro(const lang::Stmt& s, const lang::MacroStmt& m);
  Flow exec_call(const lang::Stmt& s, const lang::CallStmt& c);
  Flow exec_include(const lang::Stmt& s, const lang::IncludeStmt& inc);
  std::string value_text(std::string_view name) const;
  void note_ignored_define(const lang::DefineEntry& entry, const std::string& name);
  Flow exec_command(const lang::Stmt& s, const lang::CommandStmt& c);
  std::string find_include(const std::string& name, lang::SourceRange r);

  // Counts nested eval/exec calls (expressions inside blocks inside macro
  // calls): past the eval-depth limit the run stops before the C++ stack would.
  struct DepthGuard {
    DepthGuard(Interpreter& in, lang::SourceRange r);
    ~DepthGuard() { --in_.depth_; }
    Interpreter& in_;
  };

  // One level of the run's context, innermost last: a Call, an Include, or
  // a running For loop (whose variable value is read when a note is made).
  struct Frame {
    lang::SourceRange site;   ///< the Call, Include or For keyword
    std::string what;         ///< "macro 'Foo'", "included file 'f.geo'", or the loop variable
    bool loop = false;
    double value = 0;         ///< loop: the variable's value (or the iteration for `For (a:b)`)
  };
  struct MacroDef {
    lang::StmtId stmt;
    std::string name;
  };

  lang::SourceManager& sources_;
  lang::Diagnostics& diags_;
  std::ostream& out_;
  RunSettings settings_;
  lang::Ast ast_;
  Options options_;
  Symbols symbols_;
  std::map<std::string, double, std::less<>> onelab_numbers_;
  std::map<std::string, std::string, std::less<>> onelab_strings_;
  std::uint64_t rand_state_ = 0;
  BuiltinEnv env_;
  KernelState kernel_;
  RedirectFiles redirects_;   // Printf > file: put in place when the run ends without errors

  std::map<std::string, MacroDef, std::less<>> macros_;
  std::map<std::uint32_t, lang::StmtList> parsed_files_;   // FileId value -> statements
  std::vector<Frame> frames_;
  std::vector<std::string> include_stack_;                 // canonical paths
  std::map<std::uint32_t, std::uint32_t> included_by_;     // FileId value -> the file that first included it
  std::map<std::string, lang::SourceRange, std::less<>> defined_at_;   // name -> the DefineConstant entry that set it
  std::set<std::string, std::less<>> reported_define_ignored_;
  std::vector<lang::FileId> file_stack_;
  std::set<std::string, std::less<>> reported_unsupported_;
  lang::StmtId current_stmt_;   // the statement being run, for reports
  std::uint64_t statements_run_ = 0;
  std::size_t macro_depth_ = 0;
  std::size_t depth_ = 0;
  int exit_code_ = -1;
  bool stopped_ = false;
};

}  // namespace sm::interp
