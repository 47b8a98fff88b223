#!/usr/bin/python3
"""Outputs never replace inputs or each other: -o, --stats and --diagnostics
naming the script (directly, through a symbolic link or another spelling), an Included
file, a data file the run reads (ListFromFile), or one another are refused, as is a
script's Save naming an Included file, '-' may be
used by one output only, '-o ""' is a usage error, and a script named x.msh meshed
without -o is not replaced. Each refused run leaves every file as it was.

    outputs_clobber.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed).
"""
import os
import subprocess
import sys
import tempfile

from checks import check, exit_status, main_with_binary


SCRIPT = """Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
"""



def run(stereomesh, d, args):
    return subprocess.run([stereomesh] + args, cwd=d, capture_output=True, text=True, timeout=120)


def snapshot(d):
    out = {}
    for name in sorted(os.listdir(d)):
        p = os.path.join(d, name)
        if os.path.isfile(p) and not os.path.islink(p):
            with open(p, "rb") as f:
                out[name] = f.read()
    return out


def refused(stereomesh, d, args, status, says, what):
    before = snapshot(d)
    r = run(stereomesh, d, args)
    check(r.returncode == status, f"{what}: exit {r.returncode} (want {status})")
    check(says in r.stderr, f"{what}: says '{says}'" + ("" if says in r.stderr else f" (stderr: {r.stderr[-300:]!r})"))
    after = snapshot(d)
    check(all(after.get(k) == v for k, v in before.items()), f"{what}: every file as it was")


def main(stereomesh):
    with tempfile.TemporaryDirectory() as d:
        def write(name, text):
            with open(os.path.join(d, name), "w") as f:
                f.write(text)
        write("t.geo", SCRIPT)
        write("x.msh", SCRIPT)   # a script with a mesh's name
        write("inc.geo", SCRIPT)
        write("top.geo", 'Include "inc.geo";\n')
        write("nums.txt", "1 2 3\n")
        write("data.geo", SCRIPT + 'n[] = ListFromFile("nums.txt");\nPrintf("%g numbers", #n[]);\n')
        write("part.msh", SCRIPT)   # a script with a mesh's name, Included
        write("saver.geo", 'Include "part.msh";\nMesh 2;\nSave "part.msh";\n')
        os.symlink("t.geo", os.path.join(d, "link.msh"))
        os.mkdir(os.path.join(d, "sub"))
        usage = 2
        refused(stereomesh, d, ["-2", "t.geo", "-o", "t.geo", "-format", "msh"], usage,
                "is the script", "-o naming the script")
        refused(stereomesh, d, ["-2", "t.geo", "-o", "link.msh"], usage,
                "is the script", "-o naming the script through a symbolic link")
        refused(stereomesh, d, ["-2", "t.geo", "-o", "sub/../t.geo", "-format", "msh"], usage,
                "is the script", "-o naming the script as sub/../t.geo")
        refused(stereomesh, d, ["-2", "t.geo", "--stats", "t.geo"], usage, "is the script", "--stats naming the script")
        refused(stereomesh, d, ["-0", "t.geo", "--diagnostics", "./t.geo"], usage, "is the script",
                "--diagnostics naming the script")
        refused(stereomesh, d, ["-2", "x.msh"], usage, "name the mesh file with -o",
                "a script named x.msh meshed without -o")
        refused(stereomesh, d, ["-2", "t.geo", "-o", "m.msh", "--stats", "m.msh"], usage, "are the same file",
                "-o and --stats naming one new file")
        refused(stereomesh, d, ["-2", "t.geo", "-o", "m.msh", "--diagnostics", "sub/../m.msh"], usage,
                "are the same file", "-o and --diagnostics naming one new file two ways")
        refused(stereomesh, d, ["-2", "t.geo", "-o", "-", "--stats", "-"], usage, "standard output",
                "'-' for two outputs")
        refused(stereomesh, d, ["-2", "t.geo", "-o", ""], usage, "not an empty one", "-o ''")
        refused(stereomesh, d, ["-2", "t.geo", "--stats", ""], usage, "not an empty one", "--stats ''")
        # Known only as the run reads them: refused when the output is written.
        refused(stereomesh, d, ["-2", "top.geo", "-o", "inc.geo", "-format", "msh"], 1, "an input of this run",
                "-o naming an Included file")
        refused(stereomesh, d, ["-2", "top.geo", "--stats", "inc.geo"], 1, "an input of this run",
                "--stats naming an Included file")
        refused(stereomesh, d, ["-2", "data.geo", "-o", "nums.txt", "-format", "msh"], 1, "an input of this run",
                "-o naming a data file the run reads")
        refused(stereomesh, d, ["-0", "data.geo", "--diagnostics", "nums.txt"], 1, "an input of this run",
                "--diagnostics naming a data file the run reads")
        refused(stereomesh, d, ["-0", "saver.geo"], 1, "an input of this run",
                "Save in a script naming an Included file")
        # What is allowed still works: distinct outputs, one of them '-'.
        r = run(stereomesh, d, ["-2", "t.geo", "-o", "-", "--stats", "s.json", "--diagnostics", "d.jsonl"])
        check(r.returncode == 0 and r.stdout.startswith("$MeshFormat") and os.path.exists(os.path.join(d, "s.json")),
              "-o -, --stats and --diagnostics to three places: written")
        r = run(stereomesh, d, ["-2", "x.msh", "-o", "x_mesh.msh"])
        check(r.returncode == 0 and os.path.exists(os.path.join(d, "x_mesh.msh")), "x.msh meshed with -o: written")
    return exit_status()


if __name__ == "__main__":
    main_with_binary(main)
