#!/usr/bin/env python3
"""Runs Gmsh's own tutorials and 2D benchmarks through gmsh and stereomesh and writes the
compatibility report (docs/gmsh-compatibility.md).

Usage:
  tests/gmsh_scripts/report.py GMSH_SOURCE_TREE --gmsh PATH --stereomesh PATH
                               [--timeout SECONDS] [--out FILE] [--only NAME...]

GMSH_SOURCE_TREE is an unpacked Gmsh source tree (4.8.4: tutorial/, benchmarks/). Its scripts
are copied to a scratch directory first, because gmsh -0 writes a .geo_unrolled file next to
each script. Each script runs under a time limit (--timeout, per run):
  1. `gmsh -0` and `stereomesh -0`: Printf output (gmsh's stdout without its Info/Warning
     lines) compared line for line; a script evaluates when stereomesh exits with 0.
  2. `gmsh -2` and `stereomesh -2` to MSH 4.1 ASCII, read back here: physical groups,
     1D element counts, triangle counts and triangle quality (rho = 2 inradius /
     circumradius, Gmsh's "gamma"), and the wall time of each run.
Python 3 standard library only; the project's own tests never run this (they must not depend
on Gmsh's files).
"""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

# The scripts of the report: the tutorials, the 2D benchmarks and the ocean scripts elsewhere.
SCRIPT_GLOBS = ["tutorial/*.geo", "benchmarks/2d/*.geo", "benchmarks/statreport/ocean.geo",
                "benchmarks/2d_large/*.geo"]


# Why a script's element count is not within 15% of gmsh's, where we know: what Gmsh 4.8.4
# does (read in its source tree) and why ours differs. Written under the figures; a script
# far from gmsh's count and missing here is listed as not yet explained.
COUNT_NOTES = {
    "square.geo":
        "a tie that Gmsh's rounding breaks. Its front2d sizes a triangle by the mean of its "
        "nodes' shortest edges, written 0.3333333333 * (sum): the two triangles of the 10 x 10 "
        "square (circumradius 7.07) get size 9.999999999, so R/h passes 1/sqrt 2 by 1e-10 and "
        "Gmsh adds the centre (4 triangles). Ours computes R/h = 1/sqrt 2 exactly and keeps the "
        "2 triangles; any rectangle not square gets its centre in both.",
    "Square-Attr3.geo":
        "Gmsh's front2d all but misses the Box field (size 0.01 in [0.2, 0.6]^2, 0.1 outside): "
        "82 triangles in the box, where its own del2d puts 3,523 (3,800 in all; meshadapt "
        "5,092) and our front2d 3,365 (3,644 in all). It sizes a triangle by the field at its "
        "nodes only, and they start on the boundary, outside the box: a triangle over the box "
        "is resolved unless one of its nodes falls inside. Ours takes the field at a "
        "triangle's circumcentre. Deliberate.",
    "compound_with_physicals.geo":
        "Gmsh meshes each compound chain as one discrete curve of its own, whose nodes pass over "
        "the chain's inner points: the bottom and top chains (25 long, lc 20) get 2 edges each, 8 "
        "boundary nodes, 6 triangles. Ours keeps every mesh edge on the curve it lies on "
        "(src/mesh/compound_curve.h), so the inner points 2, 3, 6 and 7 stay nodes: 3 edges per "
        "chain, 10 boundary nodes, 14 triangles. Deliberate; without the `Compound Curve` lines "
        "both mesh 8 line elements, gmsh 12 triangles, ours 10.",
    "coin.geo":
        "Gmsh's front2d is the outlier among its own algorithms at this graded re-entrant corner "
        "(point size 1e-6, Mesh.SmoothRatio 21.5): 3,798 triangles, rho min 0.00, 10 below 0.3, "
        "where its del2d makes 9,478 and meshadapt 15,488 (ours: front2d 6,384, rho min 0.79; "
        "del2d 7,714; meshadapt 9,714). Beyond 0.1 from the corner the counts agree within 7% "
        "(1,903 and 2,035); below 1e-4, then from 1e-4 to 1e-3, 1e-3 to 1e-2 and 1e-2 to 0.1, "
        "Gmsh's front2d has 181, 334, 511 and 869 triangles against our 631, 1,309, 1,158 and "
        "1,251: it leaves the corner coarser than its boundary edges. Not followed.",
    "Square-Attr2.geo":
        "the difference is Gmsh's front2d's: its del2d makes 13,306 triangles, ours 13,330 "
        "(del2d) and 12,868 (front2d). Where: triangles whose centroid lies 0.02 to 0.03 from "
        "the Distance curves (the fine zone's edge, h = 0.005, the Threshold ramp starting at "
        "0.03 with slope 3.2) are 2,030 of mean area 0.78 h^2 in Gmsh's front2d against 3,013 "
        "of 0.57 h^2 in ours; in the zone's core (below 0.02) 7,988 of 0.45 h^2 against 8,605 "
        "of 0.42 h^2. Gmsh's front2d takes the field at a triangle's nodes (their mean), ours "
        "at its circumcentre (each then the smaller of that and the boundary sizes extended "
        "to its nodes). Not followed.",
    "wing.geo":
        "not explained yet. Same 1D mesh (569 edges); gmsh's front2d makes 23,753 triangles and "
        "its del2d 14,131, ours 17,559 (front2d) and 17,079 (del2d). The difference lies between "
        "0.1 and 10 from the wing (sizes growing from lc 0.02-0.03 to the box's 20, extended "
        "from the boundary): 20,264 triangles in Gmsh's front2d, 14,078 in ours, 10,479 in its "
        "del2d. Taking Gmsh's boundary node size (the node's shortest edge of the initial "
        "triangulation, at least half of its curve edges) for ours (the mean of its curve "
        "edges) moves ours only to 17,699.",
    "naca12_2d.geo":
        "Gmsh's 1D mesher measures the anisotropic background (MinAniso of a Box and a "
        "BoundaryLayer field) along each curve's tangent, where the BoundaryLayer metric's size "
        "is the tangential one; ours has isotropic fields only and gives the airfoil curves the "
        "wall size: 2,534 line elements against 180, and so the triangles and layers "
        "(docs/fields.md, \"MinAniso and anisotropic inputs\"). Known loss, not fixed here.",
}


