#!/usr/bin/env bash
# The side-by-side benchmark (issue 9): our figures next to Gmsh 4.8.4's from the same run,
# written to docs/benchmarks.md. Not part of the test suite: it takes a few minutes.
#
#   tests/bench/run.sh [BUILD_DIR]      (default: build; needs the bench_* programs built)
#
# What it runs:
#   - the unit square (bench_mesh_square): del2d and front2d at h = 0.002, meshadapt at
#     h = 0.005 (Gmsh's meshadapt takes ~250 s at 0.002), each next to `gmsh -2 -algo ...`;
#   - the world ocean (bench_mesh_world_ocean): GSHHG low coastlines at 30 km, shore distance
#     30-200 km within 500 km, del2d and front2d, next to `gmsh -2` on the same .geo;
#   - the paper's examples through the stereomesh command line: wall time, peak memory,
#     triangles and quality (the paper's figures beside them).
# Gmsh's columns are skipped with a note when gmsh is not installed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
out="$root/docs/benchmarks.md"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-bench.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
for p in bench_mesh_square bench_mesh_world_ocean; do
  [[ -x "$build/tests/bench/$p" ]] || { echo "run.sh: $build/tests/bench/$p is not built" >&2; exit 2; }
done
[[ -x "$build/stereomesh" ]] || { echo "run.sh: $build/stereomesh is not built" >&2; exit 2; }
timer=(/usr/bin/time -f "%e %M")
[[ -x /usr/bin/time ]] || { echo "run.sh: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
gmsh_note="Gmsh 4.8.4 ($(command -v gmsh || echo 'not installed: its columns are skipped'))"

section() {  # title, command...: runs the command in the scratch dir, output as a code block
  local title="$1"; shift
  echo "run.sh: $title" >&2
  {
    echo "### $title"
    echo
    echo '```'
    echo "\$ ${*##*/}"
    (cd "$tmp" && "$@" 2>&1) || echo "(exit status $?)"
    echo '```'
    echo
  } >> "$tmp/report.md"
}

: > "$tmp/report.md"
section "Unit square, h = 0.002: del2d" "$build/tests/bench/bench_mesh_square" 0.002 --algo del2d
section "Unit square, h = 0.002: front2d" "$build/tests/bench/bench_mesh_square" 0.002 --algo front2d
section "Unit square, h = 0.005: meshadapt" "$build/tests/bench/bench_mesh_square" 0.005 --algo meshadapt
section "World ocean, GSHHG low at 30 km, shore distance 30-200 km" \
  "$build/tests/bench/bench_mesh_world_ocean" world_l.txt 30 5,6 1

# The paper's examples through the command line.
examples_table() {
  echo "| example | triangles | rho > 0.9 | edges in [0.7, 1.4] | wall s | peak MB | paper |"
  echo "|---|---:|---:|---:|---:|---:|---|"
  local name paper
  while IFS='|' read -r name paper; do
    echo "run.sh: example $name" >&2
    if ! (cd "$tmp" && "${timer[@]}" -o "$tmp/time.txt" "$build/stereomesh" -2 -v 1 \
          "$root/examples/$name.geo" -setnumber EstimateStep 0 -o "$tmp/$name.msh" \
          --stats "$tmp/$name.json" > /dev/null 2> "$tmp/$name.err"); then
      echo "| \`$name.geo\` | failed: $(tail -1 "$tmp/$name.err") | | | | | $paper |"
      continue
    fi
    read -r wall kb < <(tail -1 "$tmp/time.txt")
    python3 - "$tmp/$name.json" "$name" "$wall" "$kb" "$paper" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"| `{sys.argv[2]}.geo` | {s['triangles']:,} | {100 * s['rho_share_above_0.9']:.1f}% | "
      f"{100 * s['length_ratio_share_0.7_1.4']:.1f}% | {float(sys.argv[3]):.2f} | "
      f"{int(sys.argv[4]) / 1024:.0f} | {sys.argv[5]} |")
PY
  done <<'LIST'
world_ocean|436,409 triangles, 35 s (2008 laptop)
gb_ireland|17,154-19,514 triangles; 93.2% / 88.1% / 84.5% rho > 0.9; 0.5-5.7 s
arctic|17,053 triangles
great_barrier_reef|20,384 elements
north_sea_scheldt|27,472 elements
LIST
}

{
  echo "# Benchmarks: stereomesh next to Gmsh"
  echo
  echo "Written by \`tests/bench/run.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'): $(nproc) cores,"
  echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), load average"
  echo "$(cut -d' ' -f1-3 /proc/loadavg) at the start; $gmsh_note. Every figure of a table comes"
  echo "from the same run; these machines are noisy, so compare ratios within a run rather than"
  echo "absolute times across runs. Quality rho = 2 r_in / r_circ, measured by our own code for"
  echo "both programs' meshes."
  echo
  echo "## The paper's examples (stereomesh -2, front2d, one thread)"
  echo
  examples_table
  echo
  echo "## Side by side with Gmsh"
  echo
  cat "$tmp/report.md"
} > "$tmp/benchmarks.md"
mv "$tmp/benchmarks.md" "$out"
echo "run.sh: wrote $out" >&2
