#!/usr/bin/env python3
"""Writes the scale figures into the docs from one measured run (docs/bench/scale.json, made by
tests/bench/scale.sh): all of docs/benchmarks_scale.md, and the marked blocks of docs/scaling.md,
README.md and docs/examples.md. With --check it writes nothing and exits 1 when a doc differs from what the JSON
gives (the test `bench_docs_current`), so a figure typed by hand, or a run not written out, is
caught. Standard library only.

    tests/bench/scale_docs.py --write|--check [ROOT]
"""
import json
import os
import sys

TITLES = {
    "default": "default example (GSHHG intermediate, 30 km)",
    "full30": "full GSHHG, 30 km",
    "full30open": "full GSHHG, 30 km, `CloseNarrowWater 0`",
    "full10": "full GSHHG, 10 km",
    "full3": "full GSHHG, 3 km",
    "full3nt2": "full GSHHG, 3 km, `-nt 2`",
    "full1": "full GSHHG, 1 km coast (gamma 3 km, ramp to 80 km)",
    "full1nt2": "full GSHHG, 1 km coast, `-nt 2`",
}
# The examples' table of docs/examples.md: run id, script, what it meshes, the paper's figures.
EXAMPLES = [
    ("default", "world_ocean", "Figs. 9-10", "436,409 triangles, 35 s"),
    ("example_gb_ireland", "gb_ireland", "Fig. 8, 15 km",
     "18,698 / 19,514 / 17,154; 93.2% / 88.1% / 84.5% rho > 0.9; 0.7 / 0.5 / 5.7 s"),
    ("example_arctic", "arctic", "Fig. 11", "17,053 triangles"),
    ("example_great_barrier_reef", "great_barrier_reef", "Fig. 14", "20,384 elements"),
    ("example_north_sea_scheldt", "north_sea_scheldt", "Fig. 13", "27,472 elements"),
    ("example_gulf_of_mexico", "gulf_of_mexico", "regional", "-"),
    ("example_irish_sea", "irish_sea", "regional", "-"),
    ("example_mediterranean", "mediterranean", "regional", "-"),
]
STAGES = ["script", "import", "fields", "1D", "2D", "statistics", "writing"]
BEGIN = "<!-- written by tests/bench/scale_docs.py from docs/bench/scale.json: {} -->"
END = "<!-- end of {} -->"


def fmt_int(x):
    return f"{int(round(x)):,}"


class Run:
    def __init__(self, raw):
        self.raw = raw
        self.id = raw["id"]
        self.ok = raw.get("exit") == 0 and "stats" in raw
        self.stats = raw.get("stats", {})
        self.triangles = self.stats.get("triangles", 0)
        self.cpu = raw.get("cpu", 0.0)
        self.wall = raw.get("wall", 0.0)
        self.peak = raw.get("peak_mib", 0.0)

    def stage_cpu(self, name):
        stages = self.stats.get("stages_cpu", {})
        if name == "fields":
            return sum(v for k, v in stages.items() if k == "fields" or k.startswith("field "))
        return stages.get(name, 0.0)

    def us_per_triangle(self, seconds):
        return 1e6 * seconds / self.triangles if self.triangles else 0.0

    def bytes_per_triangle(self):
        return self.peak * 1024 * 1024 / self.triangles if self.triangles else 0.0


def load(root):
    with open(os.path.join(root, "docs", "bench", "scale.json")) as f:
        data = json.load(f)
    runs = {r["id"]: Run(r) for r in data["runs"]}
    return data, runs


def header(data):
    m = data["machine"]
    return (f"measured by `tests/bench/run.sh --scale` on {m.get('date', '?')} from commit {m.get('commit', '?')}: "
            f"{m.get('cores', '?')} cores ({m.get('cpu', '?')}), load average {m.get('load_start', '?')} at the start "
            f"and {m.get('load_end', '?')} at the end")


