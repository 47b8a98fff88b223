#!/bin/sh
# Regenerates the Gmsh 4.8.4 reference node files (.msh41: the name keeps them out of the *.msh ignore rule) used by tests/unit/geo/curve_gmsh_test.cpp:
# each curve is meshed in 1D, and MSH 4.1 with Mesh.SaveParametric=1 stores, for every node
# inside a curve, its 3D position and the curve parameter t at which Gmsh evaluated it.
set -e
cd "$(dirname "$0")"
/usr/bin/python3 make_coast_geo.py
for f in curves_euclid curves_polar coast_polar; do
  gmsh "$f.geo" -1 -format msh41 -save_parametric -o "$f.msh41" > /dev/null
done
# All 1,440 coastlines of world_i_A100.txt as closed BSplines (Eurasia: 35,321 control
# points), meshed by gmsh at lc = 0.05 on the unit sphere; only the curve nodes are kept:
# "curve t x y z" per line (the full .msh41 would be 33 MB with every control point).
/usr/bin/python3 make_world_geo.py ../../../data/gshhg/world_i_A100.txt /tmp/world_i_$$.geo 0.05
gmsh /tmp/world_i_$$.geo -1 -format msh41 -save_parametric -o /tmp/world_i_$$.msh41 > /dev/null
/usr/bin/python3 - /tmp/world_i_$$.msh41 > world_i_bspline_nodes.txt <<'PY'
import sys
f = open(sys.argv[1])
for line in f:
    if line.startswith('$Nodes'):
        break
nb, nn, lo, hi = map(int, f.readline().split())
for b in range(nb):
    d, t, par, n = map(int, f.readline().split())
    for _ in range(n):
        f.readline()
    for _ in range(n):
        row = f.readline().split()
        if d == 1:
            print(t, row[3], row[0], row[1], row[2])
PY
rm -f /tmp/world_i_$$.geo /tmp/world_i_$$.msh41
