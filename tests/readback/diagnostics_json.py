"""--diagnostics FILE read back with Python's json: one object a line, every diagnostic of
the run, and its counts equal to those the grouped stderr prints (per kind in the header,
per sort in the "N x what [kind]" lines), whatever the verbosity. Needs only the standard
library, so it never skips."""
import collections
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "diagnostics_world_c.geo")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(stereomesh, out, *extra):
    r = subprocess.run([stereomesh, "-0", SCRIPT, "--diagnostics", out, *extra], capture_output=True, text=True)
    check(r.returncode == 0, f"stereomesh {' '.join(extra)} ran")
    return r.stderr


def main(stereomesh):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "d.jsonl")
        err = run(stereomesh, out)
        with open(out, encoding="utf-8") as f:
            every = [json.loads(line) for line in f]
        # The import's repairs, all warnings at the Coastline{} statement; the deviation
        # note stands at the Coastline's definition, on a line of its own.
        notes = [r for r in every if r["kind"] == "coastline-deviation"]
        check(len(notes) == 1 and notes[0]["severity"] == "note", "one coastline-deviation note")
        rows = [r for r in every if r["kind"] != "coastline-deviation"]
        check(len(rows) > 20, f"{len(rows)} diagnostics written")
        check(all({"file", "line", "col", "severity", "kind", "message"} <= r.keys() for r in rows),
              "every line has file, line, col, severity, kind, message")
        placed = [r for r in rows if "what" in r]
        check(placed and all(isinstance(r["lon"], (int, float)) and -180 <= r["lon"] <= 180 and -90 <= r["lat"] <= 90
                             for r in placed), "every repair has its lon/lat")
        check(len({(r["file"], r["line"], r["col"]) for r in rows}) == 1, "all at the Coastline{} statement")

        header = re.search(r": warning: (\d+) warnings from this statement: (.*)\n", err)
        check(header is not None, "one grouped header on stderr")
        if header:
            check(int(header.group(1)) == len(rows), f"the header counts {header.group(1)}, the file has {len(rows)}")
            printed = {k: int(n) for n, k in re.findall(r"(\d+) \[([a-z-]+)\]", header.group(2))}
            counted = dict(collections.Counter(r["kind"] for r in rows))
            check(printed == counted, f"counts per kind {printed} == {counted}")
        sorts = {(w, k): int(n) for n, w, k in re.findall(r"^  (\d+) x (.*) \[([a-z-]+)\]$", err, re.M)}
        counted = dict(collections.Counter((r["what"], r["kind"]) for r in placed))
        check(sorts == counted, f"counts per sort equal ({len(sorts)} sorts)")
        check(err.count("loops[] = Coastline{1};") == 1, "the source line is printed once")
        check("not listed: -v 6 lists every one" in err, "the cut group says how to see all")

        # -v 6 lists every one; -v 1 prints no warning; the file is the same either way.
        all_err = run(stereomesh, out, "-v", "6")
        shown = len(re.findall(r"^      lon ", all_err, re.M))
        check(shown == len(placed), f"-v 6 lists all {len(placed)} places ({shown})")
        check("not listed" not in all_err, "-v 6 cuts nothing")
        with open(out, encoding="utf-8") as f:
            check([json.loads(line) for line in f] == every, "the file is the same at -v 6")
        quiet = run(stereomesh, out, "-v", "1")
        check("warning" not in quiet, "-v 1 prints no warning")
        with open(out, encoding="utf-8") as f:
            check(sum(1 for _ in f) == len(every), "the file still has every diagnostic at -v 1")
        check(sorted(os.listdir(tmp)) == ["d.jsonl"], "no temporary file left beside it")
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)


main(sys.argv[1])