def run(cmd, cwd, timeout):
    """(returncode or None on timeout, stdout, stderr, seconds)."""
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.monotonic() - start
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        return None, out, "", time.monotonic() - start


def gmsh_printf(stdout):
    return [l for l in stdout.splitlines() if not l.startswith(("Info    :", "Warning :", "Error   :"))]


def gmsh_errors(stdout, stderr):
    return [l for l in (stdout + "\n" + stderr).splitlines() if l.startswith("Error   :")]


def our_errors(stderr):
    return [l for l in stderr.splitlines() if ": error: " in l]


def read_msh41(path):
    """Physical groups {(dim, tag)}, element counts by type, triangle rho (min, mean), node count."""
    with open(path, errors="replace") as f:
        lines = f.read().splitlines()
    i = 0
    physicals, counts, nodes, triangles = set(), {}, {}, []
    while i < len(lines):
        head = lines[i]
        i += 1
        if head == "$Entities":
            n = [int(x) for x in lines[i].split()]
            i += 1
            for dim in range(4):
                for _ in range(n[dim]):
                    w = lines[i].split()
                    i += 1
                    k = 4 if dim == 0 else 7   # tag, x, y, z | tag, box (6)
                    for t in w[k + 1:k + 1 + int(w[k])]:
                        physicals.add((dim, abs(int(t))))
        elif head == "$Nodes":
            blocks = int(lines[i].split()[0])
            i += 1
            for _ in range(blocks):
                count = int(lines[i].split()[3])
                i += 1
                tags = [int(lines[i + k]) for k in range(count)]
                i += count
                for k in range(count):
                    nodes[tags[k]] = tuple(float(x) for x in lines[i + k].split()[:3])
                i += count
        elif head == "$Elements":
            blocks = int(lines[i].split()[0])
            i += 1
            for _ in range(blocks):
                _, _, etype, count = (int(x) for x in lines[i].split())
                i += 1
                counts[etype] = counts.get(etype, 0) + count
                if etype == 2:
                    triangles += [[int(x) for x in lines[i + k].split()[1:4]] for k in range(count)]
                i += count
    rhos = [rho(nodes[a], nodes[b], nodes[c]) for a, b, c in triangles]
    quality = (min(rhos), sum(rhos) / len(rhos)) if rhos else None
    return physicals, counts, quality, len(nodes)


def rho(a, b, c):
    la, lb, lc = math.dist(b, c), math.dist(c, a), math.dist(a, b)
    s = (la + lb + lc) / 2
    area2 = max(s * (s - la) * (s - lb) * (s - lc), 0.0)
    if la * lb * lc == 0:
        return 0.0
    # 2 r / R with r = A / s and R = la lb lc / (4 A).
    return 8 * area2 / (s * la * lb * lc)


