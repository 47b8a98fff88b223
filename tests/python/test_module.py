"""The Python module (src/python): run() meshes a real ocean script in the process and hands
the mesh over as numpy arrays that agree with the .msh of the same script read by Gmsh's
own reader; errors raise ScriptError with the place. Run by CTest (python_module) with
PYTHONPATH at build/python and STEREOMESH at the executable."""
import os
import subprocess
import tempfile

import numpy as np
import pytest

import stereomesh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GULF = os.path.join(ROOT, "examples", "gulf_of_mexico.geo")


@pytest.fixture(scope="module")
def gulf():
    return stereomesh.run(GULF, setnumber={"ShoreSizeMin": 20e3}, algo="front2d", threads=2)


def test_arrays_are_the_mesh(gulf):
    n = len(gulf.nodes_xyz)
    assert gulf.nodes_xyz.shape == (n, 3) and gulf.nodes_lonlat.shape == (n, 2)
    assert gulf.triangles.dtype == np.int64 and gulf.triangles.shape[1] == 3
    assert gulf.triangles.min() == 0 and gulf.triangles.max() == n - 1   # every node is used
    assert len(gulf.triangles) == gulf.stats["triangles"]
    lon, lat = gulf.nodes_lonlat[:, 0], gulf.nodes_lonlat[:, 1]
    assert -98.01 < lon.min() and lon.max() < -75.99 and 6.99 < lat.min() and lat.max() < 31.01
    r = np.linalg.norm(gulf.nodes_xyz, axis=1)
    assert np.allclose(r, r[0], rtol=1e-9)          # on the Earth's sphere
    assert np.allclose(np.degrees(np.arcsin(gulf.nodes_xyz[:, 2] / r)), lat, atol=1e-9)


def test_boundary_depth_and_size(gulf):
    e = gulf.boundary_edges
    assert e.shape == (len(gulf.boundary_physical), 2) and len(e) > 100
    # Each boundary edge is a side of exactly one triangle.
    sides = {}
    for t in gulf.triangles:
        for k in range(3):
            key = tuple(sorted((t[k], t[(k + 1) % 3])))
            sides[key] = sides.get(key, 0) + 1
    assert all(sides.get(tuple(sorted(p))) == 1 for p in e)
    assert sum(1 for v in sides.values() if v == 1) == len(e)
    assert set(gulf.boundary_physical.tolist()) == {2, 3}   # coast, open (the example's groups)
    assert gulf.depth.shape == (len(gulf.nodes_xyz),) and gulf.depth.min() >= 5 and gulf.depth.max() < 11000
    assert gulf.size.min() >= 5e3 * 0.999 and gulf.size.max() <= 60e3 * 1.001
    assert gulf.stats["dt"] > 0


def test_same_mesh_as_the_command_line(gulf):
    """The executable with the same settings writes the same triangles (Gmsh's reader)."""
    gmsh = pytest.importorskip("gmsh")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "gulf.msh")
        subprocess.run([os.environ["STEREOMESH"], "-2", "-v", "0", "-nt", "2", "-algo", "front2d", GULF,
                        "-setnumber", "ShoreSizeMin", "20e3", "-o", out], check=True)
        gmsh.initialize(["-v", "0"])
        gmsh.open(out)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        xyz = dict(zip(tags.tolist(), coords.reshape(-1, 3)))
        tri = []
        for block in gmsh.model.mesh.getElements(2)[2]:
            tri += [block[i:i + 3] for i in range(0, len(block), 3)]
        gmsh.finalize()
    point = lambda p: tuple(np.round(p, 3))
    ours = {frozenset(point(gulf.nodes_xyz[v]) for v in t) for t in gulf.triangles}
    theirs = {frozenset(point(xyz[v]) for v in t) for t in tri}
    assert ours == theirs


