"""What the read-back checks share: the readers (a missing one skips the check with exit
77), a check() that prints each result, running stereomesh on a script of this folder with
OutDir set, and the exit status."""
import importlib
import os
import subprocess
import sys

try:
    import gmsh  # noqa: F401  (the checks import what they use from here)
    import netCDF4  # noqa: F401
    import numpy as np  # noqa: F401
except ImportError as e:  # the CI installs them (.ci/deps)
    print(f"skipped: {e}")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def gmsh_nodes(path, periodic=False):
    """Opens PATH in Gmsh's reader, quietly, and gives its nodes as {tag: xyz}; the model stays
    open for the caller's further queries (the caller ends with gmsh.finalize()). With
    `periodic`, the $Periodic section is read (MSH 2.2's is skipped otherwise)."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Verbosity", 0)
    if periodic:
        gmsh.option.setNumber("Mesh.IgnorePeriodicity", 0)
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return dict(zip(tags.tolist(), coords.reshape(-1, 3)))


def run_script(stereomesh, script, out_dir, extra=(), what=None):
    """stereomesh -0 SCRIPT -setstring OutDir OUT_DIR [EXTRA...]: the finished run (its stdout
    holds the script's Printf lines), or None (a failed check) if it fails. With `what`, its
    success is a check of that name too."""
    run = subprocess.run([stereomesh, "-0", os.path.join(HERE, script), "-setstring", "OutDir", out_dir, *extra],
                         capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
    if run.returncode != 0 or what:
        check(run.returncode == 0, what or "stereomesh ran")
    return run if run.returncode == 0 else None


def reader(name):
    """The module `name`, or exit 77 (the check is skipped) when it is not installed."""
    try:
        return importlib.import_module(name)
    except ImportError as e:  # the CI installs it (.ci/deps)
        print(f"skipped: {e}")
        sys.exit(77)


def finish():
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