def mesh(cmd, cwd, out, timeout):
    rc, stdout, stderr, secs = run(cmd, cwd, timeout)
    if rc is None:
        return {"status": f"timeout ({timeout:.0f} s)", "secs": secs}
    if rc != 0 or not os.path.exists(out):
        errs = gmsh_errors(stdout, stderr) or our_errors(stderr)
        return {"status": "error", "why": errs[0] if errs else f"exit {rc}", "secs": secs}
    physicals, counts, quality, nodes = read_msh41(out)
    os.remove(out)
    return {"status": "ok", "secs": secs, "physicals": physicals, "lines": counts.get(1, 0),
            "triangles": counts.get(2, 0), "quads": counts.get(3, 0), "nodes": nodes, "quality": quality}


def short(text, n=110):
    text = " ".join(text.split())
    text = text.replace("|", "\\|")
    return text if len(text) <= n else text[:n - 3] + "..."


def out_of_scope(text):
    """Why a script lies outside the project's scope (2D meshing with the built-in geometry
    kernel, no post-processing views), or None: a statement, not a comment, that selects the
    OpenCASCADE kernel, that reads a view (.pos) or sizes a mesh by one, or that merges an STL
    triangulation. Gmsh merges an STL file (tutorial t13) to remesh a surface in 3D: its
    triangles are a discrete surface that ClassifySurfaces splits along sharp edges into
    patches, each of which CreateGeometry reparametrises (a map of a curved patch onto the
    plane) so that it can be remeshed, and a volume is then meshed inside; stereomesh meshes
    planar and spherical 2D models, and stops at such a Merge with an error saying so."""
    code = [line.split("//", 1)[0] for line in text.splitlines()]
    if any('SetFactory("OpenCASCADE")' in line for line in code):
        return "OpenCASCADE"
    if any(".pos\"" in line or "Background Mesh View" in line for line in code):
        return "post-processing views"
    if any(re.search(r'\bMerge\s*"[^"]*\.stl"', line, re.IGNORECASE) for line in code):
        return "3D remeshing of an STL surface"
    return None


def element_count(m):
    return m["triangles"] + m.get("quads", 0)


def report_one(path, gmsh, sm, timeout):
    cwd, name = os.path.dirname(path), os.path.basename(path)
    r = {}
    grc, gout, gerr, gsecs = run([gmsh, "-0", name], cwd, timeout)
    src, sout, serr, ssecs = run([sm, "-0", name], cwd, timeout)
    r["gmsh_eval_errors"] = gmsh_errors(gout, gerr) if grc is not None else ["timeout"]
    if src is None:
        r["eval"] = f"timeout ({timeout:.0f} s)"
    elif src != 0:
        errs = our_errors(serr)
        r["eval"] = "error"
        r["why"] = errs[0].split(": error: ", 1)[-1] if errs else f"exit {src}"
    else:
        same = grc is not None and gmsh_printf(gout) == sout.splitlines()
        r["eval"] = "agrees" if same else "differs"
        r["printf_lines"] = len(sout.splitlines())
    with open(path, errors="replace") as f:
        text = f.read()
    r["structured"] = "Transfinite" in text
    r["out_of_scope"] = out_of_scope(text)
    if r["eval"] in ("agrees", "differs"):
        out = os.path.join(cwd, "report_out.msh")
        r["gmsh2"] = mesh([gmsh, "-2", name, "-format", "msh41", "-o", out], cwd, out, timeout)
        r["sm2"] = mesh([sm, "-2", name, "-format", "msh41", "-o", out], cwd, out, timeout)
    return r


def cell_mesh(m):
    if m["status"] != "ok":
        return m["status"]
    q = m["quality"]
    quads = f" + {m['quads']} quads" if m.get("quads") else ""
    return f"{m['lines']} / {m['triangles']}{quads}" + (f" / {q[0]:.2f}, {q[1]:.3f}" if q else "") + \
        f" / {m['secs']:.1f} s"


