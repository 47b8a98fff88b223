#!/usr/bin/python3
"""Periodic curves read back by Gmsh (periodic_square.geo): Gmsh's reader (python3-gmsh)
must load the MSH 4.1 and 2.2 files with their $Periodic section, and see curve 3 as a
copy of curve 1 (its nodes 1 above theirs, the translation's map written with them) and
curve 2 as a copy of curve 4 (node for node, reversed, 1 to the right), each pair's
curves with as many line elements.

    periodic_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, gmsh_nodes, run_script  # exits 77 when a reader is missing
import gmsh
import numpy as np


def periodic_view(path):
    """Per curve 1..4: (master tag, node pairs' coordinates (slave, master), affine map,
    line element count) as Gmsh's reader sees them."""
    xyz = gmsh_nodes(path, periodic=True)
    out = {}
    for c in range(1, 5):
        master, nodes, master_nodes, affine = gmsh.model.mesh.getPeriodicNodes(1, c)
        types, elements, _ = gmsh.model.mesh.getElements(1, c)
        lines = sum(len(e) for t, e in zip(types, elements) if t == 1)
        pairs = [(xyz[a], xyz[b]) for a, b in zip(nodes.tolist(), master_nodes.tolist())]
        out[c] = (master, pairs, list(affine), lines)
    gmsh.finalize()
    return out


def main():
    stereomesh = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        if not run_script(stereomesh, "periodic_square.geo", out, what="stereomesh ran"):
            finish()
            return
        for name in ["square.msh", "square22.msh"]:
            v = periodic_view(os.path.join(out, name))
            for slave, master, shift in [(3, 1, (0, 1, 0)), (2, 4, (1, 0, 0))]:
                m, pairs, affine, lines = v[slave]
                check(m == master, f"{name}: curve {slave}'s master is curve {m} (want {master})")
                check(lines == v[master][3] and lines > 5,
                      f"{name}: curve {slave} has {lines} line elements, curve {master} {v[master][3]}")
                check(len(pairs) == lines + 1, f"{name}: curve {slave} lists {len(pairs)} node pairs")
                err = max((float(np.linalg.norm(a - b - np.array(shift))) for a, b in pairs), default=1.0)
                check(err < 1e-12, f"{name}: each node of curve {slave} is its master's moved by {shift} ({err:.2g})")
            affine = v[3][2]
            check(len(affine) == 16 and affine[7] == 1.0, f"{name}: curve 3's map is the translation by (0, 1, 0)")
    finish()


main()
