#!/usr/bin/python3
"""Periodic surfaces read back by Gmsh (periodic_surface_rotation.geo): Gmsh's reader
(python3-gmsh) must load the MSH 4.1 and 2.2 files with their $Periodic section and see
surface 12 as a copy of surface 11: as many triangles, every node of surface 12 (its
boundary included) listed once with its master's node, each the master's turned by the
map written with them, which turns point 2 onto point 3 (a third of a turn about z). And
(periodic_surface_flip.geo) a copy onto a surface whose loop runs the other way has its
triangles reversed: surface 1's all turn counter-clockwise, surface 2's all clockwise.
And (periodic_surface_forms.geo) the forms with a transform, Translate, Rotate and Affine, a
chain (surface 5 copies surface 2, a copy of surface 1) and a source with an embedded point
and curve: each copy has its source's triangles, its link lists every node of them (the
embedded ones included) and each node is its master's moved by the map written with them.

    periodic_surface_readers.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: a reader is missing.
"""
import math
import os
import sys
import tempfile

from readback import check, finish, gmsh_nodes, run_script  # exits 77 when a reader is missing
import gmsh
import numpy as np


def surface_elements(s):
    """Surface s of the open model: its triangle count and the nodes of its elements (MSH
    2.2 keeps no entity's boundary, so a link is checked against these)."""
    types, elements, element_nodes = gmsh.model.mesh.getElements(2, s)
    nodes = set()
    for n in element_nodes:
        nodes.update(n.tolist())
    return sum(len(e) for t, e in zip(types, elements) if t == 2), nodes


def surface_view(path):
    """(master, node pairs' coordinates (slave, master), affine map, the nodes of surface
    12's triangles, the nodes the link lists, triangles of surfaces 11 and 12) as Gmsh's
    reader sees them."""
    xyz = gmsh_nodes(path, periodic=True)
    master, nodes, master_nodes, affine = gmsh.model.mesh.getPeriodicNodes(2, 12)
    pairs = [(xyz[a], xyz[b]) for a, b in zip(nodes.tolist(), master_nodes.tolist())]
    (source_triangles, _), (target_triangles, own) = surface_elements(11), surface_elements(12)
    triangles = [source_triangles, target_triangles]
    listed = sorted(nodes.tolist())
    gmsh.finalize()
    return master, pairs, list(affine), sorted(own), listed, triangles


def turns(path):
    """Per surface 1 and 2: the signs of its triangles' areas about z."""
    xyz = gmsh_nodes(path)
    out = {}
    for s in (1, 2):
        _, _, element_nodes = gmsh.model.mesh.getElements(2, s)
        tri = element_nodes[0].reshape(-1, 3).tolist() if element_nodes else []
        out[s] = {int(np.sign(np.cross(xyz[b] - xyz[a], xyz[c] - xyz[a])[2])) for a, b, c in tri}, len(tri)
    gmsh.finalize()
    return out


def copy_view(path, copies):
    """Per (target, source) of `copies`: the target's master, the largest distance of a node
    from its master's image by the written map, whether the link lists exactly the nodes of
    the target's triangles, and both surfaces' triangle counts, as Gmsh's reader sees them."""
    xyz = gmsh_nodes(path, periodic=True)
    out = []
    for target, source in copies:
        master, nodes, master_nodes, affine = gmsh.model.mesh.getPeriodicNodes(2, target)
        m = np.array(affine).reshape(4, 4) if len(affine) == 16 else np.full((4, 4), np.nan)
        err = max((float(np.linalg.norm(xyz[a] - m.dot(np.append(xyz[b], 1))[:3]))
                   for a, b in zip(nodes.tolist(), master_nodes.tolist())), default=1.0)
        (target_triangles, own), (source_triangles, _) = surface_elements(target), surface_elements(source)
        counts = [target_triangles, source_triangles]
        out.append((master, err, sorted(nodes.tolist()) == sorted(own), counts))
    gmsh.finalize()
    return out


def main():
    stereomesh = sys.argv[1]
    with tempfile.TemporaryDirectory() as out:
        if not run_script(stereomesh, "periodic_surface_rotation.geo", out, what="stereomesh ran"):
            finish()
            return
        for name in ["rotation.msh", "rotation22.msh"]:
            master, pairs, affine, own, listed, triangles = surface_view(os.path.join(out, name))
            check(master == 11, f"{name}: surface 12's master is surface {master} (want 11)")
            check(triangles[0] == triangles[1] and triangles[0] > 20,
                  f"{name}: surfaces 11 and 12 have {triangles[0]} and {triangles[1]} triangles")
            check(listed == own, f"{name}: the link lists {len(listed)} nodes, surface 12's triangles have {len(own)}")
            check(len(affine) == 16, f"{name}: the map has {len(affine)} numbers")
            if len(affine) != 16:
                continue
            m = np.array(affine).reshape(4, 4)
            turn = 2 * math.pi / 3
            p2 = np.array([0.0005, 0, 0, 1])
            want = np.array([0.0005 * math.cos(turn), 0.0005 * math.sin(turn), 0])
            check(np.linalg.norm(m.dot(p2)[:3] - want) < 1e-15, f"{name}: the map turns point 2 onto point 3")
            err = max((float(np.linalg.norm(a - m.dot(np.append(b, 1))[:3])) for a, b in pairs), default=1.0)
            check(err < 1e-12, f"{name}: each node of surface 12 is its master's turned ({err:.2g})")
        if run_script(stereomesh, "periodic_surface_flip.geo", out, what="stereomesh ran the reversed loop"):
            t = turns(os.path.join(out, "flip.msh"))
            check(t[1][1] == t[2][1] and t[1][1] > 20, f"flip.msh: surfaces 1 and 2 have {t[1][1]} and {t[2][1]} triangles")
            check(t[1][0] == {1} and t[2][0] == {-1},
                  f"flip.msh: surface 1's triangles turn {t[1][0]}, surface 2's {t[2][0]} (want {{1}}, {{-1}})")
        if run_script(stereomesh, "periodic_surface_forms.geo", out, what="stereomesh ran the transforms"):
            copies = [(2, 1), (3, 1), (4, 1), (5, 2)]
            for name in ["forms.msh", "forms22.msh"]:
                for (target, source), (master, err, listed, counts) in zip(copies, copy_view(os.path.join(out, name), copies)):
                    what = f"{name}: surface {target}"
                    check(master == source, f"{what}'s master is surface {master} (want {source})")
                    check(counts[0] == counts[1] and counts[0] > 100,
                          f"{what} has {counts[0]} triangles, surface {source} {counts[1]}")
                    check(listed, f"{what}: the link lists the nodes of its triangles")
                    check(err < 1e-12, f"{what}: each node is its master's moved by the map ({err:.2g})")
    finish()


main()
