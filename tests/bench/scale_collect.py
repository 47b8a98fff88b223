#!/usr/bin/env python3
"""Gathers one scale run's raw figures (tests/bench/scale.sh's scratch folder) into one JSON
document on standard output: the machine and its load, the import-alone reports, and for each
case its command-line arguments, exit status (and first error), /usr/bin/time figures, --stats
JSON (triangles, quality, wall and CPU seconds by stage) and the mesh's sha256.

    scale_collect.py SCRATCH_DIR CHECKOUT_ROOT
Standard library only."""
import json
import os
import re
import sys


def read(path, default=""):
    try:
        with open(path, errors="replace") as f:
            return f.read()
    except OSError:
        return default


def first_error(log, root):
    """The run's first error line, the checkout's path left out so the doc names no machine."""
    lines = log.strip().splitlines()
    line = next((x for x in lines if " error: " in x), lines[-1] if lines else "no output")
    return line.replace(root.rstrip("/") + "/", "")[:240]


def main(tmp, root):
    machine = {}
    for line in read(os.path.join(tmp, "machine.txt")).splitlines():
        key, _, value = line.partition(" ")
        machine[key] = value
    imports = []
    for name in sorted(os.listdir(tmp)):
        m = re.fullmatch(r"import_(\d+)\.txt", name)
        if m:
            imports.append({"gamma": int(m.group(1)), "report": read(os.path.join(tmp, name)).rstrip()})
    imports.sort(key=lambda r: -r["gamma"])
    runs = []
    folder = os.path.join(tmp, "runs")
    # The cases in the order scale.sh ran them (it writes each id to `order`).
    for case in read(os.path.join(folder, "order")).split():
        base = os.path.join(folder, case)
        run = {"id": case, "args": read(base + ".args").split("\n")[:-1], "threads": int(read(base + ".threads", "1")),
               "exit": int(read(base + ".rc", "-1").strip() or -1)}
        times = read(base + ".time").split()
        if len(times) >= 4:
            wall, user, system, kib = (float(x) for x in times[-4:])
            run.update(wall=wall, cpu=user + system, peak_mib=kib / 1024)
        log = read(base + ".log")
        stats = read(base + ".json")
        if stats:
            run["stats"] = json.loads(stats)
        run["sha256"] = read(base + ".sha256").strip()
        if run["exit"] != 0:
            run["error"] = first_error(log, root)
        runs.append(run)
    json.dump({"machine": machine, "imports": imports, "runs": runs}, sys.stdout, indent=1, sort_keys=False)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
