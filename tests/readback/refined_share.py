#!/usr/bin/python3
"""Figure 14's refined share, measured on the mesh: the Great Barrier Reef example meshed
with Mesh.NodeData = "criterion", read by Gmsh's own reader; a triangle is in the refined
region when most of its nodes have their size set by the Lizard Island criterion (the
field of the background Min that gives the smallest size there). The paper has 70% of
20,384 elements in its refined region; the share printed here is ours (docs/examples.md).

    refined_share.py STEREOMESH
Exit 0: the checks hold; 1: a check failed; 77: a reader is missing.
"""
import collections
import os
import subprocess
import sys
import tempfile

from readback import HERE, check, finish
import gmsh


def main(stereomesh):
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([stereomesh, "-0", os.path.join(HERE, "refined_share_gbr.geo"), "-setstring", "OutDir",
                              out], capture_output=True, text=True)
        check(run.returncode == 0, "the Great Barrier Reef meshed")
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            return
        lizard = int(next(l.split()[1] for l in run.stdout.splitlines() if l.startswith("LizardField ")))
        gmsh.initialize(["-v", "0"])
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(os.path.join(out, "gbr.msh"))
        view = gmsh.view.getTags()[0]
        _, tags, data, _, _ = gmsh.view.getModelData(view, 0)
        criterion = {int(t): int(round(v[0])) for t, v in zip(tags, data)}
        _, nodes = gmsh.model.mesh.getElementsByType(2)
        gmsh.finalize()
    triangles = nodes.reshape(-1, 3)
    by = collections.Counter(
        collections.Counter(criterion[int(n)] for n in t).most_common(1)[0][0] for t in triangles)
    share = by[lizard] / len(triangles)
    print(f"{len(triangles)} triangles, {share:.1%} of them sized by the Lizard Island criterion "
          f"(Field[{lizard}]); the paper: 70% of 20,384 in its refined region")
    check(len(triangles) > 20000 and len(triangles) < 30000, f"triangle count {len(triangles)} near the paper's 20,384")
    # 54.7% when written: the test keeps it within 5 points.
    check(abs(share - 0.547) < 0.05, f"refined share {share:.3f} within 0.05 of 0.547")


main(sys.argv[1])
finish()
