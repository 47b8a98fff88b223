// Script-test driver (see script_test.h).
#include "interp/script_test.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace sm::interp {

namespace fs = std::filesystem;

namespace {

std::string rtrim(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    lines.push_back(rtrim(std::string_view(text).substr(pos, nl - pos)));
    pos = nl + 1;
  }
  return lines;
}

}  // namespace

ScriptExpectations parse_expectations(std::string_view text) {
  ScriptExpectations ex;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    const std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    const std::size_t c = line.find("// expect");
    if (c == std::string_view::npos) continue;
    std::string_view rest = line.substr(c + 9);
    auto take = [&](std::string_view tag) {
      if (rest.substr(0, tag.size()) != tag) return false;
      rest.remove_prefix(tag.size());
      if (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
      return true;
    };
    if (take(":")) {
      ex.stdout_lines.push_back(rtrim(rest));
    } else if (take(" error:")) {
      ex.diagnostics.push_back(rtrim(rest));
    } else if (take(" warning:")) {
      ex.diagnostics.push_back("warning " + rtrim(rest));
    }
  }
  std::sort(ex.diagnostics.begin(), ex.diagnostics.end());
  return ex;
}

ScriptTestResult run_script_test(const std::string& path, const RunSettings& settings) {
  ScriptTestResult res;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    res.details = "cannot read the script";
    return res;
  }
  std::stringstream buf;
  buf << in.rdbuf();
  const ScriptExpectations ex = parse_expectations(buf.str());
  const bool expect_fail = fs::path(path).filename().string().rfind("fail_", 0) == 0;

  lang::SourceManager sources;
  lang::Diagnostics diags(sources);
  diags.set_max_errors(0);
  std::ostringstream out;
  Interpreter interp(sources, diags, out, settings);
  interp.run_file(path);

  // Each diagnostic as "[warning ]line:col: kebab: message"; an expectation without the
  // message ("line:col: kebab") matches any message of that kind there.
  std::vector<std::string> got;
  for (const auto& d : diags.all()) {
    if (d.severity == lang::Severity::Note) continue;
    const lang::LineCol lc = d.range.valid() ? sources.line_col(d.range.begin_loc()) : lang::LineCol{};
    got.push_back(fmt::format("{}{}:{}: {}: {}", d.severity == lang::Severity::Warning ? "warning " : "",
                              lc.line, lc.col, lang::diag_info(d.kind).kebab, d.message));
  }
  std::sort(got.begin(), got.end());
  std::vector<std::string> unmatched = got;
  std::vector<std::string> missing;
  for (const std::string& e : ex.diagnostics) {
    auto it = std::find_if(unmatched.begin(), unmatched.end(), [&](const std::string& g) {
      return g == e || (g.size() > e.size() + 2 && g.compare(0, e.size(), e) == 0 && g.compare(e.size(), 2, ": ") == 0);
    });
    if (it == unmatched.end())
      missing.push_back(e);
    else
      unmatched.erase(it);
  }
  std::string why;
  const auto differ = [&] {
    return fmt::format("diagnostics differ:\n  expected but not given: {}\n  given but not expected: {}\n",
                       fmt::join(missing, " | "), fmt::join(unmatched, " | "));
  };
  if (expect_fail) {
    if (ex.diagnostics.empty()) why += "a fail_ script must list its '// expect error:' lines\n";
    if (!missing.empty() || !unmatched.empty()) why += differ();
  } else {
    const bool has_error = std::any_of(diags.all().begin(), diags.all().end(),
                                       [](const auto& d) { return d.severity == lang::Severity::Error; });
    if (has_error) why += "unexpected errors:\n" + diags.render_all();
    // A script that lists '// expect warning:' lines gets exactly those warnings.
    else if (!ex.diagnostics.empty() && (!missing.empty() || !unmatched.empty())) why += differ();
  }
  const std::vector<std::string> lines = split_lines(out.str());
  if (lines != ex.stdout_lines) {
    why += "output differs:\n";
    const std::size_t n = std::max(lines.size(), ex.stdout_lines.size());
    for (std::size_t i = 0; i < n; ++i) {
      const std::string e = i < ex.stdout_lines.size() ? ex.stdout_lines[i] : "<none>";
      const std::string g = i < lines.size() ? lines[i] : "<none>";
      if (e != g) {
        why += fmt::format("  line {}: expected '{}', got '{}'\n", i + 1, e, g);
        break;   // the first difference is enough to find the statement
      }
    }
  }
  res.passed = why.empty();
  res.details = std::move(why);
  return res;
}

int run_script_tests(const std::vector<std::string>& paths, const RunSettings& settings, std::ostream& out) {
  std::vector<std::string> scripts;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (auto it = fs::recursive_directory_iterator(p, ec); !ec && it != fs::recursive_directory_iterator();
           it.increment(ec)) {
        if (it->is_regular_file(ec) && it->path().extension() == ".geo") found.push_back(it->path().string());
      }
      std::sort(found.begin(), found.end());
      scripts.insert(scripts.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(p, ec)) {
      scripts.push_back(p);
    } else {
      out << fmt::format("stereomesh --test: '{}' does not exist\n", p);
      return -1;
    }
  }
  int passed = 0, failed = 0;
  for (const std::string& s : scripts) {
    const ScriptTestResult r = run_script_test(s, settings);
    if (r.passed) {
      ++passed;
    } else {
      ++failed;
      out << "FAIL " << s << '\n' << r.details;
    }
  }
  out << fmt::format("{} passed, {} failed\n", passed, failed);
  return failed;
}

}  // namespace sm::interp
