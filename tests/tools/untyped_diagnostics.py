#!/usr/bin/env python3
"""Lists the diagnostic kinds whose format is a bare "{}" (the caller builds the whole sentence).

A kind of src/lang/diag_kinds.def declares its message's shape, DIAG(Name, Severity,
"kebab", "format"): the callers pass the values its slots read, checked at compile time
(src/lang/diag_format.h). A format that is only "{}" declares no shape: any sentence fits.

  untyped_diagnostics.py [--def FILE]                 list the kinds whose format is "{}"
  untyped_diagnostics.py --check [--allow FILE] [--def FILE]
                                                      fail (exit 1) on a "{}" kind (one an
                                                      allow-list does not hold), and on a
                                                      listed one that is typed now or gone
  untyped_diagnostics.py --self-test                  the reader on a sample table

The allow-list holds one kind name a line; `#` starts a comment. CTest
(tests/CMakeLists.txt, untyped_diagnostics) runs the check with none: no kind may be "{}".
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DEF = os.path.join(HERE, "..", "..", "src", "lang", "diag_kinds.def")

# DIAG(Name, Severity, "kebab", "format" ["format" ...]): the format may be split into
# adjacent string literals over several lines.
ENTRY = re.compile(r'^DIAG\(\s*(\w+)\s*,\s*(\w+)\s*,\s*"([^"]*)"\s*,((?:\s*"(?:[^"\\]|\\.)*")+)\s*\)',
                   re.MULTILINE)
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')


def kinds(text):
    """(name, format) of every DIAG entry, in order; comment lines are skipped."""
    text = "\n".join("" if line.lstrip().startswith("//") else line for line in text.split("\n"))
    return [(m.group(1), "".join(LITERAL.findall(m.group(4)))) for m in ENTRY.finditer(text)]


def untyped(entries):
    return [name for name, fmt in entries if fmt.strip() == "{}"]


def read_allow(path):
    names = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                names.append(line)
    return names


def check(entries, allowed):
    """The problems: untyped kinds not allowed, allowed ones typed or unknown, duplicates."""
    problems = []
    names = {name for name, _ in entries}
    bare = set(untyped(entries))
    seen = set()
    for name in allowed:
        if name in seen:
            problems.append(f"{name}: listed twice")
        seen.add(name)
        if name not in names:
            problems.append(f"{name}: listed but not a kind of diag_kinds.def: take it off the list")
        elif name not in bare:
            problems.append(f"{name}: has a typed format now: take it off the list")
    for name in sorted(bare - seen):
        problems.append(f'{name}: its format is "{{}}": declare the message\'s shape in diag_kinds.def '
                        f"and pass its values (the list only shrinks)")
    return problems


def self_test():
    sample = '\n'.join([
        '// DIAG(Commented, Error, "commented", "{}")',
        'DIAG(Plain, Error, "plain", "{}")',
        'DIAG(Typed, Error, "typed", "unknown field type \'{}\'{}")',
        'DIAG(Split, Warning, "split",',
        '     "first {} " "second {}")',
        'DIAG(SplitPlain, Note, "split-plain",',
        '     "{}")',
        'DIAG(Escaped, Error, "escaped", "write {{{}}}")',
    ])
    entries = kinds(sample)
    ok = True

    def expect(what, got, want):
        nonlocal ok
        if got != want:
            print(f"self-test: {what}: got {got!r}, want {want!r}")
            ok = False

    expect("names", [n for n, _ in entries], ["Plain", "Typed", "Split", "SplitPlain", "Escaped"])
    expect("split format", dict(entries)["Split"], "first {} second {}")
    expect("untyped", untyped(entries), ["Plain", "SplitPlain"])
    expect("clean list", check(entries, ["Plain", "SplitPlain"]), [])
    expect("missing from list", len(check(entries, ["Plain"])), 1)
    expect("typed on list", len(check(entries, ["Plain", "SplitPlain", "Typed"])), 1)
    expect("unknown on list", len(check(entries, ["Plain", "SplitPlain", "Gone"])), 1)
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--def", dest="def_file", default=DEFAULT_DEF)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--allow")
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    with open(args.def_file, encoding="utf-8") as f:
        entries = kinds(f.read())
    if not entries:
        print(f"{args.def_file}: no DIAG entries found")
        return 1
    if not args.check:
        for name in untyped(entries):
            print(name)
        print(f'{len(untyped(entries))} of {len(entries)} kinds have the format "{{}}"')
        return 0
    problems = check(entries, read_allow(args.allow) if args.allow else [])
    for p in problems:
        print(p)
    if not problems:
        print(f'{len(untyped(entries))} of {len(entries)} kinds still have the format "{{}}" (all listed)')
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
