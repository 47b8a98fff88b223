#!/usr/bin/env python3
"""Writes bad_record.txt: three real segments of GSHHG 2.3.7 crude (world_c.txt segments 3 to
5, with a correct GMT header) where the 4th point of the second segment reads "-61.2 x12"
instead of two numbers, for tests/scripts/coastline/fail_bad_record.geo."""
import os

here = os.path.dirname(os.path.abspath(__file__))
segs = []
for line in open(os.path.join(here, "../../../data/gshhg/world_c.txt")):
    if line.startswith("#"):
        continue
    if line.startswith(">"):
        segs.append([line, []])
    else:
        segs[-1][1].append(line)
keep = segs[2:5]
with open(os.path.join(here, "bad_record.txt"), "w") as out:
    out.write("# GSHHG 2.3.7 crude, three segments of world_c.txt, one point made unreadable\n")
    out.write(f"# segments=3 closed=3 open=0 wraps_pole=0 points={sum(len(p) for _, p in keep)}\n")
    for k, (head, pts) in enumerate(keep):
        out.write(head)
        for i, p in enumerate(pts):
            out.write("-61.2 x12\n" if (k, i) == (1, 3) else p)
