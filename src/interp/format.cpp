// Printf/Sprintf formatting with Gmsh 4.8.4's piece-by-piece rules (see format.h);
// each directive is validated before it reaches snprintf, so no format string
// from a script can read a missing argument or write past a buffer.
#include "interp/format.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include <fmt/format.h>

namespace sm::interp {
namespace {

// Widths and precisions beyond this are refused: a script must not be able to
// ask snprintf for gigabytes with "%999999999g".
constexpr int kMaxWidth = 4096;

struct Directive {
  std::size_t begin = 0;   // index of the '%'
  std::size_t end = 0;     // one past the conversion character
  char conv = 0;
  std::string spec;        // "%-8.3" + length-free conversion, ready for snprintf
};

// Parses the directive starting at fmt[pos] == '%'. Returns an error message or "".
std::string parse_directive(std::string_view fmt, std::size_t pos, Directive& d) {
  d.begin = pos;
  std::size_t i = pos + 1;
  std::string spec = "%";
  while (i < fmt.size() && std::string_view("-+ #0").find(fmt[i]) != std::string_view::npos)
    spec += fmt[i++];
  auto read_number = [&](const char* what) -> std::string {
    long n = 0;
    while (i < fmt.size() && fmt[i] >= '0' && fmt[i] <= '9') {
      n = n * 10 + (fmt[i] - '0');
      if (n > kMaxWidth) return fmt::format("format {} larger than {}", what, kMaxWidth);
      spec += fmt[i++];
    }
    return "";
  };
  if (i < fmt.size() && fmt[i] == '*') return "'*' width is not supported in a format";
  if (auto e = read_number("width"); !e.empty()) return e;
  if (i < fmt.size() && fmt[i] == '.') {
    spec += fmt[i++];
    if (i < fmt.size() && fmt[i] == '*') return "'*' precision is not supported in a format";
    if (auto e = read_number("precision"); !e.empty()) return e;
  }
  // Length modifiers carry no meaning here: every number is a double.
  while (i < fmt.size() && std::string_view("hlLqjzt").find(fmt[i]) != std::string_view::npos) ++i;
  if (i >= fmt.size()) return "incomplete '%' directive at the end of the format";
  const char c = fmt[i];
  if (std::string_view("gGeEfFaAdiouxXcs").find(c) == std::string_view::npos)
    return fmt::format("invalid conversion '%{}' in format", c);
  d.conv = c;
  d.end = i + 1;
  d.spec = spec;
  return "";
}

bool is_int_conv(char c) { return std::string_view("diouxXc").find(c) != std::string_view::npos; }

std::string run_snprintf(const std::string& spec, auto value) {
  const int n = std::snprintf(nullptr, 0, spec.c_str(), value);
  if (n <= 0) return "";
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), spec.c_str(), value);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

// Formats one directive with one argument; returns an error message or "".
std::string format_one(const Directive& d, const FormatArg& arg, std::string& out) {
  if (d.conv == 's') {
    const auto* s = std::get_if<std::string>(&arg);
    if (!s) return "'%s' expects a string argument, got a number";
    out += run_snprintf(d.spec + "s", s->c_str());
    return "";
  }
  const auto* v = std::get_if<double>(&arg);
  if (!v) return fmt::format("'%{}' expects a number, got a string", d.conv);
  if (is_int_conv(d.conv)) {
    // C printf semantics on the truncated value (Gmsh 4.8.4 passes a double
    // to "%d" and prints garbage).
    if (!std::isfinite(*v) || std::fabs(*v) >= 9.2e18)
      return fmt::format("value {} does not fit the integer conversion '%{}'", format_g(*v), d.conv);
    const auto iv = static_cast<long long>(*v);
    if (d.conv == 'd' || d.conv == 'i')
      out += run_snprintf(d.spec + "ll" + d.conv, iv);
    else if (d.conv == 'c')
      out += run_snprintf(d.spec + "c", static_cast<int>(static_cast<unsigned char>(iv)));
    else
      out += run_snprintf(d.spec + "ll" + d.conv, static_cast<unsigned long long>(iv));
    return "";
  }
  out += run_snprintf(d.spec + d.conv, *v);
  return "";
}

}  // namespace

std::string format_g(double v) { return run_snprintf(std::string("%g"), v); }

FormatResult format_gmsh(std::string_view fmt, const std::vector<FormatArg>& args) {
  FormatResult r;
  // Collect the directives first: "%%" is a literal percent sign.
  std::vector<Directive> dirs;
  for (std::size_t i = 0; i < fmt.size(); ++i) {
    if (fmt[i] != '%') continue;
    if (i + 1 < fmt.size() && fmt[i + 1] == '%') {
      ++i;
      continue;
    }
    Directive d;
    if (auto e = parse_directive(fmt, i, d); !e.empty()) {
      r.ok = false;
      r.error = std::move(e);
      return r;
    }
    dirs.push_back(d);
    i = d.end - 1;
  }
  auto literal = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      r.text += fmt[i];
      if (fmt[i] == '%') ++i;   // "%%" -> "%"
    }
  };
  if (dirs.empty()) {
    literal(0, fmt.size());
    // Gmsh's list dump: the format followed by " [i]v" for every argument.
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (const auto* v = std::get_if<double>(&args[i]))
        r.text += fmt::format(" [{}]{}", i, format_g(*v));
      else
        r.text += fmt::format(" [{}]{}", i, std::get<std::string>(args[i]));
    }
    return r;
  }
  if (args.size() < dirs.size()) {
    r.ok = false;
    r.error = fmt::format("too few arguments for the format: {} directive{} but {} argument{}",
                          dirs.size(), dirs.size() == 1 ? "" : "s", args.size(),
                          args.size() == 1 ? "" : "s");
    return r;
  }
  if (args.size() > dirs.size()) {
    const std::size_t extra = args.size() - dirs.size();
    r.ok = false;
    r.error = fmt::format("{} extra argument{} for the format", extra, extra == 1 ? "" : "s");
    r.arg_index = static_cast<int>(dirs.size());
    return r;
  }
  std::size_t pos = 0;
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    literal(pos, dirs[k].begin);
    if (auto e = format_one(dirs[k], args[k], r.text); !e.empty()) {
      r.ok = false;
      r.error = std::move(e);
      r.arg_index = static_cast<int>(k);
      return r;
    }
    pos = dirs[k].end;
  }
  literal(pos, fmt.size());
  return r;
}

}  // namespace sm::interp
