#!/bin/sh
# The GSHHG crude world ocean written as a plain Gmsh script (tests/bench/crude_world_geo.cpp,
# from the system's /usr/share/gmt-gshhg/binned_GSHHS_c.nc, Debian gmt-gshhg-low, which
# .ci/deps installs) meshes with stereomesh -2 in both forms, Lines and one BSpline per ring,
# at a constant 100 km, with a triangle count within 15% of what gmsh 4.8.4 -2 gives on the
# same file; the raw script (--raw: the data's zero-width spikes and crossing B-splines kept)
# stops with the located error at the first invalid place. Figures: docs/coastlines.md.
# Usage: check_crude_world.sh path/to/bench_crude_world_geo path/to/stereomesh
set -u
gen=$1
sm=$2
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0

# mesh FORM GMSH_TRIANGLES: exit 0 and a count within 15% of gmsh's.
mesh() {
  "$gen" "$1" 100000 "$tmp/$1.geo" >"$tmp/$1.gen" 2>&1 || { echo "FAIL: generator ($1)"; cat "$tmp/$1.gen"; fail=1; return; }
  if ! "$sm" -2 "$tmp/$1.geo" -o "$tmp/$1.msh" --stats "$tmp/$1.json" -v 2 >"$tmp/$1.out" 2>"$tmp/$1.err"; then
    echo "FAIL: stereomesh -2 $1.geo"; cat "$tmp/$1.err"; fail=1; return
  fi
  n=$(sed -n 's/.*"triangles": \([0-9]*\).*/\1/p' "$tmp/$1.json")
  lo=$(( $2 * 85 / 100 )); hi=$(( $2 * 115 / 100 ))
  if [ -z "$n" ] || [ "$n" -lt "$lo" ] || [ "$n" -gt "$hi" ]; then
    echo "FAIL: $1: ${n:-no} triangles, gmsh 4.8.4 gives $2 (band $lo..$hi)"; fail=1
  else
    echo "pass: $1: $n triangles (gmsh 4.8.4: $2)"
  fi
}
# gmsh 4.8.4 -2 -nt 1 on the generated files: Lines 100,015 triangles, BSplines 89,161.
mesh lines 100015
mesh bsplines 89161

# raw FORM EXPECTED: exit 1 and the located error (file:line:col, kind curves-intersect).
raw() {
  "$gen" "$1" 100000 "$tmp/raw_$1.geo" --raw >"$tmp/raw_$1.gen" 2>&1 || { echo "FAIL: generator (raw $1)"; fail=1; return; }
  "$sm" -2 "$tmp/raw_$1.geo" -o "$tmp/raw_$1.msh" -v 2 >"$tmp/raw_$1.out" 2>"$tmp/raw_$1.err"
  rc=$?
  if [ "$rc" -ne 1 ] || ! grep -q "raw_$1.geo:$2" "$tmp/raw_$1.err"; then
    echo "FAIL: raw $1: exit $rc, expected 1 and 'raw_$1.geo:$2'"; cat "$tmp/raw_$1.err"; fail=1
  else
    echo "pass: raw $1: $(grep -m1 ' error: ' "$tmp/raw_$1.err" | sed 's/.*error: //')"
  fi
}
# The spike P -> Q -> P near 0E 49.33N (gmsh -2 stops on the next one: "Unable to recover
# the edge"); the 3-point sliver island off west Greenland whose B-spline crosses Greenland's.
raw lines "1336:1: error: curves 220 and 222 have distinct nodes at the same place"
raw bsplines "7940:1: error: curves 602 and 7 intersect"
exit $fail