def write_markdown(results, out, timeout, build_dir=None):
    n = len(results)
    evaluated = sum(r["eval"] in ("agrees", "differs") for _, r in results)
    agree = sum(r["eval"] == "agrees" for _, r in results)
    tried = [r for _, r in results if "sm2" in r]
    meshed = sum(r["sm2"]["status"] == "ok" and r["sm2"]["triangles"] > 0 for r in tried)
    gmsh_meshed = sum(r["gmsh2"]["status"] == "ok" and r["gmsh2"]["triangles"] > 0 for r in tried)
    both = [r for r in tried if r["sm2"]["status"] == "ok" and r["gmsh2"]["status"] == "ok"
            and r["sm2"]["triangles"] > 0 and r["gmsh2"]["triangles"] > 0]
    same_phys = sum(r["sm2"]["physicals"] == r["gmsh2"]["physicals"] for r in both)
    ratios = sorted(r["sm2"]["triangles"] / r["gmsh2"]["triangles"] for r in both)
    lines = [
        "# Gmsh's own scripts through stereomesh",
        "",
        "Generated by `tests/gmsh_scripts/report.py` (do not edit by hand). The command was",
        "`tests/gmsh_scripts/report.py GMSH_4.8.4_SOURCE --gmsh gmsh --stereomesh build/stereomesh "
        f"--timeout {timeout:.0f}`.",
        "It runs Gmsh 4.8.4's tutorials (`tutorial/*.geo`), its 2D benchmarks (`benchmarks/2d/*.geo`) and its",
        "ocean scripts (`benchmarks/statreport/ocean.geo`, `benchmarks/2d_large/*.geo`) through `gmsh` and",
        "`stereomesh`, unchanged. The project's own tests use small scripts of their own instead",
        "(`tests/scripts/`, with `gmsh -0` expectations).",
        "",
        f"- **{evaluated} of {n}** scripts evaluate (`-0` exits with 0). In **{agree}** of them the Printf output is",
        "  identical to gmsh's.",
        f"- **{meshed} of {len(tried)}** evaluated scripts mesh in 2D with triangles (gmsh: {gmsh_meshed}).",
        f"  Where both mesh, the physical groups written are the same in {same_phys} of {len(both)}.",
    ]
    if ratios:
        lines.append(f"  Our triangle count divided by gmsh's: median {ratios[len(ratios) // 2]:.2f}, "
                     f"range {ratios[0]:.2f} to {ratios[-1]:.2f}.")
    # The goals' figures: scripts in scope that evaluate, and meshes within 15% of gmsh's count.
    outside = [(os.path.basename(name), r["out_of_scope"]) for name, r in results if r.get("out_of_scope")]
    in_scope = [r for _, r in results if not r.get("out_of_scope")]
    in_eval = sum(r["eval"] in ("agrees", "differs") for r in in_scope)
    if in_scope:
        lines.append(f"- In the project's scope (2D, the built-in geometry kernel, no post-processing views, no "
                     f"STL surfaces to remesh in 3D): "
                     f"**{in_eval} of {len(in_scope)}** evaluate ({100 * in_eval / len(in_scope):.1f}%); out of "
                     "scope: " + (", ".join(f"{n} ({why})" for n, why in outside) or "none") + ".")
    # Every script both mesh with elements, quadrangle meshes included.
    meshed_both = [r for r in tried if r["sm2"]["status"] == "ok" and r["gmsh2"]["status"] == "ok"
                   and element_count(r["sm2"]) > 0 and element_count(r["gmsh2"]) > 0]
    close = [r for r in meshed_both if abs(element_count(r["sm2"]) / element_count(r["gmsh2"]) - 1) <= 0.15]
    both_ids, close_ids = {id(r) for r in meshed_both}, {id(r) for r in close}
    far = [os.path.basename(n) for n, r in results if id(r) in both_ids and id(r) not in close_ids]
    if meshed_both:
        lines.append(f"- Where both mesh (triangles or quadrangles), **{len(close)} of {len(meshed_both)}** "
                     f"({100 * len(close) / len(meshed_both):.1f}%) have an element count (triangles + quadrangles) "
                     "within 15% of gmsh's"
                     + (f" (not: {', '.join(far)})." if far else "."))
        for name in far:
            lines.append(f"  - {name}: " + COUNT_NOTES.get(name, "not explained yet."))
    # Scripts with Transfinite constraints: their grids are Gmsh's, so the counts must be equal.
    structured = [(name, r) for name, r in results if r.get("structured") and "sm2" in r
                  and r["sm2"]["status"] == "ok" and r["gmsh2"]["status"] == "ok"]
    if structured:
        keys = ("nodes", "lines", "triangles", "quads")
        equal = [os.path.basename(n) for n, r in structured if all(r["sm2"][k] == r["gmsh2"][k] for k in keys)]
        differ = [os.path.basename(n) for n, r in structured if os.path.basename(n) not in equal]
        lines.append(f"- **{len(equal)} of {len(structured)}** meshed scripts with `Transfinite` constraints have "
                     "gmsh's node, line, triangle and quadrangle counts exactly"
                     + (f" (not: {', '.join(differ)})." if differ else "."))
    # Why the others stop: the first error's kind (and, for 'not supported yet', the statement).
    reasons = {}
    for name, r in results:
        if r["eval"] != "error":
            continue
        why = r["why"]
        kind = why[why.rfind("[") + 1:-1] if why.endswith("]") else why
        if kind == "not-supported-yet" and why.startswith("'"):
            kind = f"not supported yet: {why[1:why.index(chr(39), 1)].split('(')[0].strip()}"
        reasons.setdefault(kind, []).append(os.path.basename(name))
    lines += ["", "Why the other scripts stop (the first error of `stereomesh -0`):", ""]
    for kind, names in sorted(reasons.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        lines.append(f"- {short(kind, 80)}: {len(names)} ({', '.join(names)})")
    lines += [
        "",
        "Mesh columns: 1D elements / triangles (+ quadrangles) / rho min, mean (2 inradius / circumradius) / wall time of",
        "that run (one run on a shared machine: noisy). A script with no triangles has no 2D physical",
        "group, or no surface. *eval* is `agrees` (same Printf lines), `differs`, or our first error.",
        "`gmsh -0 errors` counts the `Error` lines gmsh prints while it goes on.",
        "",
        "| script | eval | gmsh -0 errors | gmsh -2 | stereomesh -2 | same physicals |",
        "|---|---|---|---|---|---|",
    ]
    for name, r in results:
        ev = r["eval"] if r["eval"] != "error" else f"error: {short(r['why'])}"
        gerr = len(r["gmsh_eval_errors"])
        if "sm2" in r:
            g, s = r["gmsh2"], r["sm2"]
            gm = cell_mesh(g) if g["status"] != "error" else f"error: {short(g['why'], 60)}"
            sm = cell_mesh(s) if s["status"] != "error" else f"error: {short(s['why'].split(': error: ', 1)[-1], 80)}"
            phys = "yes" if g["status"] == s["status"] == "ok" and g["physicals"] == s["physicals"] else \
                ("no" if g["status"] == s["status"] == "ok" else "")
        else:
            gm = sm = phys = ""
        lines.append(f"| {name} | {ev} | {gerr or ''} | {gm} | {sm} | {phys} |")
    text = "\n".join(lines) + "\n"
    if build_dir:   # messages name the stdlib beside the binary: no machine path in the doc
        text = text.replace(build_dir, "BUILD")
    with open(out, "w") as f:
        f.write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("source", help="Gmsh source tree (tutorial/, benchmarks/)")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--stereomesh", required=True)
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per run (default 60)")
    ap.add_argument("--out", default="docs/gmsh-compatibility.md")
    ap.add_argument("--only", nargs="*", help="script paths relative to the source tree")
    a = ap.parse_args()
    sm = os.path.abspath(a.stereomesh)
    with tempfile.TemporaryDirectory() as tmp:
        scripts = []
        for pattern in SCRIPT_GLOBS:
            for p in sorted(glob.glob(os.path.join(a.source, pattern))):
                rel = os.path.relpath(p, a.source)
                if a.only and rel not in a.only:
                    continue
                scripts.append(rel)
        # Each directory once, with the files its scripts may Include or Merge (the mesh
        # files too: benchmarks/2d/hybrid_*.geo merge hybrid_part.msh; not the views).
        for d in sorted({os.path.dirname(s) for s in scripts}):
            shutil.copytree(os.path.join(a.source, d), os.path.join(tmp, d), dirs_exist_ok=True,
                            ignore=shutil.ignore_patterns("*.pos"))
        results = []
        for rel in scripts:
            r = report_one(os.path.join(tmp, rel), a.gmsh, sm, a.timeout)
            results.append((rel, r))
            print(f"{rel}: {r['eval']}" + (f" ({r['why'][:80]})" if "why" in r else "") +
                  (f", 2D gmsh {cell_mesh(r['gmsh2'])}, ours {cell_mesh(r['sm2'])}" if "sm2" in r else ""),
                  file=sys.stderr, flush=True)
    write_markdown(results, a.out, a.timeout, os.path.dirname(sm))
    return 0


if __name__ == "__main__":
    sys.exit(main())
