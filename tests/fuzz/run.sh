#!/usr/bin/env bash
# Fuzz the .geo front end (and evaluator), or one file reader, for a fixed time.
#
#   tests/fuzz/run.sh [--target T] SECONDS                 build fuzz_T with clang in its own build
#                                                          dir ($SM_FUZZ_BUILD_DIR, default build-fuzz/)
#                                                          and run it
#   tests/fuzz/run.sh --no-build [--target T] SECONDS BIN  run an already built fuzz_T (CTest fuzz_short_geo,
#                                                          fuzz_short_<reader>)
#
# T is geo (the default), a reader: gshhs, lonlat_text, loops2, shapefile, netcdf, esri,
# gshhg_binned, or floor (the quality floor on random coasts, tests/fuzz/fuzz_floor_entry.cpp).
# The seed corpus (geo: tests/fuzz/corpus, tests/fuzz/crashes, tests/scripts, examples; a
# reader: tests/fuzz/corpus_T, tests/fuzz/crashes_T) is copied to a
# scratch directory, so the repository is never modified. Set SM_FUZZ_CORPUS=DIR to keep the
# grown corpus in DIR between runs. Exit status: 0 no crash; 1 the fuzzer
# found a crash, leak, timeout or invariant violation (the input is saved under
# $SM_FUZZ_ARTIFACTS, default <build dir>/fuzz-artifacts/: add it to tests/fuzz/crashes/ (a
# reader's: crashes_T/) with the fix); 2 usage or build error.
#
# Environment: SM_FUZZ_RUNS (stop after this many executions; with SM_FUZZ_SEED the run is the
# same every time, as the CTest tests fuzz_short_T use it), SM_FUZZ_SEED, SM_FUZZ_BUILD_DIR (build dir), SM_FUZZ_JOBS (build jobs, default 2), SM_FUZZ_CORPUS
# (keep the grown corpus there), SM_FUZZ_ARTIFACTS (where crashing inputs go), SM_FUZZ_PARSER_ONLY=1
# (fuzz lexer+parser only: builds sm_lang alone instead of the interpreter and the whole kernel).
set -euo pipefail

usage() { echo "usage: $0 [--target T] SECONDS | $0 --no-build [--target T] SECONDS FUZZ_BINARY" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"

build=1
target=geo
if [[ "${1:-}" == "--no-build" ]]; then build=0; shift; fi
if [[ "${1:-}" == "--target" ]]; then target="${2:-}"; shift 2 || usage; fi
case "$target" in
  geo|gshhs|lonlat_text|loops2|shapefile|netcdf|esri|gshhg_binned|floor) ;;
  *) usage ;;
esac
[[ $# -ge 1 && "$1" =~ ^[0-9]+$ ]] || usage
seconds="$1"

if [[ $build == 1 ]]; then
  [[ $# -eq 1 ]] || usage
  bdir="${SM_FUZZ_BUILD_DIR:-$root/build-fuzz}"
  command -v clang++ >/dev/null || { echo "run.sh: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "$root" -B "$bdir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSTEREOMESH_FUZZ=ON \
        -DSTEREOMESH_FUZZ_PARSER_ONLY="$([[ -n "${SM_FUZZ_PARSER_ONLY:-}" ]] && echo ON || echo OFF)" >/dev/null || exit 2
  cmake --build "$bdir" --target "fuzz_$target" -j "${SM_FUZZ_JOBS:-2}" || exit 2
  bin="$bdir/tests/fuzz/fuzz_$target"
else
  [[ $# -eq 2 ]] || usage
  bin="$2"
  bdir="$(pwd)"
fi
[[ -x "$bin" ]] || { echo "run.sh: no fuzz binary at $bin" >&2; exit 2; }

scratch="$(mktemp -d "${TMPDIR:-/tmp}/sm-fuzz.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/corpus" "$scratch/work"
corpus="$scratch/corpus"
if [[ -n "${SM_FUZZ_CORPUS:-}" ]]; then mkdir -p "$SM_FUZZ_CORPUS"; corpus="$SM_FUZZ_CORPUS"; fi
seed_dirs=("$here/corpus" "$here/crashes" "$root/tests/scripts" "$root/examples")
fuzz_opts=(-max_len=8192 -dict="$here/geo.dict")
if [[ "$target" != geo ]]; then
  seed_dirs=("$here/corpus_$target" "$here/crashes_$target")
  fuzz_opts=(-max_len=16384)
  # a netCDF-4 (HDF5) seed of the binned GSHHG layout takes 16.7 kB
  [[ "$target" == gshhg_binned ]] && fuzz_opts=(-max_len=32768)
fi
# shapelib and libnetcdf (not instrumented) keep allocations on some error paths of
# hostile files, and libnetcdf asks calloc for the sizes a hostile header claims: the
# leak checker would blame us, and ASan would abort where the real calloc returns NULL
# (which libnetcdf reports as an error). Crashes and overflows are still caught.
case "$target" in
  shapefile|netcdf|gshhg_binned)
    fuzz_opts+=(-detect_leaks=0)
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0:allocator_may_return_null=1" ;;
esac
for d in "${seed_dirs[@]}"; do
  [[ -d "$d" ]] || continue
  find "$d" -type f ! -name 'README*' ! -name '*.sh' ! -name '*.py' -size -64k -print0 |
    while IFS= read -r -d '' f; do cp "$f" "$corpus/seed-$(echo "$f" | md5sum | cut -c1-16)"; done
done
artifacts="${SM_FUZZ_ARTIFACTS:-$bdir/fuzz-artifacts}"
mkdir -p "$artifacts"

extra=()
[[ -n "${SM_FUZZ_RUNS:-}" ]] && extra+=(-runs="$SM_FUZZ_RUNS")
[[ -n "${SM_FUZZ_SEED:-}" ]] && extra+=(-seed="$SM_FUZZ_SEED")
echo "run.sh: fuzzing for ${seconds}s${SM_FUZZ_RUNS:+ or $SM_FUZZ_RUNS runs} with $(ls "$corpus" | wc -l) inputs; artifacts in $artifacts"
# Evaluated scripts may write files (Printf > f, Save): run inside the scratch dir.
set +e
(cd "$scratch/work" && "$bin" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2560 "${fuzz_opts[@]}" \
   -artifact_prefix="$artifacts/" -print_final_stats=1 "${extra[@]}" "$corpus")
status=$?
set -e
if [[ $status -ne 0 ]]; then
  echo "run.sh: fuzz_$target failed (status $status); reproduce with: $bin <file from $artifacts>" >&2
  exit 1
fi
echo "run.sh: no crash"
