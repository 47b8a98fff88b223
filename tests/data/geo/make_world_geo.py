#!/usr/bin/env python3
# Writes a .geo of every coastline of a GSHHG text export (default: world_i_A100.txt) as a
# closed BSpline (BSpline(k), k = segment number) on a unit PolarSphere, in Plugin(GSHHS)
# (u,v) coordinates. Used by make_reference.sh to mesh it with gmsh 4.8.4; only the node
# file is committed (the .geo is 10 MB and is rebuilt from the shared data).
import math, os, sys

src, out, lc = sys.argv[1], sys.argv[2], float(sys.argv[3])
lines = ["Mesh.CharacteristicLengthFromCurvature = 0;", "Mesh.CharacteristicLengthExtendFromBoundary = 0;",
         "Point(1) = {0, 0, 0}; Point(2) = {0, 0, 1};", "PolarSphere(1) = {1, 2};"]
tag, seg, pts = 10, 0, []

def flush():
    global tag
    if not pts:
        return
    first = tag
    for lon, lat in pts[:-1]:           # the last vertex repeats the first on the sphere
        t = math.tan(math.pi / 4 - math.radians(lat) / 2)
        lines.append("Point(%d) = {%.17g, %.17g, 0, %g};" % (tag, -t * math.cos(math.radians(lon)),
                                                           -t * math.sin(math.radians(lon)), lc))
        tag += 1
    lines.append("BSpline(%d) = {%d:%d, %d};" % (seg, first, tag - 1, first))

for line in open(src):
    if line.startswith("#"):
        continue
    if line.startswith(">"):
        flush()
        seg += 1
        pts = []
        continue
    lon, lat = map(float, line.split())
    pts.append((lon, lat))
flush()
open(out, "w").write("\n".join(lines) + "\n")
