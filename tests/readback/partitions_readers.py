#!/usr/bin/python3
"""Mesh partitions read back by other programs' readers (partitions_gulf.geo): Gmsh
(python3-gmsh) must see 4 partitions in the partitioned MSH 4.1, every triangle in exactly
one partitioned surface of one part, the parts within 3% of the mean, the same in binary
MSH 4.1, and in each
split file x_N.msh exactly part N's triangles; meshio (python3-meshio) reads the VTK
partition arrays and netCDF4-python the UGRID ones, which must agree with the MSH; the
edge cut in --stats is the count of triangle sides between parts; and the files are the
same bytes with -nt 1 and -nt 2.

    partitions_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import collections
import json
import os
import sys
import tempfile

from readback import check, finish, reader, run_script  # exits 77 when a reader is missing
import gmsh
import netCDF4
import numpy as np

meshio = reader("meshio")

PARTS = 4
FILES = ["gulf.msh", "gulf_bin.msh", "gulf.vtk", "gulf.nc"] + [f"split_{k}.msh" for k in range(1, PARTS + 1)]


def run(stereomesh, out_dir, threads):
    return run_script(stereomesh, "partitions_gulf.geo", out_dir,
                      extra=["-nt", str(threads), "--stats", os.path.join(out_dir, "stats.json")],
                      what=f"stereomesh -nt {threads} ran")


def triangles_by_part(path):
    """{part: [triangle as a frozenset of rounded node points]}, the partition count Gmsh
    reports, and the entity partition lists, from Gmsh's reader."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Verbosity", 0)
    gmsh.open(path)
    n_parts = gmsh.model.getNumberOfPartitions() if hasattr(gmsh.model, "getNumberOfPartitions") else None
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = {t: tuple(np.round(c, 3)) for t, c in zip(tags.tolist(), coords.reshape(-1, 3))}
    parts = collections.defaultdict(list)
    seen_parts = set()
    interface_lines = 0
    for dim, tag in gmsh.model.getEntities():
        p = list(gmsh.model.getPartitions(dim, tag))
        seen_parts.update(p)
        if dim == 1 and len(p) == 2:
            check(gmsh.model.getParent(dim, tag)[0] == 2, f"{path}: interface curve {tag}'s parent is a surface")
            interface_lines += sum(len(t) for t in gmsh.model.mesh.getElements(1, tag)[1])
        if dim != 2:
            continue
        _, _, enodes = gmsh.model.mesh.getElements(2, tag)
        for block in enodes:
            tri = [frozenset(xyz[v] for v in block[i:i + 3]) for i in range(0, len(block), 3)]
            if tri:
                check(len(p) == 1, f"{path}: surface {tag} with triangles is in one partition ({p})")
                parts[p[0] if p else 0] += tri
    gmsh.finalize()
    triangles_by_part.interface_lines = interface_lines
    return parts, n_parts, seen_parts


