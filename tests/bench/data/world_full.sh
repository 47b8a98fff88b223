#!/usr/bin/env bash
# The whole-globe GSHHG 2.3.7 full-resolution level-1 shoreline for tests/bench/run.sh --scale:
#   BUILD/data/world_full.txt  GMT lon/lat text, 9,717,736 points in 180,161 rings, 225 MB
#   BUILD/data/world_full.b    the same rings as a GSHHS 2.x binary (84 MB), what read_gshhs reads
# Never committed, never in the default test run. Installs Debian's gmt and gmt-gshhg-full
# when missing (apt-get, as root or through sudo), exports with
# ../shared/data/scripts/export_world_full.sh (about 2 minutes on 2 cores) and writes the
# binary with bench_coast_scale. Files already there are kept (--force redoes them).
#   tests/bench/data/world_full.sh [BUILD_DIR] [--force]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
force=0
build="$root/build"
for a in "$@"; do
  case "$a" in
    --force) force=1 ;;
    *) build="$a" ;;
  esac
done
build="$(cd "$build" && pwd)"
export_script="$root/../shared/data/scripts/export_world_full.sh"
[[ -f "$export_script" ]] || { echo "world_full.sh: $export_script is missing" >&2; exit 2; }
bench="$build/tests/bench/bench_coast_scale"
[[ -x "$bench" ]] || { echo "world_full.sh: $bench is not built" >&2; exit 2; }
out="$build/data"
mkdir -p "$out"

if ! command -v gmt > /dev/null || ! dpkg -s gmt-gshhg-full > /dev/null 2>&1; then
  echo "world_full.sh: installing gmt and gmt-gshhg-full" >&2
  sudo=()
  [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  "${sudo[@]}" apt-get install -y --no-install-recommends gmt gmt-gshhg-full python3 >&2
fi

if [[ $force -eq 1 || ! -s "$out/world_full.txt" ]]; then
  echo "world_full.sh: exporting the full GSHHG to $out/world_full.txt (about 2 minutes)" >&2
  sh "$export_script" "$out/world_full.txt.part"
  mv "$out/world_full.txt.part" "$out/world_full.txt"
fi
if [[ $force -eq 1 || ! -s "$out/world_full.b" || "$out/world_full.b" -ot "$out/world_full.txt" ]]; then
  echo "world_full.sh: writing $out/world_full.b" >&2
  "$bench" "$out/world_full.txt" - --write-gshhs "$out/world_full.b" >&2
fi
echo "$out/world_full.txt"
echo "$out/world_full.b"
