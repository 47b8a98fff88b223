#!/bin/sh
# Runs every non-fail_ script under tests/scripts/ (except extensions/ and
# scripts containing the line "// compare_with_gmsh: skip", which test native
# behaviour) through `gmsh -0` and
# `stereomesh -0` and diffs their Printf output line for line.
# Usage: tests/scripts/compare_with_gmsh.sh [path/to/stereomesh] [script.geo...]
# Exit status: 0 when every script agrees, 1 otherwise.
set -u
here=$(cd "$(dirname "$0")" && pwd)
sm=${1:-stereomesh}
[ $# -gt 0 ] && shift
command -v gmsh >/dev/null || { echo "gmsh not found" >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
cp -r "$here" "$tmp/scripts"
# Scripts may Include generated models from tests/data/geo_scripts (../../data/... from a subdirectory).
mkdir -p "$tmp/data" && cp -r "$here/../data/geo_scripts" "$tmp/data/"
if [ $# -gt 0 ]; then
  scripts="$*"
else
  scripts=$(cd "$here" && find . -name '*.geo' ! -name 'fail_*' ! -path './extensions/*' | sort)
fi
same=0; differ=0; lines=0; skipped=0
for s in $scripts; do
  rel=${s#"$here"/}; rel=${rel#./}
  # Scripts that test native features (FieldValue, %s, Assert...) opt out.
  if grep -q '// compare_with_gmsh: skip' "$here/$rel"; then
    skipped=$((skipped + 1)); continue
  fi
  dir=$tmp/scripts/$(dirname "$rel"); base=$(basename "$rel")
  (cd "$dir" && gmsh -0 "$base" 2>/dev/null | grep -av '^Info    :') > "$tmp/gmsh.out"
  (cd "$dir" && "$sm" -0 "$base" 2>"$tmp/sm.err") > "$tmp/sm.out"
  status=$?
  if [ "$status" -ne 0 ]; then
    differ=$((differ + 1)); echo "FAIL $rel: stereomesh exited with $status"
    head -5 "$tmp/sm.err"
  elif cmp -s "$tmp/gmsh.out" "$tmp/sm.out"; then
    same=$((same + 1)); lines=$((lines + $(wc -l < "$tmp/gmsh.out")))
  else
    differ=$((differ + 1)); echo "DIFF $rel (< gmsh, > stereomesh)"
    diff "$tmp/gmsh.out" "$tmp/sm.out" | head -20
  fi
done
echo "$same scripts agree ($lines Printf lines), $differ differ, $skipped skipped (native)"
[ "$differ" -eq 0 ]
