#!/bin/sh
# A diagnostic reported with the wrong arguments for its kind's format does not build
# (src/lang/diag_format.h): one call with the right arguments compiles, and each of the
# wrong ones (an argument too few, one too many, a string where the slot formats an
# integer, a kind chosen at run time, a plain string for a named slot) is refused by the
# compiler, for its reason (fmt names a bad slot through its error_handler). Run by CTest
# with the project's compiler: check_diag_format_compile.sh CXX SRC_DIR.
cxx="$1"
src="$2"
[ -n "$cxx" ] && [ -f "$src/lang/diag_format.h" ] || { echo "usage: $0 CXX SRC_DIR"; exit 2; }
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
status=0
# compile NAME EXPECT CALL: EXPECT is "ok", or text the compiler's error must contain.
compile() {
  cat > "$dir/$1.cpp" <<CPP
#include "lang/diagnostics.h"
using namespace sm::lang;
std::string run(Diag runtime_kind) {
  static_cast<void>(runtime_kind);
  SourceManager sources;
  Diagnostics diags(sources);
  $3;
  return diags.all().empty() ? std::string() : diags.all().back().message;
}
CPP
  if "$cxx" -std=c++20 -fsyntax-only -I"$src" "$dir/$1.cpp" > "$dir/$1.log" 2>&1; then
    [ "$2" = ok ] && return
    echo "$1: compiled, but it reports with the wrong arguments"
    status=1
  elif [ "$2" = ok ]; then
    echo "$1: a call with the right arguments does not compile:"
    head -20 "$dir/$1.log"
    status=1
  elif ! grep -q "$2" "$dir/$1.log"; then
    echo "$1: refused, but not for its reason ('$2' not in the compiler's errors):"
    grep error "$dir/$1.log" | head -5
    status=1
  fi
}
compile right ok 'diags.report(SourceRange{}, Diag::IndexOutOfRange, 4, "L", std::size_t{3})'
compile too_few "argument not found" 'diags.report(SourceRange{}, Diag::IndexOutOfRange, 4, "L")'
compile too_many diag_argument_count_differs_from_format \
  'diags.report(SourceRange{}, Diag::IndexOutOfRange, 4, "L", 3, 5)'
compile wrong_type "error_handler::on_error" \
  'diags.report(SourceRange{}, Diag::InvalidByte, std::string("x"))'
compile runtime_kind "not a constant expression" 'diags.report(SourceRange{}, runtime_kind, 1)'
# A named slot ("{text}", the script's own text of UserError) takes only its named argument:
# a sentence passed as a plain string, or under another name, is refused.
compile user_text ok 'using namespace fmt::literals; diags.report(SourceRange{}, Diag::UserError, "text"_a = std::string("x"))'
compile user_text_plain "named argument is not found" \
  'diags.report(SourceRange{}, Diag::UserError, std::string("x"))'
compile user_text_other_name "named argument is not found" \
  'using namespace fmt::literals; diags.report(SourceRange{}, Diag::UserError, "message"_a = std::string("x"))'
exit $status
