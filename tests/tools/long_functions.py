#!/usr/bin/env python3
"""Lists the functions in src/ longer than a limit, longest first.

A function is found by brace matching: comments, string and character literals are
blanked out, then every `{` at namespace or class scope whose text since the previous
`;`, `{` or `}` ends in `)` (with const, noexcept, override, a trailing return type, or a
constructor's initialiser list after it) opens a function; its length is the lines from
the line naming it to its closing brace, both counted. Lambdas and local classes count
as part of the function that holds them.

  long_functions.py [--src DIR] [--min N]          list functions of more than N lines
  long_functions.py --check LIMIT [--allow FILE]   fail (exit 1) if a function not on the
                                                   allow-list has more than LIMIT lines,
                                                   or an allow-listed one no longer does
  long_functions.py --self-test                    the counter on a sample of known functions

The allow-list holds one `path:function` a line (path relative to src/); `#` starts a
comment. Run by CTest (tests/CMakeLists.txt, function_length).
"""
import argparse
import os
import re
import sys

KEYWORDS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof",
            "noexcept", "static_assert", "requires", "co_return"}


def blank(text):
    """Replaces comments and literals by spaces, keeping newlines (so line numbers hold)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i + 2)
            delim = text[i + 2:k]
            j = text.find(")" + delim + '"', k)
            j = n if j < 0 else j + len(delim) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum())):
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * (j - i - 2) + c if j - i >= 2 else " " * (j - i))
            i = j
        elif c == "#" and (i == 0 or text[i - 1] == "\n"):
            # preprocessor line (with continuations): no braces of its own count
            j = i
            while True:
                e = text.find("\n", j)
                if e < 0:
                    e = n
                    break
                if text[e - 1] == "\\":
                    j = e + 1
                    continue
                break
            out.append(re.sub(r"[^\n]", " ", text[i:e]))
            i = e
        else:
            out.append(c)
            i += 1
    return "".join(out)


AFTER_PARAMS = re.compile(r"\)\s*(?:(?:const|noexcept(?:\s*\([^)]*\))?|override|final|mutable|&&|&)\s*)*"
                          r"(?:->[^;{}]*)?$")


def function_name(header):
    """The name before the parameter list: the identifier (with scope) before the first
    `(` at depth 0 that is not inside template arguments, or operator...()."""
    m = re.search(r"(operator\s*(?:\(\)|[^\s(]+))\s*\(", header)
    if m:
        pre = header[:m.start()]
        s = re.search(r"((?:\w+::)*)$", pre)   # the class of a member operator
        return s.group(1) + m.group(1).replace(" ", "")
    depth = 0
    for k, ch in enumerate(header):
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth = max(0, depth - 1)
        elif ch == "(" and depth == 0:
            s = re.search(r"([\w:~]+)\s*$", header[:k])
            if s and s.group(1).split("::")[-1] not in KEYWORDS:
                return s.group(1)
            return None
    return None


def is_function(header):
    h = header.strip()
    if not h or "(" not in h:
        return False
    if re.match(r"(template\s*<.*>\s*)?(namespace|struct|class|union|enum)\b", h, re.S):
        return False
    if AFTER_PARAMS.search(h):
        return function_name(h) is not None
    # constructor initialiser list: `X::X(...) : a_(b), c_{d} {`
    m = re.search(r"\)\s*(noexcept\s*)?:(?!:)", h)
    if m and h[-1] in ")}":   # else the brace is a member's initialiser `c_{d}` inside the list
        return function_name(h[:m.start() + 1]) is not None
    # lambda bound at namespace scope: `auto f = [](...) {`
    return False


def functions(path, source=None):
    text = blank(open(path, encoding="utf-8", errors="replace").read() if source is None else source)
    line_of = []
    line = 1
    for ch in text:
        line_of.append(line)
        if ch == "\n":
            line += 1
    found = []
    stack = []  # 'scope' (namespace, class, other data) or ('fn', name, first line)
    header_start = 0
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        in_fn = any(isinstance(s, tuple) for s in stack)
        if ch == "{":
            if in_fn:
                stack.append("block")
            else:
                header = text[header_start:i]
                if is_function(header):
                    name = function_name(header.strip())
                    k = header_start + header.find(name.split("::")[0]) if name else header_start
                    # the line naming the function: where its name stands before `(`
                    m = re.search(re.escape(name) + r"\s*\(", header)
                    first = line_of[header_start + m.start()] if m else line_of[k]
                    stack.append(("fn", name, first))
                elif re.search(r"(=|\w|\])\s*$", header) and not re.match(
                        r"\s*(template\s*<.*>\s*)?(namespace|struct|class|union|enum|extern)\b", header, re.S):
                    # an initialiser `x{...}` or `= {...}` inside a header: part of the header
                    depth = 1
                    j = i + 1
                    while j < n and depth:
                        depth += {"{": 1, "}": -1}.get(text[j], 0)
                        j += 1
                    i = j
                    continue
                else:
                    stack.append("scope")
            header_start = i + 1
        elif ch == "}":
            top = stack.pop() if stack else None
            if isinstance(top, tuple):
                found.append((top[1], top[2], line_of[i]))
            header_start = i + 1
        elif ch == ";" and not in_fn:
            header_start = i + 1
        i += 1
    return found


SELF_TEST = r'''namespace sm {
namespace {
constexpr int kTable[] = {1, 2, 3};
struct S {
  int a_, b_;
  S(int x) : a_(x), b_{x} {
    a_ += 1;
  }
  int f() const { return a_; }
};
}  // namespace
auto g(int x) -> int {
  if (x > 0) {
    return 1;
  }
  auto l = [&](int y) { return y + x; };
  return l(0);
}
void h(const char* s = "{") {
  // }
  char c = '}';
  const char* r = R"x(})x";
  int n = 1'000;
  /* { */
}
#define BRACE {
template <class T>
T k(T v) noexcept {
  return v;
}
}  // namespace sm
'''
SELF_TEST_EXPECT = [("S", 6, 8), ("f", 9, 9), ("g", 12, 18), ("h", 19, 25), ("k", 28, 30)]


def self_test():
    got = sorted(functions("self_test.cpp", SELF_TEST), key=lambda r: r[1])
    if got != SELF_TEST_EXPECT:
        print(f"the counter finds {got}, expected {SELF_TEST_EXPECT}")
        return 1
    print(f"the counter finds the {len(got)} functions of its sample with their lines")
    return 0


def scan(src):
    rows = []
    for root, dirs, files in os.walk(src):
        dirs.sort()
        for f in sorted(files):
            if f.endswith((".cpp", ".h", ".hpp", ".cc")):
                p = os.path.join(root, f)
                for name, a, b in functions(p):
                    rows.append((b - a + 1, os.path.relpath(p, src), name, a))
    rows.sort(key=lambda r: (-r[0], r[1], r[3]))
    return rows


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", default=os.path.join(here, "..", "..", "src"))
    ap.add_argument("--min", type=int, default=100)
    ap.add_argument("--check", type=int)
    ap.add_argument("--allow")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    rows = scan(a.src)
    if a.check is None:
        over = [r for r in rows if r[0] > a.min]
        for lines, path, name, first in over:
            print(f"{lines:5d}  {path}:{first}  {name}")
        print(f"{len(over)} functions over {a.min} lines ({len(rows)} functions in {a.src})")
        return 0
    allowed = set()
    if a.allow:
        for ln in open(a.allow, encoding="utf-8"):
            ln = ln.split("#", 1)[0].strip()
            if ln:
                allowed.add(ln)
    status = 0
    seen = set()
    for lines, path, name, first in rows:
        key = f"{path}:{name}"
        if lines > a.check:
            if key in allowed:
                seen.add(key)
            else:
                print(f"src/{path}:{first}: {name} has {lines} lines (limit {a.check}): split it into named stages")
                status = 1
    for key in sorted(allowed - seen):
        print(f"{key} is allow-listed but no longer over {a.check} lines (or gone): take it off the list")
        status = 1
    if status == 0:
        print(f"every function in src/ has at most {a.check} lines but the {len(allowed)} allow-listed")
    return status


if __name__ == "__main__":
    sys.exit(main())
