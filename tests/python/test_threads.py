"""stereomesh.run from several Python threads at once (two threads calling it
deadlocked): the GIL is released around the C++ work, each run has its own interpreter,
and every mesh equals the one the same call makes alone, on 2 and on 8 threads."""
import concurrent.futures
import os

import numpy as np
import pytest

import stereomesh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GULF = os.path.join(ROOT, "examples", "gulf_of_mexico.geo")

# A square with a narrow inlet, meshed at one size with a quality floor.
INLET = """Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0.505, 1, 0};
Point(5) = {0.505, 0.6, 0}; Point(6) = {0.495, 0.6, 0}; Point(7) = {0.495, 1, 0}; Point(8) = {0, 1, 0};
For i In {1:8} Line(i) = {i, (i % 8) + 1}; EndFor
Curve Loop(1) = {1:8}; Plane Surface(1) = {1};
Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeExtendFromBoundary = 0;
DefineConstant[ Size = 0.05, Floor = 0.3 ];
Mesh.MeshSizeMax = Size; Mesh.QualityFloor = Floor;
"""


@pytest.fixture(scope="module")
def calls(tmp_path_factory):
    d = tmp_path_factory.mktemp("threads")
    inlet = d / "inlet.geo"
    inlet.write_text(INLET)
    out = [(GULF, {"ShoreSizeMin": s}) for s in (40e3, 60e3)]
    out += [(str(inlet), {"Size": s, "Floor": q}) for s, q in ((0.05, 0.3), (0.04, 0.5), (0.03, 0.7), (0.06, 0.9))]
    return out


def one(call):
    path, numbers = call
    m = stereomesh.run(path, setnumber=numbers, threads=1)
    return m.nodes_xyz, m.triangles, m.printed


def same(a, b):
    return all(np.array_equal(x, y) if isinstance(x, np.ndarray) else x == y for x, y in zip(a, b))


@pytest.mark.parametrize("workers", [2, 8])
def test_concurrent_runs_equal_serial(calls, workers):
    serial = [one(c) for c in calls]
    # Each call several times, interleaved, so that runs overlap.
    jobs = calls * 2
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        futures = [pool.submit(one, c) for c in jobs]
        # A deadlock fails here (instead of hanging the test run).
        results = [f.result(timeout=120) for f in futures]
    for i, r in enumerate(results):
        assert same(r, serial[i % len(calls)]), f"call {i % len(calls)} differs on {workers} threads"


def test_errors_from_threads_are_script_errors(tmp_path):
    bad = tmp_path / "bad.geo"
    bad.write_text("Point(1) = {0, 0, 0;\n")
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        futures = [pool.submit(stereomesh.run, str(bad)) for _ in range(8)]
        for f in futures:
            with pytest.raises(stereomesh.ScriptError) as e:
                f.result(timeout=60)
            assert e.value.line == 1