def benchmarks_scale(data, runs):
    out = ["# Scale: the full GSHHG through examples/world_ocean.geo", ""]
    out += [f"Written by `tests/bench/scale_docs.py` from docs/bench/scale.json, {header(data)}. Do not edit by "
            "hand: run `tests/bench/run.sh --scale` (about eight minutes of CPU). Each case is "
            "`stereomesh -2 examples/world_ocean.geo` (`-nt 1` unless the case says `-nt 2`) with the example's defaults (passage closing, channel "
            "width, the quality floor, the coast within gamma / 2), the full cases reading Debian's "
            "`/usr/share/gmt-gshhg/binned_GSHHS_f.nc` (`-setstring CoastResolution f -setnumber CoastMinArea 0`, "
            "gamma = coast size = `CoastAccuracy` = `ShoreSizeMin`). CPU is user + system time of the whole "
            "process and peak its maximum resident set (`/usr/bin/time`); the machine is shared, so wall times "
            "lean on the load and CPU times are the figures to compare. Measurements by hand at older commits, "
            "kept for what each change bought, are in docs/benchmarks_history.md.", ""]
    base = runs.get("default")
    out += ["## The whole run", "",
            "| case | triangles | CPU s | wall s | peak MiB | CPU / default | peak / default "
            "| CPU µs / triangle | bytes / triangle |",
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for case in TITLES:
        r = runs.get(case)
        if r is None:
            continue
        if not r.ok:
            out.append(f"| {TITLES[case]} | failed (exit {r.raw.get('exit')}): `{r.raw.get('error', '')}` "
                       "| | | | | | | |")
            continue
        rel_cpu = f"{r.cpu / base.cpu:.1f}" if base and base.ok and base.cpu else "-"
        rel_peak = f"{r.peak / base.peak:.1f}" if base and base.ok and base.peak else "-"
        out.append(f"| {TITLES[case]} | {fmt_int(r.triangles)} | "
                   f"{r.cpu:.1f} | {r.wall:.1f} | {r.peak:.0f} | {rel_cpu} | {rel_peak} | "
                   f"{r.us_per_triangle(r.cpu):.1f} | {r.bytes_per_triangle():.0f} |")
    out += ["", "## Where the CPU goes", "",
            "The run's own account of CPU seconds by stage (`--stats`: `stages_cpu`, every thread's time charged "
            "to the stage that was open), and each stage's share of the process's CPU.", "",
            "| case | " + " | ".join(STAGES) + " | import share | 1D share | 2D µs / triangle |",
            "|---|" + "---:|" * (len(STAGES) + 3)]
    for case in TITLES:
        r = runs.get(case)
        if r is None or not r.ok:
            continue
        cells = [f"{r.stage_cpu(s):.2f}" for s in STAGES]
        share = lambda s: f"{100 * r.stage_cpu(s) / r.cpu:.0f}%" if r.cpu else "-"
        out.append(f"| {TITLES[case]} | " + " | ".join(cells) +
                   f" | {share('import')} | {share('1D')} | {r.us_per_triangle(r.stage_cpu('2D')):.1f} |")
    out += ["", "## Against the goals", "",
            "| goal | measured | met |", "|---|---|---|"]
    for goal, measured, met in goals(runs):
        out.append(f"| {goal} | {measured} | {'yes' if met else 'no'} |")
    out += ["", "## The wall-time account", "",
            "Each run's `Time:` account by stage (wall seconds; the 2D mesher's own stages split out).", "", "```"]
    for case in TITLES:
        r = runs.get(case)
        if r is None or not r.ok:
            continue
        stages = r.stats.get("stages", {})
        line = ", ".join(f"{k} {v:.2f} s" for k, v in stages.items())
        out.append(f"{case}: {line}")
    out += ["```", "", "## The import alone (constant gamma, `bench_coast_scale`)", "",
            "Each step of the import of the whole file with the process's peak memory after it.", ""]
    for rep in data["imports"]:
        out += [f"gamma = {rep['gamma'] / 1000:g} km:", "", "```", rep["report"], "```", ""]
    return "\n".join(out).rstrip() + "\n"


def goals(runs):
    """(goal, measured, met) for the scale goals the runs can measure."""
    out = []
    d, f30, f30o, f3, f3t = (runs.get(k) for k in ("default", "full30", "full30open", "full3", "full3nt2"))
    ok = lambda *rs: all(r is not None and r.ok for r in rs)
    for r in (f30, f3):
        if r is not None and not r.ok:
            out.append((f"{TITLES[r.id]} with every default on meshes", f"failed: `{r.raw.get('error', '')}`", False))
    if ok(f30, f30o):
        x = f30.cpu / f30o.cpu
        out.append(("passage closing on the full GSHHG at 30 km: CPU at most 1.3x that of `CloseNarrowWater 0`",
                    f"{x:.2f}x ({f30.cpu:.1f} s against {f30o.cpu:.1f} s)", x <= 1.3))
    if ok(d, f3):
        x = f3.cpu / d.cpu
        out.append(("the full world at 3 km, every default on: CPU at most 6x the default example's",
                    f"{x:.1f}x ({f3.cpu:.1f} s against {d.cpu:.1f} s)", x <= 6))
        out.append(("the same: peak memory at most 600 MB", f"{f3.peak * 1.048576:.0f} MB ({f3.peak:.0f} MiB)",
                    f3.peak * 1.048576 <= 600))
        for stage, bound in (("import", 15), ("1D", 10)):
            share = 100 * f3.stage_cpu(stage) / f3.cpu
            out.append((f"the same: the {stage} at most {bound}% of the run's CPU", f"{share:.0f}%", share <= bound))
        us = f3.us_per_triangle(f3.cpu)
        out.append(("whole-run CPU at most 25 µs per triangle (the goal is set for ten million triangles; "
                    "this is the 3 km case)", f"{us:.1f} µs", us <= 25))
        b = f3.bytes_per_triangle()
        out.append(("peak memory at most 200 bytes per triangle (the same)", f"{b:.0f} bytes", b <= 200))
    if ok(f3, f3t):
        x = f3.wall / f3t.wall
        out.append(("`-nt 2` at least 1.7x faster in wall time than `-nt 1` (when two cores are free: see the load "
                    "above)", f"{x:.2f}x ({f3.wall:.1f} s against {f3t.wall:.1f} s)", x >= 1.7))
        same = bool(f3.raw.get("sha256")) and f3.raw.get("sha256") == f3t.raw.get("sha256")
        out.append(("the same bytes for every thread count (the 3 km mesh at -nt 1 and -nt 2)",
                    "identical" if same else "different", same))
    out += ten_million_goals(runs.get("full1"), runs.get("full1nt2"))
    return out


def ten_million_goals(one, two):
    """(goal, measured, met) for the ten-million-triangle case (the 1 km coast) at -nt 1 and -nt 2."""
    if one is None:
        return []
    if not one.ok:
        return [(f"{TITLES[one.id]} meshes", f"failed: `{one.raw.get('error', '')}`", False)]
    us, b = one.us_per_triangle(one.cpu), one.bytes_per_triangle()
    out = [(f"ten million triangles ({fmt_int(one.triangles)} here): whole-run CPU at most 25 µs per triangle",
            f"{us:.1f} µs", us <= 25),
           ("the same: peak memory at most 200 bytes per triangle", f"{b:.0f} bytes", b <= 200)]
    if two is not None and two.ok:
        x = one.wall / two.wall
        out.append(("the same: `-nt 2` at least 1.7x faster in wall time than `-nt 1` (when two cores are free: "
                    "see the load above)", f"{x:.2f}x ({one.wall:.1f} s against {two.wall:.1f} s)", x >= 1.7))
        same = bool(one.raw.get("sha256")) and one.raw.get("sha256") == two.raw.get("sha256")
        out.append(("the same bytes at -nt 1 and -nt 2 (the ten-million mesh)", "identical" if same else "different",
                    same))
    return out


def scaling_costs(data, runs):
    d, f30, f3 = runs.get("default"), runs.get("full30"), runs.get("full3")
    if not (d and d.ok and f3 and f3.ok):
        return "The scale run did not finish: no costs to give.\n"
    two_d = (d.us_per_triangle(d.stage_cpu("2D")), f3.us_per_triangle(f3.stage_cpu("2D")))
    lo, hi = min(two_d), max(two_d)
    edges = f3.stats.get("edges", 0)
    rows = [
        ("2D meshing, front2d, per triangle (size field included)",
         f"{two_d[0]:.1f} µs (default example: {d.stage_cpu('2D'):.2f} s for {fmt_int(d.triangles)}); "
         f"{two_d[1]:.1f} µs at 3 km ({f3.stage_cpu('2D'):.2f} s for {fmt_int(f3.triangles)})"),
        ("one part (131,072 triangles, the part size of `partition.cpp`)",
         f"{0.131072 * lo:.2f}-{0.131072 * hi:.2f} s at those rates"),
        ("1D of the coast", f"{f3.stage_cpu('1D'):.2f} s at 3 km ({f3.us_per_triangle(f3.stage_cpu('1D')):.1f} µs "
                            "per triangle of the mesh)"),
        ("the import of the full GSHHG (9.5 M points), whole run's import stage",
         (f"{f30.stage_cpu('import'):.2f} s at 30 km; " if f30 and f30.ok else "") +
         f"{f3.stage_cpu('import'):.2f} s at 3 km"),
        ("the script's own evaluation", f"{f3.stage_cpu('script'):.2f} s at 3 km"),
        ("the statistics", f"{1e6 * f3.stage_cpu('statistics') / edges:.2f} µs per edge" if edges else "-"),
        ("writing MSH 4.1 text", f"{f3.us_per_triangle(f3.stage_cpu('writing')):.2f} µs per triangle at 3 km"),
        ("memory, whole run", f"{d.bytes_per_triangle():.0f} bytes per triangle (default example), "
                              f"{f3.bytes_per_triangle():.0f} at 3 km"),
    ]
    mem = sorted((d.bytes_per_triangle(), f3.bytes_per_triangle()))
    out = [f"CPU seconds of one thread by stage, {header(data)} (docs/benchmarks_scale.md).", "",
           "| what | figure |", "|---|---|"]
    out += [f"| {a} | {b} |" for a, b in rows]
    out += ["", f"At these rates, 10^9 triangles are about {fmt_int(1e3 * lo)}-{fmt_int(1e3 * hi)} core-seconds of "
                f"2D work and about {mem[0]:.0f}-{mem[1]:.0f} GB of memory in all. No machine of this project holds "
                f"that; 256 ranks would, at about {4 * mem[0] / 1e3:.1f}-{4 * mem[1] / 1e3:.1f} GB each "
                "(4 M triangles, about 30 parts a rank)."]
    return "\n".join(out) + "\n"


def scaling_estimate(data, runs):
    d, f3 = runs.get("default"), runs.get("full3")
    if not (d and d.ok and f3 and f3.ok):
        return "The scale run did not finish: no estimate to give.\n"
    rates = sorted((d.us_per_triangle(d.stage_cpu("2D")), f3.us_per_triangle(f3.stage_cpu("2D"))))
    start = f3.stage_cpu("script") + f3.stage_cpu("import") + f3.stage_cpu("fields")
    coarse64 = 244e3 * rates[1] / 1e6
    coarse8 = 4e6 / 64 * rates[1] / 1e6
    two_d = (4 * rates[0], 4 * rates[1])
    writing = 4 * f3.us_per_triangle(f3.stage_cpu("writing"))
    one_d = f3.stage_cpu("1D")
    lo = start + coarse64 + coarse8 + two_d[0] + writing
    hi = start + coarse64 + coarse8 + two_d[1] + writing + one_d
    out = ["With 256 ranks, about 4 M triangles each, at the rates above:",
           f"- script, import and field set-up: {start:.1f} s (the 3 km case's);",
           f"- coarse passes: {coarse64:.1f} s + {coarse8:.1f} s (244 k and 62 k triangles at the 2D rate);",
           f"- 1D: at most the 3 km case's {one_d:.1f} s, spread over the ranks;",
           f"- 2D: {two_d[0]:.0f}-{two_d[1]:.0f} s (4 M x {rates[0]:.1f}-{rates[1]:.1f} µs);",
           "- seams: two exchanges and a band of smoothing (not measured);",
           f"- writing: {writing:.1f} s.", "",
           f"About {lo:.0f}-{hi:.0f} s wall, of which 2D is the share that scales with ranks. The serial start "
           f"(script, import, fields, the 64 h pass) is about {start + coarse64:.1f} s on every rank, so beyond "
           "about 1,000 ranks it, not the meshing, would set the time."]
    return "\n".join(out) + "\n"


def readme_table(data, runs):
    d = runs.get("default")
    if not (d and d.ok):
        return "The scale run's default example failed: no figures.\n"
    s = d.stats
    out = [f"The World Ocean {header(data)}, one thread (docs/benchmarks_scale.md), next to the paper:", "",
           "| World Ocean (`examples/world_ocean.geo`) | triangles | rho min | rho > 0.9 | edges within [0.7, 1.4] of "
           "the size | whole run |",
           "|---|---:|---:|---:|---:|---:|",
           f"| stereomesh (front2d, default: channels resolved, narrow dead ends filled, quality floor 0.3, coast "
           f"within gamma / 2 of the data) | {fmt_int(d.triangles)} | {s.get('rho_min', 0):.2f} | "
           f"{100 * s.get('rho_share_above_0.9', 0):.1f}% | {100 * s.get('length_ratio_share_0.7_1.4', 0):.1f}% | "
           f"{d.cpu:.1f} s CPU ({d.peak:.0f} MiB peak) |",
           "| paper (Gmsh, 2008 laptop) | 436,409 | - | - | - | 35 s |"]
    return "\n".join(out) + "\n"


def examples_table(data, runs):
    out = [f"`stereomesh -2 -nt 1 examples/X.geo` with every default, {header(data)}. Time is the whole run's CPU "
           "(user + sys), peak memory its maximum resident set.", "",
           "| example | paper | triangles | rho min | rho > 0.9 | in range | CPU | peak memory | paper's mesh |",
           "|---|---|---:|---:|---:|---:|---:|---:|---|"]
    for run_id, script, figure, paper in EXAMPLES:
        r = runs.get(run_id)
        if r is None:
            out.append(f"| `{script}.geo` | {figure} | not measured in this run | | | | | | {paper} |")
            continue
        if not r.ok:
            out.append(f"| `{script}.geo` | {figure} | failed (exit {r.raw.get('exit')}): `{r.raw.get('error', '')}` "
                       f"| | | | | | {paper} |")
            continue
        s = r.stats
        out.append(f"| `{script}.geo` | {figure} | {fmt_int(r.triangles)} | {s.get('rho_min', 0):.2f} | "
                   f"{100 * s.get('rho_share_above_0.9', 0):.1f}% | {100 * s.get('length_ratio_share_0.7_1.4', 0):.1f}% | "
                   f"{r.cpu:.2f} s | {r.peak:.0f} MiB | {paper} |")
    return "\n".join(out) + "\n"


def replace_block(text, name, body, path):
    begin, end = BEGIN.format(name), END.format(name)
    i, j = text.find(begin), text.find(end)
    if i < 0 or j < i:
        raise SystemExit(f"scale_docs.py: {path} has no block '{name}' (the lines {begin} ... {end})")
    return text[:i + len(begin)] + "\n" + body + text[j:]


def main(argv):
    if len(argv) < 2 or argv[1] not in ("--write", "--check"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    root = argv[2] if len(argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    data, runs = load(root)
    wanted = {os.path.join("docs", "benchmarks_scale.md"): lambda old: benchmarks_scale(data, runs)}
    blocks = {os.path.join("docs", "scaling.md"): [("costs", scaling_costs), ("estimate", scaling_estimate)],
              "README.md": [("world ocean", readme_table)],
              os.path.join("docs", "examples.md"): [("examples", examples_table)]}
    for path, items in blocks.items():
        def render(old, items=items, path=path):
            for name, fn in items:
                old = replace_block(old, name, fn(data, runs), path)
            return old
        wanted[path] = render
    stale = []
    for path, render in wanted.items():
        full = os.path.join(root, path)
        old = open(full).read() if os.path.exists(full) else ""
        new = render(old)
        if new != old:
            stale.append(path)
            if argv[1] == "--write":
                with open(full + ".tmp", "w") as f:
                    f.write(new)
                os.replace(full + ".tmp", full)
    if argv[1] == "--check" and stale:
        print("scale_docs.py: these differ from what docs/bench/scale.json gives (edited by hand, or a run not "
              "written out; run tests/bench/scale_docs.py --write): " + ", ".join(stale), file=sys.stderr)
        return 1
    if argv[1] == "--write":
        print("scale_docs.py: " + (", ".join(stale) + " written" if stale else "the docs were current"),
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
