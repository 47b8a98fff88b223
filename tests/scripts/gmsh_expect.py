#!/usr/bin/env python3
"""Writes the `// expect:` lines of script tests from what `gmsh -0` prints.

Usage: tests/scripts/gmsh_expect.py SCRIPT.geo...   (needs gmsh 4.8.4 on PATH)

Each script runs in a scratch copy of tests/scripts/ (gmsh writes .geo_unrolled
next to it, and relative Includes keep working). Printf lines are gmsh's stdout
minus its 'Info    :' lines. Straight-line scripts get the expectation on each
Printf line; scripts with loops, macros or includes get a block at the end.
A script on which gmsh reports an error is left untouched.
"""
import os, re, shutil, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.abspath(__file__))
EXPECT = re.compile(r"\s*// expect:.*$")

def gmsh_output(script):
    with tempfile.TemporaryDirectory() as tmp:
        copy = os.path.join(tmp, "scripts")
        shutil.copytree(ROOT, copy)
        # Generated models that scripts Include as ../../data/geo_scripts/... (world_c.geo).
        shutil.copytree(os.path.join(ROOT, "..", "data", "geo_scripts"), os.path.join(tmp, "data", "geo_scripts"))
        rel = os.path.relpath(os.path.abspath(script), ROOT)
        run = subprocess.run(["gmsh", "-0", os.path.basename(rel)], cwd=os.path.join(copy, os.path.dirname(rel)),
                             capture_output=True, text=True)
    lines = [l for l in run.stdout.splitlines() if not l.startswith("Info    :")]
    # gmsh -0 writes .geo_unrolled and cannot export a surface on a PolarSphere: not a script error.
    err = [l for l in run.stderr.splitlines() if not re.match(r"Error   : Skipping surface \d+ in export", l)]
    return lines, "\n".join(err).strip()

def annotate(script):
    lines, err = gmsh_output(script)
    if err:
        print(f"{script}: gmsh reported errors, not annotated:\n{err}", file=sys.stderr)
        return False
    src = [EXPECT.sub("", l) for l in open(script).read().splitlines()]
    while src and src[-1].startswith("// gmsh 4.8.4 -0 output"):
        src.pop()
    src = [l for l in src if not l.startswith("// expect:")]
    while src and not src[-1].strip():
        src.pop()
    printf_lines = [i for i, l in enumerate(src) if re.match(r"\s*Printf\s*\(", l)]
    flow = any(re.match(r"\s*(For|Call|Include|Macro|Function)\b", l) for l in src)
    if not flow and len(printf_lines) == len(lines):
        for i, text in zip(printf_lines, lines):
            src[i] += f"  // expect: {text}"
    else:
        src.append("// gmsh 4.8.4 -0 output:")
        src += [f"// expect: {text}" for text in lines]
    open(script, "w").write("\n".join(src) + "\n")
    return True

if __name__ == "__main__":
    ok = all([annotate(s) for s in sys.argv[1:]])
    sys.exit(0 if ok else 1)
