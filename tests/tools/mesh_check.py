#!/usr/bin/python3
"""Reads a mesh file with Gmsh's own reader (python3-gmsh) and prints its figures as JSON:
what a user checks by hand before giving a mesh to a model, and what tests/bench/run.sh
puts beside Gmsh's own meshes.

usage: mesh_check.py MESH [--sphere R]

Printed: nodes, nodes used by no triangle (a reader that builds its connectivity from the
node list trips on them), triangles, quadrangles, rho = 2 r_in / r_circ of the triangles
(min, mean, share above 0.9), conforming (no edge in more than two triangles), inverted
triangles (in the plane: negative area; on a sphere of radius R: the normal points inwards)
and, with --sphere, the largest |r - R| of a node. Exit 0 when Gmsh read the file, 2 when not.
"""
import json
import sys

import gmsh
import numpy as np


def triangle_figures(xyz, tri, radius):
    a, b, c = xyz[tri[:, 0]], xyz[tri[:, 1]], xyz[tri[:, 2]]
    la = np.linalg.norm(b - c, axis=1)
    lb = np.linalg.norm(c - a, axis=1)
    lc = np.linalg.norm(a - b, axis=1)
    normal = np.cross(b - a, c - a)
    area = 0.5 * np.linalg.norm(normal, axis=1)
    # rho = 2 r_in / r_circ with r_in = area / s and r_circ = la lb lc / (4 area).
    s = 0.5 * (la + lb + lc)
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = np.where(area > 0, 8.0 * area * area / (s * la * lb * lc), 0.0)
    if radius is None:   # a planar mesh: the sign of the z component of the normal
        inverted = int(np.count_nonzero(normal[:, 2] < 0))
    else:                # on the sphere: the normal against the position of the centroid
        centroid = (a + b + c) / 3.0
        inverted = int(np.count_nonzero(np.einsum("ij,ij->i", normal, centroid) < 0))
    return rho, inverted


def conforming(tri):
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(counts <= 2))


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    path = sys.argv[1]
    radius = float(sys.argv[sys.argv.index("--sphere") + 1]) if "--sphere" in sys.argv else None
    gmsh.initialize(["mesh_check", "-v", "0"])
    try:
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        types, _, element_nodes = gmsh.model.mesh.getElements(dim=2)
    except Exception as e:  # Gmsh's reader refused the file
        print(json.dumps({"error": f"Gmsh could not read {path}: {e}"}))
        return 2
    finally:
        gmsh.finalize()
    xyz = coords.reshape(-1, 3)
    order = np.argsort(tags)
    sorted_tags = tags[order]

    def rows(nodes, k):
        ids = np.asarray(nodes, dtype=np.int64).reshape(-1, k)
        return order[np.searchsorted(sorted_tags, ids)]

    tri = np.zeros((0, 3), dtype=np.int64)
    quads = np.zeros((0, 4), dtype=np.int64)
    for t, n in zip(types, element_nodes):
        if t == 2:
            tri = np.vstack([tri, rows(n, 3)])
        elif t == 3:
            quads = np.vstack([quads, rows(n, 4)])
    used = np.zeros(len(tags), dtype=bool)
    used[tri.ravel()] = True
    used[quads.ravel()] = True
    out = {"nodes": int(len(tags)), "unused_nodes": int(np.count_nonzero(~used)),
           "triangles": int(len(tri)), "quadrangles": int(len(quads))}
    if len(tri):
        rho, inverted = triangle_figures(xyz, tri, radius)
        out.update({"rho_min": float(rho.min()), "rho_mean": float(rho.mean()),
                    "rho_gt_0.9": float(np.mean(rho > 0.9)), "conforming": conforming(tri),
                    "inverted": inverted})
    if radius is not None:
        out["max_radius_error"] = float(np.max(np.abs(np.linalg.norm(xyz, axis=1) - radius)))
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
