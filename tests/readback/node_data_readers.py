#!/usr/bin/python3
"""Mesh.NodeData read back by other programs' readers: Gmsh (python3-gmsh) reads the
$NodeData of MSH 4.1 and of binary MSH 2.2 as views, meshio (python3-meshio) the VTK point
data, netCDF4-python the UGRID node variables; all must hold the same values at the same
points, and the values must be what they say (depth from ETOPO, size within the example's
bounds, criterion the ids of the size criteria).

    node_data_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, gmsh_nodes, reader, run_script  # exits 77 when a reader is missing
import gmsh
import netCDF4
import numpy as np

meshio = reader("meshio")

NAMES = ["depth", "size", "criterion"]


def same(a, b):
    """The same points, and values equal to the 16 significant digits ASCII files hold."""
    return a.keys() == b.keys() and all(np.isclose(a[k], b[k], rtol=1e-15, atol=0) for k in a)


def by_point(xyz, values):
    """{rounded point: value} for comparing files whose nodes are numbered differently."""
    return {tuple(np.round(p, 3)): v for p, v in zip(xyz, values)}


def gmsh_views(path):
    xyz = gmsh_nodes(path)
    out = {}
    for t in gmsh.view.getTags():
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(t)}].Name")
        _, node_tags, data, _, _ = gmsh.view.getModelData(t, 0)
        out[name] = by_point([xyz[n] for n in node_tags], [d[0] for d in data])
    gmsh.finalize()
    return out


def main():
    with tempfile.TemporaryDirectory() as tmp:
        if not run_script(sys.argv[1], "node_data_gulf.geo", tmp):
            return
        nc = netCDF4.Dataset(os.path.join(tmp, "gulf.nc"))
        cart = np.stack([nc.variables[f"mesh2d_node_cartesian_{c}"][:] for c in "xyz"], axis=1)
        ref = {n: by_point(cart, np.ma.filled(nc.variables[f"mesh2d_node_{n}"][:].astype(float), np.nan))
               for n in NAMES}
        nc.close()
        for f in ("gulf41.msh", "gulf22b.msh"):
            views = gmsh_views(os.path.join(tmp, f))
            check(sorted(views) == sorted(NAMES), f"{f}: Gmsh reads views {sorted(views)}")
            for n in NAMES:
                check(n in views and same(views[n], ref[n]), f"{f}: {n} at {len(ref[n])} nodes as in the UGRID file")
        vtk = meshio.read(os.path.join(tmp, "gulf.vtk"))
        for n in NAMES:
            check(same(by_point(vtk.points, vtk.point_data[n]), ref[n]), f"gulf.vtk: {n} (meshio) as in the UGRID file")

        depth, size, crit = (np.array(list(ref[n].values())) for n in NAMES)
        check(depth.min() >= 5 and depth.max() < 11000, f"depth from ETOPO, 5 m at least ({depth.min():.0f}..{depth.max():.0f} m)")
        # examples/gulf_of_mexico.geo: shore size 10-60 km, the channel widths down to the 5 km accuracy.
        check(size.min() >= 5e3 * 0.999 and size.max() <= 60e3 * 1.001, f"size within 5-60 km ({size.min():.0f}..{size.max():.0f} m)")
        kinds = sorted(set(crit.tolist()))
        check(0 in kinds and len(kinds) == 2 and kinds[1] > 0,
              f"criterion: the channel width (0) and the shore field ({kinds})")
        check(size[crit == 0].min() < 10e3 and size[crit > 0].min() >= 10e3 * 0.999,
              "sizes below the 10 km shore minimum come from the channel width")


main()
finish()
