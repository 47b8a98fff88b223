#!/usr/bin/env bash
# The scale benchmark (tests/bench/run.sh --scale): the whole full-resolution GSHHG
# (9.5 million points, read from Debian's gmt-gshhg-full) through examples/world_ocean.geo
# with every default on, next to the default example (GSHHG intermediate, 30 km) in the
# same run. It measures and writes the raw figures to docs/bench/scale.json; then
# tests/bench/scale_docs.py writes from that one file docs/benchmarks_scale.md, the cost
# table of docs/scaling.md, the World Ocean table of README.md and the examples' table of
# docs/examples.md, so that no figure in
# them is typed by hand (the test `bench_docs_current` fails when one is edited).
#
#   tests/bench/run.sh --scale [BUILD_DIR]
#
# The cases (stereomesh -2 -nt 1, each timed by /usr/bin/time, its --stats JSON kept with
# the run's own wall and CPU account by stage):
#   default    the default example as the README's first command runs it
#   full30     the full GSHHG, the example's gamma = coast size = 30 km
#   full30open the same with CloseNarrowWater 0 (what passage closing costs)
#   full10     gamma = coast size = 10 km
#   full3      gamma = coast size = 3 km
#   full3nt2   the 3 km case with -nt 2: its wall time against full3's, and the same bytes
#   full1      the ten-million-triangle case (tests/bench/tenmillion.sh's): gamma 3 km, a 1 km
#              coast (ShoreSizeMin), the shore ramp to 80 km (ShoreSizeMax): 9.2 M triangles
#   full1nt2   the same with -nt 2
#   example_X  each other example (examples/X.geo) as it comes: docs/examples.md's table
# and the import alone (bench_coast_scale: each step with its peak memory) at 30, 10 and
# 3 km. About 8 minutes of CPU and 1.1 GB of memory on this project's machine.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
for p in stereomesh tests/bench/bench_coast_scale; do
  [[ -x "$build/$p" ]] || { echo "scale.sh: $build/$p is not built" >&2; exit 2; }
done
[[ -x /usr/bin/time ]] || { echo "scale.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
full=/usr/share/gmt-gshhg/binned_GSHHS_f.nc
[[ -f $full ]] || { echo "scale.sh: $full is missing (apt-get install gmt-gshhg-full)" >&2; exit 2; }
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-scale.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/runs"

{
  echo "commit $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src || echo ' (with uncommitted changes in src/)')"
  echo "date $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "cores $(nproc)"
  echo "cpu $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo "load_start $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$tmp/machine.txt"

for g in 30000 10000 3000; do
  echo "scale.sh: the import alone at $g m" >&2
  "$build/tests/bench/bench_coast_scale" "$full" "$g" 1 2>&1 | sed "s|$build/||" > "$tmp/import_$g.txt"
done

full_args=(-setstring CoastResolution f -setnumber CoastMinArea 0)
run_case() {  # id threads script arguments...
  local id="$1" threads="$2" script="$3" rc=0
  shift 3
  echo "scale.sh: $id" >&2
  echo "$id" >> "$tmp/runs/order"
  printf '%s\n' "$@" > "$tmp/runs/$id.args"
  (cd "$tmp" && /usr/bin/time -f "%e %U %S %M" -o "$tmp/runs/$id.time" "$build/stereomesh" -2 -nt "$threads" \
     "$root/examples/$script.geo" "$@" -o "$tmp/runs/$id.msh" --stats "$tmp/runs/$id.json" \
     > /dev/null 2> "$tmp/runs/$id.log") || rc=$?
  echo "$rc" > "$tmp/runs/$id.rc"
  echo "$threads" > "$tmp/runs/$id.threads"
  [[ -f "$tmp/runs/$id.msh" ]] && sha256sum "$tmp/runs/$id.msh" | cut -d' ' -f1 > "$tmp/runs/$id.sha256"
  rm -f "$tmp/runs/$id.msh"
}
run_case default 1 world_ocean
run_case full30 1 world_ocean "${full_args[@]}"
run_case full30open 1 world_ocean "${full_args[@]}" -setnumber CloseNarrowWater 0
run_case full10 1 world_ocean "${full_args[@]}" -setnumber CoastAccuracy 10000 -setnumber ShoreSizeMin 10000
run_case full3 1 world_ocean "${full_args[@]}" -setnumber CoastAccuracy 3000 -setnumber ShoreSizeMin 3000
run_case full3nt2 2 world_ocean "${full_args[@]}" -setnumber CoastAccuracy 3000 -setnumber ShoreSizeMin 3000
ten_million=(-setnumber CoastAccuracy 3000 -setnumber ShoreSizeMin 1000 -setnumber ShoreSizeMax 80e3)
run_case full1 1 world_ocean "${full_args[@]}" "${ten_million[@]}"
run_case full1nt2 2 world_ocean "${full_args[@]}" "${ten_million[@]}"
# The other examples as `stereomesh -2 examples/X.geo` runs them: docs/examples.md's table.
for example in gb_ireland arctic great_barrier_reef north_sea_scheldt gulf_of_mexico irish_sea mediterranean; do
  run_case "example_$example" 1 "$example"
done
echo "load_end $(cut -d' ' -f1-3 /proc/loadavg)" >> "$tmp/machine.txt"

mkdir -p "$root/docs/bench"
python3 "$here/scale_collect.py" "$tmp" "$root" > "$tmp/scale.json"
mv "$tmp/scale.json" "$root/docs/bench/scale.json"
echo "scale.sh: wrote docs/bench/scale.json" >&2
