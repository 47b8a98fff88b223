"""The 2D algorithm names (src/mesh/mesh2d_algorithms.h): the command line's -algo, the
interpreter's Mesh.Algorithm and the Python module's algo= accept the same names and
numbers, and refuse the same others. Run by CTest (python_module) with PYTHONPATH at
build/python and STEREOMESH at the executable."""
import os
import re
import subprocess

import pytest

import stereomesh

# Gmsh's -algo names and Mesh.Algorithm numbers that the kernel has; losing one from any
# front end fails below.
EXPECTED = {"meshadapt": 1, "auto": 2, "initial2d": 3, "del2d": 5, "front2d": 6, "delquad": 8}

SQUARE = """Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Printf("algorithm %g", Mesh.Algorithm);
"""


def cli(*args):
    return subprocess.run([os.environ["STEREOMESH"], *args], capture_output=True, text=True)


@pytest.fixture(scope="module")
def square(tmp_path_factory):
    path = tmp_path_factory.mktemp("algo") / "square.geo"
    path.write_text(SQUARE)
    return str(path)


def test_module_lists_the_names():
    assert stereomesh.algorithms == EXPECTED


def test_help_lists_the_names():
    out = cli("--help").stdout
    line = re.search(r"-algo NAME\s+(.*)", out).group(1)
    names = [n.strip() for n in line.split("(")[0].split(",")]
    assert names == list(EXPECTED)


@pytest.mark.parametrize("name", list(EXPECTED))
def test_every_front_end_accepts(name, square, tmp_path):
    number = EXPECTED[name]
    # The command line: -algo NAME sets Mesh.Algorithm and meshes.
    r = cli("-2", "-v", "0", "-algo", name, square, "-o", str(tmp_path / "a.msh"))
    assert r.returncode == 0, r.stderr
    assert f"algorithm {number}" in r.stdout
    # The interpreter: the number set as an option meshes.
    r = cli("-2", "-v", "0", "-setnumber", "Mesh.Algorithm", str(number), square, "-o", str(tmp_path / "b.msh"))
    assert r.returncode == 0, r.stderr
    # The Python module: algo=NAME sets the same number and meshes.
    m = stereomesh.run(square, algo=name)
    assert m.printed.strip() == f"algorithm {number}"
    assert len(m.triangles) > 0


def test_every_front_end_refuses_the_others(square, tmp_path):
    r = cli("-2", "-algo", "bamg", square, "-o", str(tmp_path / "c.msh"))
    assert r.returncode == 2 and "unknown algorithm 'bamg'" in r.stderr
    with pytest.raises(ValueError, match="unknown algorithm 'bamg'"):
        stereomesh.run(square, algo="bamg")
    r = cli("-2", "-setnumber", "Mesh.Algorithm", "7", square, "-o", str(tmp_path / "d.msh"))
    assert r.returncode != 0 and "Mesh.Algorithm 7 is not available" in r.stderr
    with pytest.raises(stereomesh.ScriptError, match="Mesh.Algorithm 7 is not available"):
        stereomesh.run(square, setnumber={"Mesh.Algorithm": 7})
