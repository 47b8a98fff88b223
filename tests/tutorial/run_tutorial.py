#!/usr/bin/env python3
"""Runs docs/tutorial.md as a newcomer pastes it, so that the tutorial cannot go stale.

Every ```geo block is appended, in the order of the page, to the tutorial's script
(irish_sea.geo in a scratch folder). A ```console block holds commands (lines starting
with "$ ") each followed by what it prints: when the block is reached, the script so far is
written out and the command is run in the scratch folder ("stereomesh" is the built
program; "python3" is /usr/bin/python3 with the module's folder on PYTHONPATH). Every
printed line shown must appear in the command's output (stdout and stderr), in that order;
"..." in a shown line stands for any text (timings, sizes that vary by machine). A
```python block is written to the file named on its first line ("# file.py") and run by
the console block that names it.

The finished script, examples/irish_sea.geo, must be those blocks: the same lines once
comments and blank lines are left out of both.

usage: run_tutorial.py STEREOMESH PYTHON_MODULE_DIR [TUTORIAL_MD]
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

FENCE = re.compile(r"^```(\w*)\s*$")


def blocks(markdown):
    """(language, lines, line number of the fence) for each fenced block, in order."""
    out, lang, body, start = [], None, [], 0
    for number, line in enumerate(markdown.splitlines(), 1):
        m = FENCE.match(line)
        if lang is None:
            if m:
                lang, body, start = m.group(1), [], number
        elif line.strip() == "```":
            out.append((lang, body, start))
            lang = None
        else:
            body.append(line)
    if lang is not None:
        sys.exit(f"tutorial:{start}: a code block is not closed")
    return out


def pattern(shown):
    """A regular expression for one shown output line ("..." matches anything)."""
    parts = [re.escape(p) for p in shown.strip().split("...")]
    return re.compile(".*".join(parts))


def check_output(where, command, output, shown):
    lines = [l.rstrip() for l in output.splitlines()]
    at = 0
    for want in shown:
        if not want.strip():
            continue
        rx = pattern(want)
        while at < len(lines) and not rx.fullmatch(lines[at].strip()):
            at += 1
        if at == len(lines):
            return (f"{where}: `{command}` did not print (in order) the line\n    {want.strip()}\n"
                    f"  it printed:\n" + "\n".join("    " + l for l in lines))
        at += 1
    return None


def code_lines(lines):
    """The lines of a script without // comments and blank lines (for the example check)."""
    out = []
    for line in lines:
        code = line.split("//", 1)[0].rstrip()
        if code.strip():
            out.append(code)
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    stereomesh = os.path.abspath(sys.argv[1])
    module_dir = os.path.abspath(sys.argv[2])
    md = Path(sys.argv[3] if len(sys.argv) > 3 else Path(__file__).resolve().parents[2] / "docs" / "tutorial.md")
    script_lines, commands, failures = [], 0, []
    env = dict(os.environ, PYTHONPATH=module_dir + os.pathsep + os.environ.get("PYTHONPATH", ""))
    with tempfile.TemporaryDirectory(prefix="tutorial-") as work:
        for lang, body, start in blocks(md.read_text()):
            where = f"{md.name}:{start}"
            if lang == "geo":
                script_lines += body
                continue
            if lang == "python":
                first = body[0].strip() if body else ""
                if not first.startswith("# ") or not first.endswith(".py"):
                    failures.append(f"{where}: a python block starts with '# name.py'")
                    continue
                Path(work, first[2:]).write_text("\n".join(body) + "\n")
                continue
            if lang != "console":
                continue
            Path(work, "irish_sea.geo").write_text("\n".join(script_lines) + "\n")
            i = 0
            while i < len(body):
                if not body[i].startswith("$ "):
                    failures.append(f"{where}: output before any command: {body[i]!r}")
                    break
                command = body[i][2:].strip()
                i += 1
                shown = []
                while i < len(body) and not body[i].startswith("$ "):
                    shown.append(body[i])
                    i += 1
                argv = shlex.split(command)
                if argv[0] == "stereomesh":
                    argv[0] = stereomesh
                elif argv[0] == "python3":
                    argv[0] = "/usr/bin/python3"
                elif argv[0] not in ("ls", "head"):
                    failures.append(f"{where}: the tutorial runs only stereomesh, python3, ls, head: {command}")
                    continue
                commands += 1
                run = subprocess.run(argv, cwd=work, env=env, capture_output=True, text=True, timeout=600)
                if run.returncode != 0:
                    failures.append(f"{where}: `{command}` exited with {run.returncode}:\n{run.stdout}{run.stderr}")
                    continue
                problem = check_output(where, command, run.stdout + run.stderr, shown)
                if problem:
                    failures.append(problem)
    if not commands:
        failures.append(f"{md}: no console block ran a command")
    example = md.resolve().parents[1] / "examples" / "irish_sea.geo"
    if md.name == "tutorial.md" and example.exists():
        mine, theirs = code_lines(script_lines), code_lines(example.read_text().splitlines())
        if mine != theirs:
            where = next((i for i, (a, b) in enumerate(zip(mine, theirs)) if a != b), min(len(mine), len(theirs)))
            failures.append(f"{example} is not the tutorial's geo blocks: first difference at code line {where + 1}:\n"
                            f"    tutorial: {mine[where] if where < len(mine) else '(end)'}\n"
                            f"    example:  {theirs[where] if where < len(theirs) else '(end)'}")
    for f in failures:
        print(f, file=sys.stderr)
    print(f"tutorial: {commands} commands, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
