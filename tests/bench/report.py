#!/usr/bin/env python3
"""The side-by-side part of tests/bench/run.sh: one JSON record per program run in, a Markdown
table and an SVG bar chart of the Gmsh / stereomesh ratios out. Standard library only.

  report.py record RUNS.jsonl CASE ALGO PROG RC TIME_FILE STATS_JSON LOG   (appends one record)
  report.py table RUNS.jsonl                                             (Markdown to stdout)
  report.py plot RUNS.jsonl OUT.svg                                      (ratios per case)
"""
import json
import re
import statistics
import sys


def record(path, case, algo, prog, rc, time_file, stats_file, log_file):
    rec = {"case": case, "algo": algo, "prog": prog, "rc": int(rc)}
    # /usr/bin/time -f "%e %U %S %M": wall, user, system seconds and peak resident KB. The last
    # line: a program killed by a signal makes time print a note first.
    with open(time_file) as f:
        wall, user, system, kb = f.read().split("\n")[-2].split()
    rec.update(wall=float(wall), cpu=float(user) + float(system), peak_mb=int(kb) / 1024)
    try:
        with open(stats_file) as f:
            stats = json.load(f)
    except (OSError, ValueError):
        stats = {"error": "no statistics"}
    rec["stats"] = stats
    with open(log_file, errors="replace") as f:
        log = f.read()
    # Per-stage wall seconds from each program's own log.
    stages = {}
    for dim, wall_s in re.findall(r"Done meshing (\d)D \(Wall ([0-9.e+-]+)s", log):
        stages[dim + "D"] = float(wall_s)
    # Ours: the run's account, "Time: script 0.1 s, ..., 1D 2.0 s, 2D boundary 0.3 s, ...,
    # total 9.0 s"; the 1D and 2D meshing are its "1D" and "2D ..." stages (as Gmsh's
    # "Done meshing" times hold neither the field set-up nor the statistics).
    m = re.search(r"^Time: (.*), total [0-9.]+ s$", log, re.M)
    if m:
        parts = [re.fullmatch(r"(.+) ([0-9.]+) s", p.strip()) for p in m.group(1).split(",")]
        named = [(p.group(1), float(p.group(2))) for p in parts if p]
        stages["1D"] = sum(t for n, t in named if n == "1D")
        stages["2D"] = sum(t for n, t in named if n.startswith("2D"))
    rec["stages"] = stages
    if rec["rc"] != 0 or "error" in stats:
        rec["failure"] = (stats.get("error") or log.strip().split("\n")[-1])[:160]
    with open(path, "a") as f:
        f.write(json.dumps(rec) + "\n")


