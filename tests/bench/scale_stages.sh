#!/usr/bin/env bash
# Where the time of the full-resolution world ocean goes, stage by stage: the run's own
# account (the `Time:` line: the script's evaluation, the import, the field set-up by kind,
# 1D, 2D, the statistics, the writing) at gamma = 30, 10 and 3 km, next to the wall time
# /usr/bin/time measures, so that a stage nobody names shows as a gap. Markdown on stdout.
#
#   tests/bench/scale_stages.sh [BUILD_DIR]   (run.sh --scale calls it)
#
# The whole GSHHG at full resolution comes from the system (Debian gmt-gshhg-full). Each
# case: stereomesh -2 -nt SCALE_THREADS (default 1) examples/world_ocean.geo with
# CoastResolution "f", CoastAccuracy = ShoreSizeMin = gamma, ShoreSizeMax 100 km,
# ShoreDistMax 300 km. The 3 km case takes about 90 s of CPU and 1 GB.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
[[ -x "$build/stereomesh" ]] || { echo "scale_stages.sh: $build/stereomesh is not built" >&2; exit 2; }
[[ -f /usr/share/gmt-gshhg/binned_GSHHS_f.nc ]] ||
  { echo "scale_stages.sh: the full GSHHG is missing (apt-get install gmt-gshhg-full)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "scale_stages.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-scale.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

for gamma in ${SCALE_GAMMAS:-30e3 10e3 3e3}; do
  echo "scale_stages.sh: gamma $gamma" >&2
  rc=0
  (cd "$tmp" && /usr/bin/time -f "%e %U %M" -o "$tmp/$gamma.time" "$build/stereomesh" -2 -nt "${SCALE_THREADS:-1}" \
     "$root/examples/world_ocean.geo" -setstring CoastResolution f -setnumber CoastMinArea 0 -setnumber CoastAccuracy "$gamma" \
     -setnumber ShoreSizeMin "$gamma" -setnumber ShoreSizeMax 100e3 -setnumber ShoreDistMax 300e3 \
     -o "$tmp/w.msh" > "$tmp/$gamma.log" 2>&1) || rc=$?
  echo "$gamma $rc" >> "$tmp/cases"
  rm -f "$tmp/w.msh"
done

python3 - "$tmp" <<'PY'
import re, sys
tmp = sys.argv[1]
cases = [line.split() for line in open(f"{tmp}/cases")]
cols = ["script", "import", "fields", "1D", "2D", "statistics", "writing"]
print("| gamma | control points | triangles | wall s | " + " | ".join(cols) +
      " | stages sum | sum / wall | script + fields | statistics + writing |")
print("|---" * (len(cols) + 8) + "|")
details = []
for gamma, rc in cases:
    log = open(f"{tmp}/{gamma}.log", errors="replace").read()
    wall, user, kb = open(f"{tmp}/{gamma}.time").read().split()[-3:]
    wall = float(wall)
    m = re.search(r"^Time: (.*), total ([0-9.]+) s$", log, re.M)
    pts = re.search(r"(\d+) control points", log)
    tri = re.search(r"^Mesh: \d+ nodes, (\d+) triangles", log, re.M)
    if rc != "0" or not m:
        print(f"| {float(gamma) / 1e3:g} km | failed (exit {rc}): {log.strip().splitlines()[-1][:100]} |")
        continue
    named = []
    for part in m.group(1).split(","):
        p = re.fullmatch(r"(.+) ([0-9.]+) s", part.strip())
        if p: named.append((p.group(1), float(p.group(2))))
    def total(pred): return sum(t for n, t in named if pred(n))
    col = {"script": total(lambda n: n == "script"), "import": total(lambda n: n == "import"),
           "fields": total(lambda n: n == "fields" or n.startswith("field ")),
           "1D": total(lambda n: n == "1D"), "2D": total(lambda n: n.startswith("2D")),
           "statistics": total(lambda n: n == "statistics"), "writing": total(lambda n: n == "writing")}
    s = sum(t for _, t in named)
    before = col["script"] + col["fields"]
    after = col["statistics"] + col["writing"]
    print(f"| {float(gamma) / 1e3:g} km | {pts.group(1) if pts else '?'} | {tri.group(1) if tri else '?'} | "
          f"{wall:.2f} | " + " | ".join(f"{col[c]:.2f}" for c in cols) +
          f" | {s:.2f} | {100 * s / wall:.1f}% | {100 * before / wall:.1f}% | {100 * after / wall:.1f}% |")
    details.append(f"{float(gamma) / 1e3:g} km: Time: {m.group(1)}, total {m.group(2)} s "
                   f"(wall {wall:.2f} s, user {float(user):.2f} s, peak {int(kb) // 1024} MiB)")
print()
print("The `Time:` lines:")
print()
print("```")
print("\n".join(details))
print("```")
PY
