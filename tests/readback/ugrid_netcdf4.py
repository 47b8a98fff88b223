#!/usr/bin/python3
"""UGRID netCDF read back by independent readers: the Gulf of Mexico meshed once and saved
as MSH and as UGRID (ugrid_gulf.geo); python3-netcdf4 reads the .nc, Gmsh's own reader
(python3-gmsh) the .msh, and every count and the geometry must agree.

    ugrid_netcdf4.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, gmsh_nodes, run_script  # exits 77 when a reader is missing
import gmsh
import netCDF4
import numpy as np


def main():
    with tempfile.TemporaryDirectory() as tmp:
        if not run_script(sys.argv[1], "ugrid_gulf.geo", tmp):
            return
        compare(os.path.join(tmp, "gulf.msh"), os.path.join(tmp, "gulf.nc"))


def compare(msh_path, nc_path):
    xyz = gmsh_nodes(msh_path)
    tri = []
    for _, etags, enodes in zip(*gmsh.model.mesh.getElements(2)):
        tri += [tuple(enodes[i:i + 3]) for i in range(0, len(enodes), 3)]
    lines = {}   # edge (sorted node tags) -> physical tag of its curve
    for dim, group in gmsh.model.getPhysicalGroups(1):
        for curve in gmsh.model.getEntitiesForPhysicalGroup(dim, group):
            _, _, enodes = gmsh.model.mesh.getElements(1, curve)
            for block in enodes:
                for i in range(0, len(block), 2):
                    lines[tuple(sorted(block[i:i + 2]))] = group
    names = {g: gmsh.model.getPhysicalName(1, g) for _, g in gmsh.model.getPhysicalGroups(1)}
    gmsh.finalize()
    faces_on = {}
    for t in tri:
        for k in range(3):
            e = tuple(sorted((t[k], t[(k + 1) % 3])))
            faces_on[e] = faces_on.get(e, 0) + 1
    boundary = {e: g for e, g in lines.items() if faces_on.get(e) == 1}
    used = sorted({v for t in tri for v in t})

    nc = netCDF4.Dataset(nc_path)
    topo = nc.variables["mesh2d"]
    check(topo.cf_role == "mesh_topology" and topo.topology_dimension == 2, "mesh topology variable")
    check("UGRID-1.0" in nc.Conventions, "Conventions names UGRID-1.0")
    nn, nf = len(nc.dimensions["mesh2d_nNodes"]), len(nc.dimensions["mesh2d_nFaces"])
    ne = len(nc.dimensions["mesh2d_nEdges"])
    check(nn == len(used), f"nodes: {nn} in the .nc, {len(used)} used by the .msh triangles")
    check(nf == len(tri), f"faces: {nf} in the .nc, {len(tri)} triangles in the .msh")
    check(ne == len(boundary), f"boundary edges: {ne} in the .nc, {len(boundary)} in the .msh")

    lon = nc.variables["mesh2d_node_x"][:]
    lat = nc.variables["mesh2d_node_y"][:]
    cart = np.stack([nc.variables[f"mesh2d_node_cartesian_{c}"][:] for c in "xyz"], axis=1)
    r = np.linalg.norm(cart, axis=1)
    check(np.allclose(r, nc.sphere_radius, rtol=1e-12), "nodes on the sphere of sphere_radius")
    lon_c = np.degrees(np.arctan2(cart[:, 1], cart[:, 0]))
    lat_c = np.degrees(np.arcsin(cart[:, 2] / r))
    check(np.allclose(lon, lon_c, atol=1e-9) and np.allclose(lat, lat_c, atol=1e-9), "lon/lat agree with x y z")
    check(lon.min() > -98.01 and lon.max() < -75.99 and lat.min() > 6.99 and lat.max() < 31.01,
          f"nodes inside the Gulf's box (lon {lon.min():.2f}..{lon.max():.2f}, lat {lat.min():.2f}..{lat.max():.2f})")

    # Each .nc node is a .msh node (the same point to 1e-6 m), and each face a triangle.
    by_point = {tuple(np.round(xyz[t], 3)): t for t in used}
    to_msh = [by_point.get(tuple(np.round(p, 3))) for p in cart]
    check(all(t is not None for t in to_msh), "every .nc node is a .msh node")
    fn = nc.variables["mesh2d_face_nodes"]
    check(fn.start_index == 0, "start_index 0")
    faces = np.ma.filled(fn[:], -1)
    check((faces >= 0).all() and (faces < nn).all(), "face nodes in range")
    msh_faces = {frozenset(t) for t in tri}
    nc_faces = {frozenset(to_msh[v] for v in f) for f in faces}
    check(nc_faces == msh_faces, "the .nc faces are the .msh triangles")
    a, b, c = cart[faces[:, 0]], cart[faces[:, 1]], cart[faces[:, 2]]
    outward = np.einsum("ij,ij->i", np.cross(b - a, c - a), a)
    check((outward > 0).all(), "faces anticlockwise seen from outside the sphere")

    en = nc.variables["mesh2d_edge_nodes"][:]
    phys_var = nc.variables["mesh2d_edge_physical"]
    phys = phys_var[:]
    kind = nc.variables["mesh2d_edge_type"][:]
    edges = [tuple(sorted((to_msh[p], to_msh[q]))) for p, q in en]
    check(set(edges) == set(boundary), "the .nc edges are the .msh boundary lines")
    check(all(boundary.get(e) == g for e, g in zip(edges, phys)), "each edge's physical group as in the .msh")
    meanings = dict(zip(np.atleast_1d(phys_var.flag_values).tolist(), phys_var.flag_meanings.split()))
    check(all(meanings.get(g) == names[g] for g in set(phys.tolist())), f"group names {meanings}")
    open_group = [g for g, n in names.items() if n == "open"]
    n_open = sum(1 for g in boundary.values() if g in open_group)
    n_kind_open = int((kind == 3).sum())
    check(n_open > 0 and n_kind_open == n_open, f"open edges: {n_kind_open} of kind open, {n_open} in the group 'open'")
    check(int((kind == 2).sum()) > 0 and int((kind == 1).sum()) > 0, "island and mainland edges present")

    depth = nc.variables["mesh2d_node_depth"]
    d = np.ma.filled(depth[:].astype(float), np.nan)
    check(depth.positive == "down" and depth.units == "m", "depth attributes")
    check(d.min() >= 5 and d.max() < 11000 and float(np.median(d)) > 100,
          f"depths from ETOPO (min {d.min():.0f} m, median {float(np.median(d)):.0f} m, max {d.max():.0f} m)")
    nc.close()


main()
finish()
