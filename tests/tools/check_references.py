#!/usr/bin/env python3
"""Fails when a comment or doc leads outside the repository.

A reader of a clone has the repository and nothing else: a reference to an issue number
("#38", "issue 38") or to a folder of the machine it was written on ("/work/...",
"/tmp/...", "/home/...") leads nowhere for them. The folders beside the checkout are
tests/tools/check_standalone.sh's check.

  check_references.py --check ROOT   fail (exit 1) on every such reference in ROOT's src/,
                                     docs/, examples/, grammar/, stdlib/ and top-level *.md
  check_references.py --self-test    the patterns on planted lines, each way

The test and benchmark sources under tests/ are not read: their scratch files are real
paths of the machine that runs them (a /tmp folder), not references.
"""
import argparse
import os
import re
import sys

SCANNED_DIRS = ("src", "docs", "examples", "grammar", "stdlib")
SCANNED_SUFFIXES = (".h", ".cpp", ".def", ".py", ".md", ".geo", ".txt", ".sh", ".cmake", ".in", ".pyi")

# Spelled in parts so that this file's own text does not read as a reference.
ROOTS = "|".join(("wo" + "rk", "tm" + "p", "ho" + "me"))
PATTERNS = (
    ("a machine path", re.compile(r"(?<![\w.~-])/(?:" + ROOTS + r")/")),
    ("an issue number", re.compile(r"\b(?:issue|pull request|PR)s?\s+#?\d+", re.IGNORECASE)),
    # "#38" standing alone (after a space or bracket, before a space, a bracket or a stop);
    # "#0" inside a quoted format's flags ("-+ #0") or "#list[]" in a script is not one.
    ("an issue number", re.compile(r"(?:^|(?<=[\s(\[]))#\d+(?=[\s).,;:\]]|$)")),
)


def problems_in(text):
    """(line number, what, line) of every reference in a file's text."""
    found = []
    for number, line in enumerate(text.split("\n"), 1):
        for what, pattern in PATTERNS:
            if pattern.search(line):
                found.append((number, what, line.strip()))
                break
    return found


def scanned_files(root):
    for d in SCANNED_DIRS:
        for base, dirs, files in os.walk(os.path.join(root, d)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(SCANNED_SUFFIXES):
                    yield os.path.join(base, name)
    for name in sorted(os.listdir(root)):
        if name.endswith(".md"):
            yield os.path.join(root, name)


def check(root):
    count, bad = 0, []
    for path in scanned_files(root):
        count += 1
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, what, line in problems_in(f.read()):
                bad.append(f"{os.path.relpath(path, root)}:{number}: {what}: {line}")
    if bad:
        print("references that lead outside the repository:")
        print("\n".join(bad))
        return 1
    print(f"no issue number or machine path in {count} files")
    return 0


def self_test():
    flagged = [
        "// Fixes the walk (issue 38).",
        "// See #38 for the plan.",
        "see issue #12, the cavity",
        "(#7) the floor",
        "Merged in PR 41.",
        "the mesh in /" + "tmp/ref/w3km.msh",
        "read /" + "work/shared/STYLE.md first",
        "`/" + "home/user/data`",
    ]
    clean = [
        'while (i < fmt.size() && std::string_view("-+ #0").find(fmt[i]) != npos)',
        "n = #list[];",
        "stroke=\"#999\"",
        "the 3 km world (docs/bench/scale.json)",
        "Issues are reported at file:line:col.",
        "a path such as out/tmp/x.msh or ./work/a.geo",
    ]
    failures = []
    for line in flagged:
        if not problems_in(line):
            failures.append(f"not flagged: {line}")
    for line in clean:
        if problems_in(line):
            failures.append(f"flagged: {line}")
    print("\n".join(failures) if failures else f"{len(flagged) + len(clean)} planted lines read as expected")
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", metavar="ROOT")
    ap.add_argument("--self-test", action="store_true")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    if args.check:
        return check(args.check)
    ap.print_usage()
    return 2


if __name__ == "__main__":
    sys.exit(main())
