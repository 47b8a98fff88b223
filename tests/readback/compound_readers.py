#!/usr/bin/python3
"""A compound surface's elements back on the original surfaces (compound_plate.geo): Gmsh
(python3-gmsh) must load the MSH 4.1 file and find every triangle of the run on the three
rectangles of the physical surface "plate", each rectangle with some, each triangle's
centroid inside the rectangle it is on; triangles across the shared lines 2 and 6 (they
constrain nothing); the physical curves "top" and "bottom" with line elements on their three
curves each.

    compound_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, run_script
import gmsh


def inside(poly, p):
    """Crossing-number test of point p in polygon poly (a list of (x, y))."""
    n, c = len(poly), False
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > p[1]) != (y1 > p[1]) and p[0] < x0 + (p[1] - y0) * (x1 - x0) / (y1 - y0):
            c = not c
    return c


def main():
    stereomesh = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        run = run_script(stereomesh, "compound_plate.geo", out, what="stereomesh ran")
        if not run:
            finish()
            return
        triangles = int(run.stdout.split()[0])
        gmsh.initialize(["-v", "0"])
        gmsh.option.setNumber("General.Verbosity", 0)
        gmsh.open(os.path.join(out, "plate.msh"))
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = dict(zip(tags.tolist(), coords.reshape(-1, 3).tolist()))
        pts = {1: (0, 0), 2: (8.33333, 0), 3: (16.6667, 0), 4: (25, 0), 5: (0, 5.34874), 6: (9.4089, 10.8391),
               7: (16.7265, 10.0288), 8: (25.0479, 9.96269)}
        rect = {1: [pts[1], pts[2], pts[6], pts[5]], 2: [pts[2], pts[3], pts[7], pts[6]],
                3: [pts[3], pts[4], pts[8], pts[7]]}
        groups = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
        check(set(groups) == {"plate", "top", "bottom"}, f"physical groups plate, top, bottom: {sorted(groups)}")
        plate = sorted(gmsh.model.getEntitiesForPhysicalGroup(*groups["plate"]).tolist())
        check(plate == [1, 2, 3], f"'plate' holds surfaces 1, 2, 3: {plate}")
        total, misplaced, tri_xy = 0, 0, []
        for s in (1, 2, 3):
            _, _, enodes = gmsh.model.mesh.getElements(2, s)
            nodes = [int(v) for block in enodes for v in block]
            tris = [nodes[i:i + 3] for i in range(0, len(nodes), 3)]
            check(len(tris) > 0, f"surface {s} has triangles ({len(tris)})")
            total += len(tris)
            for t in tris:
                tri_xy.append([xyz[v][:2] for v in t])
                c = [sum(xyz[v][k] for v in t) / 3 for k in (0, 1)]
                owners = [r for r in rect if inside(rect[r], c)]
                if owners and s not in owners:   # none: the centroid is on a shared line
                    misplaced += 1
        check(total == triangles, f"all {triangles} triangles of the run on the three rectangles ({total})")
        check(misplaced == 0, f"every triangle on the rectangle holding its centroid ({misplaced} not)")
        # The shared lines constrain nothing: some triangles have corners on both sides.
        for a, b in ((2, 6), (3, 7)):
            (x0, y0), (x1, y1) = pts[a], pts[b]
            side = lambda p: (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)
            across = sum(1 for t in tri_xy if min(map(side, t)) < -1e-9 and max(map(side, t)) > 1e-9)
            check(across > 0, f"{across} triangles across the shared line from point {a} to {b}")
        for name in ("top", "bottom"):
            curves = gmsh.model.getEntitiesForPhysicalGroup(*groups[name]).tolist()
            lines = [sum(len(b) for b in gmsh.model.mesh.getElements(1, c)[1]) for c in curves]
            check(len(curves) == 3 and sum(lines) > 0, f"'{name}': line elements on curves {curves}: {lines}")
        gmsh.finalize()
    finish()
    print("all checks hold")


if __name__ == "__main__":
    main()
