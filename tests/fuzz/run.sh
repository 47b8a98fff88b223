#!/usr/bin/env bash
# Runs a libFuzzer target of the fuzz build for a fixed time (or a fixed number of runs).
#
#   tests/fuzz/run.sh SECONDS [NAME]          configure and build fuzz_NAME (default geo) with clang
#                                             in its own build dir ($SM_FUZZ_BUILD_DIR, default
#                                             build-fuzz/) and run it on its seed corpus
#   tests/fuzz/run.sh --no-build SECONDS BIN [--dict FILE] [--max-len BYTES] [--corpus DIR]...
#                                             run an already built target (the fuzz build's CTest
#                                             tests fuzz_short_NAME do this)
#
# The corpus directories (for geo by default tests/fuzz/corpus, tests/fuzz/crashes, tests/scripts
# and examples) are copied to a scratch directory, so the repository is never modified. Set
# SM_FUZZ_CORPUS=DIR to keep the grown corpus in DIR between runs. Exit status: 0 no crash; 1 the
# fuzzer found a crash, leak, timeout or invariant violation (the input is saved under
# $SM_FUZZ_ARTIFACTS, default <build dir>/fuzz-artifacts/: add it to the target's crashes
# directory with the fix); 2 usage or build error.
#
# Environment: SM_FUZZ_RUNS (stop after this many executions; with SM_FUZZ_SEED the run is the
# same every time), SM_FUZZ_SEED, SM_FUZZ_BUILD_DIR, SM_FUZZ_JOBS (build jobs, default 2),
# SM_FUZZ_CORPUS, SM_FUZZ_ARTIFACTS, SM_FUZZ_PARSER_ONLY=1 (geo: lexer+parser only).
set -euo pipefail

usage() { echo "usage: $0 SECONDS [NAME] | $0 --no-build SECONDS FUZZ_BINARY [--dict FILE] [--max-len BYTES] [--corpus DIR]..." >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"

build=1
if [[ "${1:-}" == "--no-build" ]]; then build=0; shift; fi
[[ $# -ge 1 && "$1" =~ ^[0-9]+$ ]] || usage
seconds="$1"
shift

dict=""
max_len=8192
corpora=()
if [[ $build == 1 ]]; then
  [[ $# -le 1 ]] || usage
  name="${1:-geo}"
  bdir="${SM_FUZZ_BUILD_DIR:-$root/build-fuzz}"
  command -v clang++ >/dev/null || { echo "run.sh: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
  cmake -S "$root" -B "$bdir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSTEREOMESH_FUZZ=ON \
        -DSTEREOMESH_FUZZ_PARSER_ONLY="$([[ -n "${SM_FUZZ_PARSER_ONLY:-}" ]] && echo ON || echo OFF)" >/dev/null || exit 2
  cmake --build "$bdir" --target "fuzz_$name" -j "${SM_FUZZ_JOBS:-2}" || exit 2
  bin="$bdir/tests/fuzz/fuzz_$name"
  # The same corpus and dictionary as the target's CTest test.
  args=$(ctest --test-dir "$bdir" -R "^fuzz_short_${name}\$" --show-only=json-v1 |
         python3 -c 'import json,sys; t=json.load(sys.stdin)["tests"]; print("\n".join(t[0]["command"][t[0]["command"].index("--no-build")+3:]) if t else "")')
  while IFS= read -r a; do
    case "$a" in
      --dict) read_next=dict ;;
      --corpus) read_next=corpus ;;
      --max-len) read_next=max_len ;;
      *) case "${read_next:-}" in dict) dict="$a" ;; corpus) corpora+=("$a") ;; max_len) max_len="$a" ;; esac ;;
    esac
  done <<< "$args"
else
  [[ $# -ge 1 ]] || usage
  bin="$1"
  shift
  bdir="$(pwd)"
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --dict) [[ $# -ge 2 ]] || usage; dict="$2"; shift 2 ;;
      --corpus) [[ $# -ge 2 ]] || usage; corpora+=("$2"); shift 2 ;;
      --max-len) [[ $# -ge 2 ]] || usage; max_len="$2"; shift 2 ;;
      *) usage ;;
    esac
  done
fi
[[ -x "$bin" ]] || { echo "run.sh: no fuzz binary at $bin" >&2; exit 2; }
[[ ${#corpora[@]} -gt 0 ]] || { echo "run.sh: no corpus directory for $bin" >&2; exit 2; }

scratch="$(mktemp -d "${TMPDIR:-/tmp}/sm-fuzz.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/corpus" "$scratch/work"
corpus="$scratch/corpus"
if [[ -n "${SM_FUZZ_CORPUS:-}" ]]; then mkdir -p "$SM_FUZZ_CORPUS"; corpus="$SM_FUZZ_CORPUS"; fi
for d in "${corpora[@]}"; do
  [[ -d "$d" ]] || { echo "run.sh: no corpus directory $d" >&2; exit 2; }
  find "$d" -type f ! -name 'README*' ! -name '*.sh' ! -name '*.py' -size -64k -print0 |
    while IFS= read -r -d '' f; do cp "$f" "$corpus/seed-$(echo "$f" | md5sum | cut -c1-16)"; done
done
artifacts="${SM_FUZZ_ARTIFACTS:-$bdir/fuzz-artifacts}"
mkdir -p "$artifacts"

extra=()
[[ -n "${SM_FUZZ_RUNS:-}" ]] && extra+=(-runs="$SM_FUZZ_RUNS")
[[ -n "${SM_FUZZ_SEED:-}" ]] && extra+=(-seed="$SM_FUZZ_SEED")
[[ -n "$dict" ]] && extra+=(-dict="$dict")
echo "run.sh: fuzzing $(basename "$bin") for ${seconds}s${SM_FUZZ_RUNS:+ or $SM_FUZZ_RUNS runs} with $(ls "$corpus" | wc -l) inputs; artifacts in $artifacts"
# Evaluated scripts may write files (Printf > f, Save): run inside the scratch dir.
set +e
(cd "$scratch/work" && "$bin" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2560 -max_len="$max_len" \
   -artifact_prefix="$artifacts/" -print_final_stats=1 "${extra[@]}" "$corpus")
status=$?
set -e
if [[ $status -ne 0 ]]; then
  echo "run.sh: $(basename "$bin") failed (status $status); reproduce with: $bin <file from $artifacts>" >&2
  exit 1
fi
echo "run.sh: no crash"
