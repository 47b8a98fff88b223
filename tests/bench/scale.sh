#!/usr/bin/env bash
# The scale benchmark (tests/bench/run.sh --scale): the whole full-resolution GSHHG
# (9.5 million points, read from Debian's gmt-gshhg-full: Coastline = GSHHG, Resolution
# "f") through examples/world_ocean.geo at
# gamma = coast size = 30 km, 10 km and 3 km, next to the default example (GSHHG
# intermediate, 30 km) in the same run. Prints a Markdown report on standard output:
#   - the import alone (bench_coast_scale: read, then each step of the import, with the
#     peak memory after each), from the system's binned file;
#   - the whole run (stereomesh -2 -nt THREADS): wall and CPU seconds, peak memory,
#     triangles, bytes of peak memory per triangle, triangles per wall second.
#   tests/bench/run.sh --scale [BUILD_DIR] [THREADS] > docs/benchmarks_scale.md   (THREADS default 1)
# Takes a few minutes (the 3 km mesh alone about 1.5 minutes of CPU); needs /usr/bin/time.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
threads="${2:-1}"
for p in stereomesh tests/bench/bench_coast_scale; do
  [[ -x "$build/$p" ]] || { echo "scale.sh: $build/$p is not built" >&2; exit 2; }
done
[[ -x /usr/bin/time ]] || { echo "scale.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
full=/usr/share/gmt-gshhg/binned_GSHHS_f.nc
[[ -f $full ]] || { echo "scale.sh: $full is missing (apt-get install gmt-gshhg-full)" >&2; exit 2; }
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-scale.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

echo "# Scale: the full GSHHG through examples/world_ocean.geo"
echo
echo "Written by \`tests/bench/run.sh --scale\` on $(date -u '+%Y-%m-%d %H:%M UTC') from commit"
echo "$(git -C "$root" rev-parse --short HEAD): $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'),"
echo "load average $(cut -d' ' -f1-3 /proc/loadavg) at the start; $threads thread(s)."
echo
echo "## The import alone (constant gamma, bench_coast_scale)"
for g in 30000 10000 3000; do
  for f in "$full"; do
    echo "run.sh --scale: import of $(basename "$f") at $g m" >&2
    echo
    echo '```'
    "$build/tests/bench/bench_coast_scale" "$f" "$g" "$threads" 2>&1 | sed "s|$build/||"
    echo '```'
  done
done
echo
echo "## The whole run (stereomesh -2, front2d)"
echo
echo "| case | triangles | wall s | CPU s | peak MB | bytes / triangle | triangles / s |"
echo "|---|---:|---:|---:|---:|---:|---:|"
run_case() {  # title, extra arguments...
  local title="$1"; shift
  echo "run.sh --scale: $title" >&2
  if ! (cd "$tmp" && /usr/bin/time -f "%e %U %S %M" -o "$tmp/time.txt" "$build/stereomesh" -2 -nt "$threads" \
        -v 1 "$root/examples/world_ocean.geo" "$@" -o "$tmp/m.msh" --stats "$tmp/s.json" > /dev/null 2> "$tmp/err"); then
    echo "| $title | failed: $(tail -1 "$tmp/err") | | | | | |"
    return
  fi
  python3 - "$tmp/s.json" "$tmp/time.txt" "$title" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
wall, user, sys_s, kb = (float(x) for x in open(sys.argv[2]).read().split()[-4:])
t = s["triangles"]
print(f"| {sys.argv[3]} | {t:,} | {wall:.1f} | {user + sys_s:.1f} | {kb / 1024:.0f} | "
      f"{kb * 1024 / t:,.0f} | {t / wall:,.0f} |")
PY
  rm -f "$tmp/m.msh"
}
run_case "default example (GSHHG intermediate, 30 km)"
for km in 30 10 3; do
  m=$((km * 1000))
  run_case "full GSHHG, gamma = coast size = $km km" -setstring CoastResolution f -setnumber CoastMinArea 0 \
    -setnumber CoastAccuracy "$m" -setnumber ShoreSizeMin "$m"
done
