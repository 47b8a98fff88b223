#!/bin/sh
# The gmsh 4.8.4 runs behind the expected values of tests/unit/geo/model_test.cpp and
# surface_filling_test.cpp: each script's Printf output (and Gmsh's own error lines) is kept
# in <script>.out; filling_surfaces.out holds model.getValue samples (python3-gmsh).
set -e
cd "$(dirname "$0")"
for f in tags physicals_boundary_delete duplicata_transforms duplicata_tags split_curve split_in_loop bounding_box; do
  gmsh -0 "$f.geo" -o /tmp/gmsh_queries_$$.geo_unrolled 2>&1 | grep -v '^Info' > "$f.out" || true
  echo "--- unrolled:" >> "$f.out"
  cat /tmp/gmsh_queries_$$.geo_unrolled >> "$f.out"
done
for onr in 1 0; do
  gmsh -0 duplicata_oldnewreg.geo -setnumber onr $onr -o /tmp/gmsh_queries_$$.geo_unrolled 2>&1 | grep -v '^Info'
done > duplicata_oldnewreg.out
rm -f /tmp/gmsh_queries_$$.geo_unrolled
/usr/bin/python3 - > filling_surfaces.out <<'PY'
import gmsh
gmsh.initialize()
gmsh.option.setNumber('General.Verbosity', 2)
gmsh.open('filling_surfaces.geo')
for s in [1, 2, 3, 4, 5, 6]:
    for (u, v) in [(0, 0), (0.3, 0.2), (0.5, 0.5), (0.9, 0.7), (1, 1), (1, 0), (0, 1)]:
        print(s, u, v, ' '.join('%.17g' % x for x in gmsh.model.getValue(2, s, [u, v])))
gmsh.finalize()
PY
