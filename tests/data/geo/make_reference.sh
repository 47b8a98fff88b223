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