def test_partitions(gulf):
    """Mesh.NbPartitions: the triangles' parts as the VTK file of the executable has them,
    each node's the smallest of its triangles'; None without."""
    assert gulf.partition is None and gulf.node_partition is None
    m = stereomesh.run(GULF, setnumber={"ShoreSizeMin": 20e3, "Mesh.NbPartitions": 3}, algo="front2d", threads=2)
    assert m.partition.shape == (len(m.triangles),) and m.node_partition.shape == (len(m.nodes_xyz),)
    counts = np.bincount(m.partition)[1:]
    assert len(counts) == 3 and counts.max() <= 1.03 * len(m.triangles) / 3
    assert m.stats["partitions"] == 3 and m.stats["partition_edge_cut"] > 0
    smallest = np.full(len(m.nodes_xyz), 4)
    for k in range(3):
        np.minimum.at(smallest, m.triangles[:, k], m.partition)
    assert np.array_equal(smallest, m.node_partition)
    meshio = pytest.importorskip("meshio")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "gulf.vtk")
        subprocess.run([os.environ["STEREOMESH"], "-2", "-v", "0", "-nt", "2", "-algo", "front2d", "-part", "3", GULF,
                        "-setnumber", "ShoreSizeMin", "20e3", "-o", out], check=True)
        vtk = meshio.read(out)
    point = lambda p: tuple(np.round(p, 3))
    ours = {frozenset(point(m.nodes_xyz[v]) for v in t): p for t, p in zip(m.triangles, m.partition)}
    theirs = {frozenset(point(vtk.points[v]) for v in t): int(p)
              for t, p in zip(vtk.cells[0].data, np.ravel(vtk.cell_data["partition"][0]))}
    assert ours == theirs


def test_evaluate_only_and_printf():
    with tempfile.TemporaryDirectory() as tmp:
        geo = os.path.join(tmp, "p.geo")
        with open(geo, "w") as f:
            f.write('DefineConstant[ x = 3 ];\nPrintf("x = %g", x);\nWarning("look");\n')
        m = stereomesh.run(geo, setnumber={"x": 4}, dim=0)
    assert m.printed == "x = 4\n"
    assert [d["kind"] for d in m.diagnostics] == ["user-warning"]
    assert m.diagnostics[0]["line"] == 3
    assert len(m.triangles) == 0 and m.stats is None


def test_curves_only_stats_and_repairs_with_places():
    # dim=1: the 1D figures as -1 prints them, along the Earth's sphere; each coastline
    # repair is a diagnostic with its lon/lat, as --diagnostics FILE writes it.
    m = stereomesh.run(GULF, dim=1)
    assert m.stats["line_elements"] > 100 and m.stats["edge_units"] == "m"
    assert 0 < m.stats["edge_min"] < m.stats["edge_max"] < 100e3
    repairs = [d for d in m.diagnostics if d["kind"] in ("coastline-repair", "coastline-passage")]
    placed = [d for d in repairs if "what" in d]
    assert len(placed) > 20
    assert all(-98.01 < d["lon"] < -75.99 and 6.99 < d["lat"] < 31.01 for d in placed)


def test_script_error_carries_the_place():
    with tempfile.TemporaryDirectory() as tmp:
        geo = os.path.join(tmp, "bad.geo")
        with open(geo, "w") as f:
            f.write("Point(1) = {0, 0, 0};\nLine(1) = {1, 7};\n")
        with pytest.raises(stereomesh.ScriptError) as err:
            stereomesh.run(geo)
    e = err.value
    assert (e.file, e.line) == (geo, 2) and e.column >= 1
    assert "7" in e.message and str(e).startswith(f"{geo}:2:")
    assert any(d["severity"] == "error" for d in e.diagnostics)


def test_bad_arguments():
    with pytest.raises(ValueError, match="unknown algorithm"):
        stereomesh.run(GULF, algo="delaunay")
    with pytest.raises(ValueError, match="dim"):
        stereomesh.run(GULF, dim=3)


def test_quadrangles():
    """A transfinite recombined rectangle: its 8 x 4 quadrangles, no triangle; the ocean
    mesh has none."""
    script = os.path.join(ROOT, "tests", "scripts", "structured", "transfinite_square.geo")
    m = stereomesh.run(script)
    assert m.quads.shape == (32, 4) and m.triangles.shape == (0, 3)
    assert m.quads.min() == 0 and m.quads.max() == len(m.nodes_xyz) - 1
    assert m.stats["quadrangles"] == 32