def nodes_by_tag(path):
    """Gmsh's reader: the node tags and their coordinates, by tag."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Verbosity", 0)
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    gmsh.finalize()
    order = np.argsort(tags)
    return tags[order], coords.reshape(-1, 3)[order]


def sides_between_parts(parts):
    owner = collections.defaultdict(set)
    for p, tris in parts.items():
        for t in tris:
            pts = sorted(t)
            for a in range(3):
                for b in range(a + 1, 3):
                    owner[(pts[a], pts[b])].add(p)
    return sum(1 for s in owner.values() if len(s) == 2)


def main():
    with tempfile.TemporaryDirectory() as one, tempfile.TemporaryDirectory() as two:
        if not run(sys.argv[1], one, 1) or not run(sys.argv[1], two, 2):
            return
        for f in FILES:
            same = open(os.path.join(one, f), "rb").read() == open(os.path.join(two, f), "rb").read()
            check(same, f"{f}: the same bytes with -nt 1 and -nt 2")
        stats = json.load(open(os.path.join(one, "stats.json")))
        parts, n_parts, seen = triangles_by_part(os.path.join(one, "gulf.msh"))
        if n_parts is not None:
            check(n_parts == PARTS, f"gmsh.model.getNumberOfPartitions() = {n_parts}")
        check(seen == set(range(1, PARTS + 1)), f"the entities' partitions are 1..{PARTS}: {sorted(seen)}")
        check(sorted(parts) == list(range(1, PARTS + 1)), f"triangles in partitions {sorted(parts)}")
        every = [t for tris in parts.values() for t in tris]
        check(len(every) == stats["triangles"], f"{len(every)} partitioned triangles, {stats['triangles']} meshed")
        check(len(set(every)) == len(every), "no triangle is in two partitions")
        counts = {p: len(t) for p, t in parts.items()}
        mean = len(every) / PARTS
        check(max(counts.values()) <= 1.03 * mean, f"balance within 3%: {counts}, mean {mean:.1f}")
        check(stats["partitions"] == PARTS, "--stats: partitions")
        check(abs(stats["partition_imbalance"] - max(counts.values()) / mean) < 1e-9,
              f"--stats: imbalance {stats['partition_imbalance']}")
        cut = sides_between_parts(parts)
        check(stats["partition_edge_cut"] == cut, f"--stats: edge cut {stats['partition_edge_cut']}, {cut} sides")
        lines = triangles_by_part.interface_lines
        check(lines == cut, f"the interface curves between parts hold {lines} lines, one per cut side")

        binary, _, _ = triangles_by_part(os.path.join(one, "gulf_bin.msh"))
        check(binary == parts, "binary MSH 4.1: the same partitioned triangles as ASCII")

        # One file per part: Gmsh reads each, holding exactly that part's triangles.
        for k in range(1, PARTS + 1):
            split, _, _ = triangles_by_part(os.path.join(one, f"split_{k}.msh"))
            check(list(split) == [k] and set(split[k]) == set(parts[k]),
                  f"split_{k}.msh: part {k}'s {len(parts[k])} triangles")

        # meshio: the VTK cell and point partition arrays.
        vtk = meshio.read(os.path.join(one, "gulf.vtk"))
        cell_part = np.concatenate(vtk.cell_data["partition"]).ravel()
        vtk_counts = {int(p): int(n) for p, n in zip(*np.unique(cell_part, return_counts=True))}
        check(vtk_counts == counts, f"VTK cell partitions {vtk_counts}")
        point_part = np.asarray(vtk.point_data["partition"]).ravel()
        check(len(point_part) == len(vtk.points) and set(np.unique(point_part)) == set(range(1, PARTS + 1)),
              "VTK point partitions 1..4 at every point")
        # Each point's partition is the smallest of its triangles'.
        smallest = np.full(len(vtk.points), PARTS + 1)
        tri = np.concatenate([c.data for c in vtk.cells])
        for k in range(3):
            np.minimum.at(smallest, tri[:, k], cell_part.astype(int))
        check(np.array_equal(smallest, point_part.astype(int)), "VTK point partition: the smallest of its cells'")

        # One node order (as unpartitioned, io/from_model_mesh.h): MSH node tag t is VTK point
        # and UGRID node t - 1, in the partitioned file and in each split file.
        tags, xyz = nodes_by_tag(os.path.join(one, "gulf.msh"))
        check(np.array_equal(tags, np.arange(1, len(vtk.points) + 1)) and np.allclose(xyz, vtk.points, rtol=0, atol=1e-3),
              f"partitioned MSH node tag t is VTK point t - 1 ({len(tags)} nodes)")
        for k in range(1, PARTS + 1):
            tags, xyz = nodes_by_tag(os.path.join(one, f"split_{k}.msh"))
            check(np.allclose(xyz, vtk.points[tags - 1], rtol=0, atol=1e-3),
                  f"split_{k}.msh: node tag t is VTK point t - 1 ({len(tags)} nodes)")

        # netCDF4: the UGRID face and node partitions.
        nc = netCDF4.Dataset(os.path.join(one, "gulf.nc"))
        cart = np.stack([nc.variables[f"mesh2d_node_cartesian_{c}"][:] for c in "xyz"], axis=1)
        check(np.allclose(cart, vtk.points, rtol=0, atol=1e-3), "UGRID node i is VTK point i")
        face_part = np.asarray(nc.variables["mesh2d_face_partition"][:])
        nc_counts = {int(p): int(n) for p, n in zip(*np.unique(face_part, return_counts=True))}
        check(nc_counts == counts, f"UGRID face partitions {nc_counts}")
        node_part = np.asarray(nc.variables["mesh2d_node_partition"][:])
        check(len(node_part) == len(nc.dimensions["mesh2d_nNodes"]) and set(np.unique(node_part)) ==
              set(range(1, PARTS + 1)), "UGRID node partitions 1..4 at every node")
        nc.close()


if __name__ == "__main__":
    main()
    finish()
