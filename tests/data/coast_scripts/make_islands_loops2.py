#!/usr/bin/env python3
"""Writes islands_loops2.txt (Gmsh 2.x loops2, lonlat_degrees): Islay, Anglesey and the Isle
of Man copied from GSHHG 2.3.7 full (data/gshhg/gb_ireland_f.txt, segments 9, 11 and
the first ring of 100 to 5,000 points whose box holds 54.2N 4.5W), for tests/scripts/coastline/loops2.geo.
Usage: make_islands_loops2.py [path/to/gb_ireland_f.txt]"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "../../../data/gshhg/gb_ireland_f.txt")
segs = []
for line in open(src):
    if line.startswith("#"):
        continue
    if line.startswith(">"):
        words = dict(w.split("=", 1) for w in line[1:].split() if "=" in w)
        segs.append((words, []))
    else:
        lon, lat = line.split()
        segs[-1][1].append((lon, lat))


def holds(words, lon, lat):
    w, e = map(float, words["lon"].split("/"))
    s, n = map(float, words["lat"].split("/"))
    return w <= lon <= e and s <= lat <= n and words["closed"] == "1"


man = next(i for i, (w, _) in enumerate(segs) if holds(w, -4.5, 54.2) and 100 < int(w["npts"]) < 5000)
with open(os.path.join(here, "islands_loops2.txt"), "w") as out:
    for i in (8, 10, man):   # 0-based: segments 9 and 11
        pts = segs[i][1]
        out.write(f"{len(pts)} 1\n")
        for lon, lat in pts:
            out.write(f"{lon} {lat}\n")
