#!/usr/bin/python3
"""Every output file holds the mesh and only the mesh, numbered one way: the World
Ocean at a coarse setting (two small islands left out of the 2D mesh) and the Gulf of Mexico
(open boundaries) are meshed once each and saved as MSH 4.1, MSH 2.2, VTK, UGRID netCDF,
fort.14 and hgrid.gr3 / hgrid.ll (outputs_world.geo, outputs_gulf.geo); Gmsh's reader
(python3-gmsh) reads the MSH 4.1, meshio the MSH 2.2 and the VTK, netCDF4-python the UGRID
file, and a small parser here the fort.14 and hgrid.gr3 with their boundary lists. Checks:
no node that no triangle uses, the same node and triangle counts as the run's summary and
--stats, node i at the same place in every file (within the format's printed digits), the
same triangles in the same order, and every boundary edge (a side of one triangle only)
listed exactly once in fort.14 and hgrid.gr3, closed loops closed. With the Python module
built beside the program (build/python), its arrays for the Gulf are compared too.

    outputs_agree.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from readback import HERE, check, finish, reader  # exits 77 when a reader is missing
import gmsh
import netCDF4
import numpy as np

meshio = reader("meshio")
R = 6371000.0   # the stdlib's EarthRadius: lon/lat <-> x y z of the files


def lonlat_of(xyz):
    r = np.linalg.norm(xyz, axis=1)
    return np.stack([np.degrees(np.arctan2(xyz[:, 1], xyz[:, 0])), np.degrees(np.arcsin(xyz[:, 2] / r))], axis=1)


def same_lonlat(a, b, tol):
    """lon/lat pairs equal within tol degrees (longitudes modulo 360: +-180 is one meridian)."""
    dlon = np.abs((a[:, 0] - b[:, 0] + 180.0) % 360.0 - 180.0)
    return bool((dlon <= tol).all() and (np.abs(a[:, 1] - b[:, 1]) <= tol).all())


def parse_grid(path):
    """fort.14 or hgrid.gr3/.ll: (lonlat (N,2), triangles (T,3) 0-based, [(kind, type, nodes)])
    with kind 'open' or 'land' and nodes 0-based as listed."""
    with open(path) as f:
        lines = f.read().splitlines()
    ne, nn = (int(v) for v in lines[1].split()[:2])
    xy = np.array([[float(v) for v in lines[2 + i].split()[1:3]] for i in range(nn)])
    ids = [int(lines[2 + i].split()[0]) for i in range(nn)]
    tri = []
    for i in range(ne):
        v = lines[2 + nn + i].split()
        tri.append([int(x) - 1 for x in v[2:2 + int(v[1])]])
    k = 2 + nn + ne
    strings = []
    for kind in ("open", "land"):
        count = int(lines[k].split()[0])
        k += 2   # the count, then the total node count
        for _ in range(count):
            head = lines[k].split("=")[0].split()
            n, typ = int(head[0]), (int(head[1]) if len(head) > 1 else None)
            strings.append((kind, typ, [int(lines[k + 1 + j].split()[0]) - 1 for j in range(n)]))
            k += 1 + n
    return xy, np.array(tri), strings, ids


def boundary_of(tri):
    count = {}
    for t in tri:
        for j in range(3):
            e = tuple(sorted((int(t[j]), int(t[(j + 1) % 3]))))
            count[e] = count.get(e, 0) + 1
    return {e for e, c in count.items() if c == 1}


def check_strings(name, strings, boundary, adcirc):
    """Every boundary edge listed once, nothing else listed; closed loops closed: ADCIRC's
    islands (IBTYPE 21) repeat their first node, SCHISM's (flag 1) close without it; a
    mainland loop (no open boundary) repeats its first node in both."""
    listed = {}
    closed_ok = True
    for kind, typ, nodes in strings:
        edges = list(zip(nodes, nodes[1:]))
        island = kind == "land" and typ == (21 if adcirc else 1)
        if island and adcirc:
            closed_ok &= len(nodes) > 3 and nodes[0] == nodes[-1]
        if island and not adcirc:
            closed_ok &= len(nodes) >= 3 and nodes[0] != nodes[-1]
            edges.append((nodes[-1], nodes[0]))
        for a, b in edges:
            e = tuple(sorted((a, b)))
            listed[e] = listed.get(e, 0) + 1
    twice = sum(1 for c in listed.values() if c > 1)
    missing = boundary - set(listed)
    extra = set(listed) - boundary
    check(not twice and not missing and not extra,
          f"{name}: {len(boundary)} boundary edges, each listed once ({len(missing)} missing, {twice} listed twice, "
          f"{len(extra)} not boundary)")
    check(closed_ok, f"{name}: island loops closed as the format closes them")
    # Every list that ends where it starts is a closed loop; the rest end on an open boundary.
    ends = {}
    for kind, typ, nodes in strings:
        if nodes[0] != nodes[-1] and not (kind == "land" and typ == (21 if adcirc else 1)):
            for v in (nodes[0], nodes[-1]):
                ends[v] = ends.get(v, 0) + 1
    check(all(c % 2 == 0 for c in ends.values()), f"{name}: every open string's ends meet another string's")


def run_case(stereomesh, script, tmp, with_python):
    stats_path = os.path.join(tmp, "stats.json")
    run = subprocess.run([stereomesh, "-0", os.path.join(HERE, script), "-setstring", "OutDir", tmp,
                          "--stats", stats_path], capture_output=True, text=True)
    check(run.returncode == 0, f"{script}: stereomesh ran")
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        return
    m = re.search(r"^Mesh: (\d+) nodes, (\d+) triangles", run.stderr, re.M)
    summary = (int(m.group(1)), int(m.group(2))) if m else None
    with open(stats_path) as f:
        stats = json.load(f)
    name = os.path.splitext(script)[0]

    # MSH 4.1 through Gmsh's reader: the reference numbering.
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(os.path.join(tmp, "out.msh"))
    tags, coords, _ = gmsh.model.mesh.getNodes()
    order = np.argsort(tags)
    tags, xyz = tags[order], coords.reshape(-1, 3)[order]
    types, _, enodes = gmsh.model.mesh.getElements(2)
    tri = np.concatenate([n for t, n in zip(types, enodes) if t == 2]).reshape(-1, 3).astype(np.int64) - 1
    gmsh.finalize()
    nn, nt = len(tags), len(tri)
    check(np.array_equal(tags, np.arange(1, nn + 1)), f"{name}: MSH 4.1 node tags run 1..{nn}")
    used = np.zeros(nn, bool)
    used[tri.ravel()] = True
    check(used.all(), f"{name}: MSH 4.1: every node is a triangle's ({(~used).sum()} unused of {nn})")
    check(summary == (nn, nt), f"{name}: summary {summary} = MSH 4.1 ({nn} nodes, {nt} triangles)")
    check((stats.get("nodes"), stats.get("triangles")) == (nn, nt),
          f"{name}: --stats ({stats.get('nodes')} nodes, {stats.get('triangles')} triangles) = MSH 4.1")
    ll = lonlat_of(xyz)

    # MSH 2.2 and VTK through meshio.
    for f, label in (("out22.msh", "MSH 2.2"), ("out.vtk", "VTK")):
        mm = meshio.read(os.path.join(tmp, f))
        t = np.concatenate([c.data for c in mm.cells if c.type == "triangle"])
        check(len(mm.points) == nn and np.allclose(mm.points, xyz, rtol=0, atol=1e-6 * R),
              f"{name}: {label}: {len(mm.points)} nodes, node i at the MSH 4.1 node i")
        check(t.shape == tri.shape and np.array_equal(t, tri), f"{name}: {label}: the same {len(t)} triangles in order")

    # UGRID through netCDF4-python (faces may be turned anticlockwise: compared as sets).
    nc = netCDF4.Dataset(os.path.join(tmp, "out.nc"))
    cart = np.stack([nc.variables[f"mesh2d_node_cartesian_{c}"][:] for c in "xyz"], axis=1)
    nll = np.stack([nc.variables["mesh2d_node_x"][:], nc.variables["mesh2d_node_y"][:]], axis=1)
    faces = np.ma.filled(nc.variables["mesh2d_face_nodes"][:], -1)
    nc.close()
    check(len(cart) == nn and np.allclose(cart, xyz, rtol=0, atol=1e-6 * R) and same_lonlat(nll, ll, 1e-9),
          f"{name}: UGRID: {len(cart)} nodes, node i at the MSH 4.1 node i")
    check(faces.shape == tri.shape and np.array_equal(np.sort(faces, axis=1), np.sort(tri, axis=1)),
          f"{name}: UGRID: the same {len(faces)} faces in order")

    # fort.14, hgrid.gr3 and hgrid.ll through the parser above.
    boundary = boundary_of(tri)
    for f, adcirc in (("fort.14", True), ("hgrid.gr3", False), ("hgrid.ll", False)):
        gll, gtri, strings, ids = parse_grid(os.path.join(tmp, f))
        check(len(gll) == nn and ids == list(range(1, nn + 1)) and same_lonlat(gll, ll, 1e-9),
              f"{name}: {f}: {len(gll)} nodes, node i at the MSH 4.1 node i")
        check(gtri.shape == tri.shape and np.array_equal(gtri, tri), f"{name}: {f}: the same {len(gtri)} triangles in order")
        if f != "hgrid.ll":
            check_strings(f"{name}: {f}", strings, boundary, adcirc)

    # The Python module's arrays, when it is built beside the program (the Gulf only: the
    # World's second run would double the test's time).
    pydir = os.path.join(os.path.dirname(os.path.abspath(stereomesh)), "python")
    if with_python and os.path.isdir(pydir):
        sys.path.insert(0, pydir)
        try:
            import stereomesh as sm
        except ImportError:
            sm = None
        sys.path.remove(pydir)
        if sm:
            p = sm.run(os.path.join(HERE, script), setstring={"OutDir": tmp + "/py"}, dim=0)
            check(p.nodes_xyz.shape == xyz.shape and np.allclose(p.nodes_xyz, xyz, rtol=0, atol=1e-6 * R),
                  f"{name}: Python nodes_xyz: node i at the MSH 4.1 node i")
            check(np.array_equal(p.triangles, tri), f"{name}: Python triangles: the same, in order")
            pe = {tuple(sorted(e)) for e in p.boundary_edges.tolist()}
            check(pe == boundary, f"{name}: Python boundary_edges: the mesh's {len(boundary)} boundary edges")


def main():
    stereomesh = sys.argv[1]
    for script, with_python in (("outputs_world.geo", False), ("outputs_gulf.geo", True)):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "py"))
            run_case(stereomesh, script, tmp, with_python)


main()
finish()
