#!/usr/bin/env bash
# The ten-million-triangle benchmark (opt-in, not part of the test suite: about 10 minutes
# of CPU and 2 GB of memory): the whole full-resolution GSHHG through
# examples/world_ocean.geo with every default on (passage closing, channel width, the
# quality floor), meshed once with -nt 1 and once with -nt 2: 9.2 million triangles. The
# coast size (ShoreSizeMin) is 1 km and the shore ramp reaches 80 km (ShoreSizeMax) at
# 500 km from the coast; the coastline is imported at gamma = CoastAccuracy = 3 km, as in
# the 3 km scale case (at gamma = 1 km the import's passage closing alone takes minutes:
# docs/scaling.md, "Ten million triangles on this machine"). It writes one JSON document: the machine and its load,
# and per run the triangles, CPU (user + system) and wall seconds, the peak resident memory
# (/usr/bin/time), the per-triangle figures against the goals (25 µs of CPU and 200 bytes of
# peak a triangle), the run's --stats account by stage, and the mesh's sha256 (the same for
# both thread counts, or the document says not). docs/benchmarks_scale.md ("Ten million
# triangles") has a run's figures.
#
#   tests/bench/tenmillion.sh [BUILD_DIR] [OUT_JSON]   (defaults: build, tenmillion.json)
#
# Environment: TENMILLION_GAMMA (CoastAccuracy, metres, default 3000), TENMILLION_COAST
# (ShoreSizeMin, default 1000), TENMILLION_RAMP (ShoreSizeMax, default 80000) for another
# case, TENMILLION_THREADS (default "1 2") for other thread counts.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
out="${2:-tenmillion.json}"
gamma="${TENMILLION_GAMMA:-3000}"
coast="${TENMILLION_COAST:-1000}"
ramp="${TENMILLION_RAMP:-80000}"
threads_list="${TENMILLION_THREADS:-1 2}"
[[ -x "$build/stereomesh" ]] || { echo "tenmillion.sh: $build/stereomesh is not built" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "tenmillion.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
full=/usr/share/gmt-gshhg/binned_GSHHS_f.nc
[[ -f $full ]] || { echo "tenmillion.sh: $full is missing (apt-get install gmt-gshhg-full)" >&2; exit 2; }
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-tenmillion.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

commit="$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src || echo ' (with uncommitted changes in src/)')"
{
  echo "commit $commit"
  echo "date $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "cores $(nproc)"
  echo "cpu $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo "gamma $gamma"
  echo "coast_size $coast"
  echo "ramp_size $ramp"
  echo "load_start $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$tmp/machine.txt"

args=(-setstring CoastResolution f -setnumber CoastMinArea 0 -setnumber CoastAccuracy "$gamma"
      -setnumber ShoreSizeMin "$coast" -setnumber ShoreSizeMax "$ramp")
for nt in $threads_list; do
  echo "tenmillion.sh: -nt $nt (load $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  rc=0
  (cd "$tmp" && /usr/bin/time -f "%e %U %S %M" -o "$tmp/nt$nt.time" "$build/stereomesh" -2 -nt "$nt" \
     "$root/examples/world_ocean.geo" "${args[@]}" -o "$tmp/nt$nt.msh" --stats "$tmp/nt$nt.json" \
     > /dev/null 2> "$tmp/nt$nt.log") || rc=$?
  echo "$rc" > "$tmp/nt$nt.rc"
  echo "load_after_nt$nt $(cut -d' ' -f1-3 /proc/loadavg)" >> "$tmp/machine.txt"
  [[ -f "$tmp/nt$nt.msh" ]] && sha256sum "$tmp/nt$nt.msh" | cut -d' ' -f1 > "$tmp/nt$nt.sha256"
  rm -f "$tmp/nt$nt.msh"
done

/usr/bin/python3 - "$tmp" "$threads_list" "${args[*]}" > "$tmp/out.json" <<'PY'
import json, os, sys
tmp, threads, args = sys.argv[1], [int(x) for x in sys.argv[2].split()], sys.argv[3].split()
def read(name, default=""):
    try:
        with open(os.path.join(tmp, name), errors="replace") as f:
            return f.read()
    except OSError:
        return default
machine = dict(line.partition(" ")[::2] for line in read("machine.txt").splitlines())
runs = []
for nt in threads:
    run = {"threads": nt, "exit": int(read(f"nt{nt}.rc", "-1").strip() or -1), "sha256": read(f"nt{nt}.sha256").strip()}
    times = read(f"nt{nt}.time").split()
    if len(times) >= 4:
        wall, user, system, kib = (float(x) for x in times[-4:])
        run.update(wall_s=wall, cpu_s=user + system, peak_mib=kib / 1024)
    stats = read(f"nt{nt}.json")
    if stats:
        s = json.loads(stats)
        run["triangles"] = s.get("triangles")
        run["stats"] = s
        if run["triangles"] and "cpu_s" in run:
            run["cpu_us_per_triangle"] = 1e6 * run["cpu_s"] / run["triangles"]
            run["peak_bytes_per_triangle"] = run["peak_mib"] * 1024 * 1024 / run["triangles"]
    if run["exit"] != 0:
        lines = read(f"nt{nt}.log").strip().splitlines()
        run["error"] = next((x for x in lines if " error: " in x), lines[-1] if lines else "no output")[:240]
    runs.append(run)
doc = {"machine": machine, "args": args, "runs": runs,
       "goals": {"cpu_us_per_triangle": 25, "peak_bytes_per_triangle": 200, "speedup_nt2": 1.7}}
by = {r["threads"]: r for r in runs}
if 1 in by and 2 in by and "wall_s" in by[1] and "wall_s" in by[2]:
    doc["speedup_nt2"] = by[1]["wall_s"] / by[2]["wall_s"]
hashes = {r["sha256"] for r in runs if r["exit"] == 0}
doc["same_bytes"] = len(hashes) == 1 and all(r["exit"] == 0 for r in runs)
json.dump(doc, sys.stdout, indent=1)
print()
PY
mv "$tmp/out.json" "$out"
echo "tenmillion.sh: wrote $out" >&2
