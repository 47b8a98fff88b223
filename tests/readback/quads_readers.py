#!/usr/bin/python3
"""Quadrangles read back by other programs' readers (quads_channel.geo): Gmsh
(python3-gmsh) must load the MSH 4.1 and 2.2 files and see the same number of type 3
(4-node quadrangle) elements as the script's Mesh.NbQuadrangles, all of them on the
physical surface, each with a positive area; meshio (python3-meshio) must read the VTK's
quad cells; netCDF4-python the UGRID faces with 4 nodes (a fill value for triangles); the
hgrid.gr3 must list "id 4 n1 n2 n3 n4" lines as SCHISM reads them.

    quads_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, gmsh_nodes, run_script, reader  # exits 77 when a reader is missing
import gmsh
import netCDF4
import numpy as np

meshio = reader("meshio")


def gmsh_quads(path):
    """(quadrangles, triangles, smallest quadrangle area) as Gmsh's reader sees them."""
    xyz = gmsh_nodes(path)
    quads = tris = 0
    smallest = float("inf")
    for dim, tag in gmsh.model.getEntities(2):
        types, _, enodes = gmsh.model.mesh.getElements(2, tag)
        for t, block in zip(types, enodes):
            if t == 2:
                tris += len(block) // 3
            if t != 3:
                continue
            for i in range(0, len(block), 4):
                p = [xyz[v] for v in block[i:i + 4]]
                area = 0.5 * sum(p[k][0] * p[(k + 1) % 4][1] - p[(k + 1) % 4][0] * p[k][1] for k in range(4))
                smallest = min(smallest, area)
                quads += 1
    gmsh.finalize()
    return quads, tris, smallest


def main():
    stereomesh = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        run = run_script(stereomesh, "quads_channel.geo", out, what="stereomesh ran")
        if not run:
            finish()
            return
        words = run.stdout.split()
        want_q, want_t = int(float(words[1])), int(float(words[3]))
        check(want_q > 100, f"the script made {want_q} quadrangles (and {want_t} triangles)")
        for name in ["channel.msh", "channel22.msh"]:
            q, t, smallest = gmsh_quads(os.path.join(out, name))
            check(q == want_q and t == want_t, f"{name}: Gmsh reads {q} quadrangles and {t} triangles")
            check(smallest > 0, f"{name}: every quadrangle counter-clockwise (smallest area {smallest:.3g})")
        m = meshio.read(os.path.join(out, "channel.vtk"))
        vq = sum(len(c.data) for c in m.cells if c.type == "quad")
        check(vq == want_q, f"channel.vtk: meshio reads {vq} quad cells")
        with netCDF4.Dataset(os.path.join(out, "channel.nc")) as nc:
            faces = nc.variables["mesh2d_face_nodes"][:]
            nq = int(np.sum(~np.ma.getmaskarray(faces[:, 3]))) if faces.shape[1] == 4 else 0
            check(faces.shape[1] == 4 and nq == want_q, f"channel.nc: {nq} faces with 4 nodes of {faces.shape[0]}")
        with open(os.path.join(out, "hgrid.gr3")) as f:
            f.readline()
            ne, np_ = (int(x) for x in f.readline().split()[:2])
            lines = f.read().splitlines()
        elements = [l.split() for l in lines[np_:np_ + ne]]   # after the NP node lines
        g4 = sum(1 for e in elements if e[1] == "4" and len(e) == 6)
        check(ne == want_q + want_t and g4 == want_q, f"hgrid.gr3: {ne} elements, {g4} written 'id 4 n1 n2 n3 n4'")
    finish()


main()
