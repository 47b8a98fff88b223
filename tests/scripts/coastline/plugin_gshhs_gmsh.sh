#!/bin/sh
# Loads the .geo that Plugin(GSHHS) writes (plugin_gshhs.geo) in Gmsh 4.8.4: `gmsh -0` must
# read it with no error other than its refusal to export the PolarSphere surface to
# .geo_unrolled, and count the same points, curves, surfaces and boundary curves as
# stereomesh. Usage: plugin_gshhs_gmsh.sh [path/to/stereomesh]
# Exit status: 0 pass, 1 fail, 77 skipped (no gmsh on PATH).
set -u
here=$(cd "$(dirname "$0")" && pwd)
sm=${1:-stereomesh}
command -v gmsh >/dev/null || { echo "gmsh not found: skipped"; exit 77; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
if ! "$sm" "$here/plugin_gshhs.geo" -setstring out "$tmp/earth.geo" >"$tmp/run.out" 2>"$tmp/run.err"; then
  echo "FAIL: stereomesh could not run plugin_gshhs.geo"; cat "$tmp/run.err"; exit 1
fi
cat >"$tmp/count.geo" <<'GEO'
Include "earth.geo";
c[] = Curve{:};
s[] = Surface{:};
p[] = Point{:};
b[] = Boundary{ Surface{s[0]}; };
Printf("%g points, %g curves, %g surfaces, %g boundary curves", #p[], #c[], #s[], #b[]);
GEO
(cd "$tmp" && gmsh -0 count.geo >gmsh.out 2>&1)
errors=$(grep -a '^Error' "$tmp/gmsh.out" | grep -v 'Skipping surface .* in export')
if [ -n "$errors" ]; then
  echo "FAIL: gmsh reported errors on the plugin's output:"; echo "$errors"; exit 1
fi
grep -av '^Info\|^Error\|^Warning' "$tmp/gmsh.out" >"$tmp/gmsh.counts"
(cd "$tmp" && "$sm" -0 count.geo >sm.counts 2>sm.err) || { echo "FAIL: stereomesh count.geo"; cat "$tmp/sm.err"; exit 1; }
if ! cmp -s "$tmp/gmsh.counts" "$tmp/sm.counts"; then
  echo "FAIL: counts differ"; echo "gmsh:"; cat "$tmp/gmsh.counts"; echo "stereomesh:"; cat "$tmp/sm.counts"; exit 1
fi
echo "pass: $(cat "$tmp/sm.counts")"