def load(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def pairs(runs):
    """(case, algo, ours, gmsh-or-None) in run order."""
    out, seen = [], {}
    for r in runs:
        key = (r["case"], r["algo"])
        if key not in seen:
            seen[key] = len(out)
            out.append([r["case"], r["algo"], None, None])
        out[seen[key]][2 if r["prog"] == "stereomesh" else 3] = r
    return out


def ok(r):
    return r is not None and "failure" not in r


def table(path):
    print("| case | algorithm | program | triangles | rho > 0.9 | min rho | wall s | CPU s | peak MB | 1D / 2D wall s |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for case, algo, ours, gmsh in pairs(load(path)):
        for prog, r in (("stereomesh", ours), ("Gmsh 4.8.4", gmsh)):
            if r is None:
                continue
            if not ok(r):
                print(f"| {case} | {algo} | {prog} | failed (exit {r['rc']}): {r['failure']} | | | "
                      f"{r['wall']:.2f} | {r['cpu']:.2f} | {r['peak_mb']:.0f} | |")
                continue
            s = r["stats"]
            wall, cpu, mem = f"{r['wall']:.2f}", f"{r['cpu']:.2f}", f"{r['peak_mb']:.0f}"
            if r is gmsh and ok(ours):
                wall += f" ({r['wall'] / ours['wall']:.1f}x)"
                cpu += f" ({r['cpu'] / ours['cpu']:.1f}x)"
                mem += f" ({r['peak_mb'] / ours['peak_mb']:.1f}x)"
            st = r["stages"]
            stages = f"{st['1D']:.2f} / {st['2D']:.2f}" if "1D" in st and "2D" in st else ""
            print(f"| {case} | {algo} | {prog} | {s['triangles']:,} | {100 * s['rho_gt_0.9']:.1f}% | "
                  f"{s['rho_min']:.3f} | {wall} | {cpu} | {mem} | {stages} |")
    done = [(o, g) for _, _, o, g in pairs(load(path)) if ok(o) and ok(g)]
    if done:
        print()
        parts = []
        for key, name in (("wall", "wall time"), ("cpu", "CPU time"), ("peak_mb", "peak memory")):
            r = sorted(g[key] / o[key] for o, g in done)
            parts.append(f"{name} {r[0]:.1f}-{r[-1]:.1f}x (median {statistics.median(r):.1f}x)")
        print(f"Gmsh / stereomesh over the {len(done)} cases both meshed: " + ", ".join(parts) + ".")


def plot(path, out):
    """Grouped horizontal bars from 1 on a log axis: Gmsh / stereomesh for wall time, CPU time and
    peak memory, one group per case; hand-written SVG (no plotting library needed)."""
    import math
    rows = [(f"{c}, {a}", [g[k] / o[k] for k in ("wall", "cpu", "peak_mb")])
            for c, a, o, g in pairs(load(path)) if ok(o) and ok(g)]
    series = [("wall time", "#1f77b4"), ("CPU time", "#ff7f0e"), ("peak memory", "#2ca02c")]
    left, right, top, bar, gap = 300, 30, 50, 9, 12
    width = 820
    lo = 0.5
    hi = max([2.0] + [v for _, vs in rows for v in vs]) * 1.3
    decades = [10 ** k for k in range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)]
    x0, x1 = math.log10(lo), math.log10(hi)
    def x(v):
        return left + (math.log10(max(v, lo)) - x0) / (x1 - x0) * (width - left - right)
    group = 3 * bar + gap
    height = top + len(rows) * group + 40
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           f'<text x="10" y="18" font-size="14" font-weight="bold">Gmsh 4.8.4 / stereomesh, one run '
           f'(above 1: stereomesh is faster or smaller)</text>']
    for k, (name, colour) in enumerate(series):
        svg.append(f'<rect x="{left + 140 * k}" y="28" width="12" height="10" fill="{colour}"/>'
                   f'<text x="{left + 140 * k + 16}" y="37">{name}</text>')
    bottom = top + len(rows) * group
    for d in decades + [2, 5, 20, 50, 200, 500]:
        if lo <= d <= hi:
            major = d in decades
            svg.append(f'<line x1="{x(d):.1f}" y1="{top - 4}" x2="{x(d):.1f}" y2="{bottom}" '
                       f'stroke="{"#999" if major else "#ddd"}" stroke-width="1"/>')
            svg.append(f'<text x="{x(d):.1f}" y="{bottom + 14}" text-anchor="middle" '
                       f'fill="{"#000" if major else "#777"}">{d:g}x</text>')
    for i, (label, values) in enumerate(rows):
        y = top + i * group
        svg.append(f'<text x="{left - 8}" y="{y + 1.5 * bar + 4}" text-anchor="end">{label}</text>')
        for k, v in enumerate(values):
            yy = y + k * bar
            svg.append(f'<rect x="{min(x(1), x(v)):.1f}" y="{yy}" width="{abs(x(v) - x(1)):.1f}" '
                       f'height="{bar - 1}" fill="{series[k][1]}"/>')
            svg.append(f'<text x="{x(v) + 3:.1f}" y="{yy + bar - 1.5}" font-size="9">{v:.1f}</text>')
    svg.append(f'<text x="{(left + width - right) / 2}" y="{height - 8}" text-anchor="middle">'
               f'ratio Gmsh / stereomesh (log scale)</text>')
    svg.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(svg) + "\n")


def main(argv):
    if len(argv) >= 10 and argv[1] == "record":
        record(*argv[2:10])
    elif len(argv) == 3 and argv[1] == "table":
        table(argv[2])
    elif len(argv) == 4 and argv[1] == "plot":
        plot(argv[2], argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
