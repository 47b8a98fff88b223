// Printf/Sprintf formatting with Gmsh 4.8.4's piece-by-piece rules (see format.h);
// each directive is validated before it reaches snprintf, so no format string
// from a script can read a missing argument or write past a buffer.
#include "interp/format.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include <fmt/format.h>

namespace sm::interp {

using lang::Diag;
using lang::DiagFormat;
using lang::format_diag;

namespace {

// Why a format failed: its Format* kind and that kind's message.
struct FormatFailure {
  Diag kind = Diag::kCount;
  std::string message;
  bool failed() const { return kind != Diag::kCount; }
};

template <class... Args>
FormatFailure format_failure(std::type_identity_t<DiagFormat<Args...>> kind, const Args&... args) {
  return {kind.kind(), format_diag<Args...>(kind, args...)};
}

// Widths and precisions beyond this are refused: a script must not be able to
// ask snprintf for gigabytes with "%999999999g".
constexpr int kMaxWidth = 4096;

struct Directive {
  std::size_t begin = 0;   // index of the '%'
  std::size_t end = 0;     // one past the conversion character
  char conv = 0;
  std::string spec;        // "%-8.3" + length-free conversion, ready for snprintf
};

// Parses the directive starting at fmt[pos] == '%'. Returns why it is refused, if it is.
FormatFailure parse_directive(std::string_view fmt, std::size_t pos, Directive& d) {
  d.begin = pos;
  std::size_t i = pos + 1;
  std::string spec = "%";
  while (i < fmt.size() && std::string_view("-+ #0").find(fmt[i]) != std::string_view::npos)
    spec += fmt[i++];
  auto read_number = [&](std::string_view what) -> FormatFailure {
    long n = 0;
    while (i < fmt.size() && fmt[i] >= '0' && fmt[i] <= '9') {
      n = n * 10 + (fmt[i] - '0');
      if (n > kMaxWidth) return format_failure(Diag::FormatNumberTooLarge, what, kMaxWidth);
      spec += fmt[i++];
    }
    return {};
  };
  if (i < fmt.size() && fmt[i] == '*') return format_failure(Diag::FormatStarNotSupported, std::string_view("width"));
  if (auto e = read_number("width"); e.failed()) return e;
  if (i < fmt.size() && fmt[i] == '.') {
    spec += fmt[i++];
    if (i < fmt.size() && fmt[i] == '*')
      return format_failure(Diag::FormatStarNotSupported, std::string_view("precision"));
    if (auto e = read_number("precision"); e.failed()) return e;
  }
  // Length modifiers carry no meaning here: every number is a double.
  while (i < fmt.size() && std::string_view("hlLqjzt").find(fmt[i]) != std::string_view::npos) ++i;
  if (i >= fmt.size()) return format_failure(Diag::FormatIncompleteDirective);
  const char c = fmt[i];
  if (std::string_view("gGeEfFaAdiouxXcs").find(c) == std::string_view::npos)
    return format_failure(Diag::FormatInvalidConversion, c);
  d.conv = c;
  d.end = i + 1;
  d.spec = spec;
  return {};
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

// Formats one directive with one argument; returns why it cannot, if it cannot.
FormatFailure format_one(const Directive& d, const FormatArg& arg, std::string& out) {
  if (d.conv == 's') {
    const auto* s = std::get_if<std::string>(&arg);
    if (!s) return format_failure(Diag::FormatStringExpected);
    out += run_snprintf(d.spec + "s", s->c_str());
    return {};
  }
  const auto* v = std::get_if<double>(&arg);
  if (!v) return format_failure(Diag::FormatNumberExpected, d.conv);
  if (is_int_conv(d.conv)) {
    // C printf semantics on the truncated value (Gmsh 4.8.4 passes a double
    // to "%d" and prints garbage).
    if (!std::isfinite(*v) || std::fabs(*v) >= 9.2e18)
      return format_failure(Diag::FormatIntegerOverflow, format_g(*v), d.conv);
    const auto iv = static_cast<long long>(*v);
    if (d.conv == 'd' || d.conv == 'i')
      out += run_snprintf(d.spec + "ll" + d.conv, iv);
    else if (d.conv == 'c')
      out += run_snprintf(d.spec + "c", static_cast<int>(static_cast<unsigned char>(iv)));
    else
      out += run_snprintf(d.spec + "ll" + d.conv, static_cast<unsigned long long>(iv));
    return {};
  }
  out += run_snprintf(d.spec + d.conv, *v);
  return {};
}

FormatResult failed_result(FormatFailure f, int arg_index) {
  FormatResult r;
  r.ok = false;
  r.kind = f.kind;
  r.error = std::move(f.message);
  r.arg_index = arg_index;
  return r;
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
    if (auto e = parse_directive(fmt, i, d); e.failed()) return failed_result(std::move(e), -1);
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
  auto plural = [](std::size_t n) { return std::string_view(n == 1 ? "" : "s"); };
  if (args.size() < dirs.size())
    return failed_result(
        format_failure(Diag::FormatTooFewArguments, dirs.size(), plural(dirs.size()), args.size(), plural(args.size())),
        -1);
  if (args.size() > dirs.size()) {
    const std::size_t extra = args.size() - dirs.size();
    return failed_result(format_failure(Diag::FormatExtraArguments, extra, plural(extra)),
                         static_cast<int>(dirs.size()));
  }
  std::size_t pos = 0;
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    literal(pos, dirs[k].begin);
    if (auto e = format_one(dirs[k], args[k], r.text); e.failed())
      return failed_result(std::move(e), static_cast<int>(k));
    pos = dirs[k].end;
  }
  literal(pos, fmt.size());
  return r;
}

}  // namespace sm::interp
