#!/usr/bin/python3
"""No stray temporary file after SIGKILL at any moment of a write: the mesh goes
to an unnamed temporary linked in place, and an existing file is replaced through a name
".x.msh.stereomesh-tmp-PID-N" held for the instant before the rename, which the next run
writing the same file removes. strace holds the run at that instant (its rename delayed)
so that the kill lands there every time:
 - a new target: the run is killed as soon as any new name appears; no temporary is left,
   and the target, if there, is the whole mesh;
 - an existing target: killed while the temporary is named; the old file is intact, the
   only extra file has our pattern, and the next run removes it;
 - kills at spread moments of a plain run leave the old file or the whole new one;
 - the sweep removes only our pattern for this target with a dead pid: a live writer's
   temporary, another target's, and near-miss names stay.

    outputs_sigkill.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: strace is missing.
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from checks import check, exit_status, main_with_binary


SCRIPT = """Point(1) = {0, 0, 0, 0.004}; Point(2) = {1, 0, 0, 0.004};
Point(3) = {1, 1, 0, 0.004}; Point(4) = {0, 1, 0, 0.004};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
"""
OLD = b"old mesh\n"
DELAY_US = 20_000_000   # the rename held for 20 s: far longer than the test needs to act
LINK_DELAY_US = 2_000_000   # a new target's link held 2 s after it is made: the poll sees it
POLL_S = 0.002



def names(d):
    return sorted(os.listdir(d))


def read(path):
    with open(path, "rb") as f:
        return f.read()


def children(pid):
    """Pids of the children of pid (the traced stereomesh of strace)."""
    kids = []
    task_dir = f"/proc/{pid}/task"
    for tid in os.listdir(task_dir):
        try:
            with open(f"{task_dir}/{tid}/children") as f:
                kids += [int(x) for x in f.read().split()]
        except OSError:
            pass
    return kids


def kill_traced_when(stereomesh, d, args, appeared):
    """Runs stereomesh under strace with every rename delayed; once appeared(new names) is
    true (names not in the folder before the run) SIGKILLs stereomesh (not strace).
    Returns whether the kill happened."""
    before = set(names(d))
    # Renames wait before they happen (the temporary is named); links of a new target wait
    # after (the name is there): either way the poll sees the name with the run still alive,
    # however loaded the machine (a link without a delay could finish the run between polls).
    cmd = ["strace", "-f", "-qq", "-o", "/dev/null", "-e", "trace=/^(rename|link)",
           "-e", f"inject=/^rename:delay_enter={DELAY_US}", "-e", f"inject=/^link:delay_exit={LINK_DELAY_US}",
           stereomesh] + args
    tracer = subprocess.Popen(cmd, cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    killed = False
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and tracer.poll() is None:
        if appeared([x for x in names(d) if x not in before]):
            for pid in children(tracer.pid):
                os.kill(pid, signal.SIGKILL)
                killed = True
            break
        time.sleep(POLL_S)
    try:
        tracer.wait(timeout=60)
    except subprocess.TimeoutExpired:
        tracer.kill()
        tracer.wait()
    return killed


def run(stereomesh, d, args):
    return subprocess.run([stereomesh] + args, cwd=d, capture_output=True, timeout=300)


def main(stereomesh):
    if shutil.which("strace") is None or subprocess.run(["strace", "-qq", "-o", "/dev/null", "true"]).returncode:
        print("strace is missing or cannot trace here")
        return 77
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "t.geo"), "w") as f:
            f.write(SCRIPT)
        args = ["-2", "t.geo", "-o", "a.msh"]
        start = time.monotonic()
        r = run(stereomesh, d, args)
        took = time.monotonic() - start
        check(r.returncode == 0 and names(d) == ["a.msh", "t.geo"], "a plain run writes a.msh and nothing else")
        whole = read(os.path.join(d, "a.msh"))
        os.remove(os.path.join(d, "a.msh"))

        # A new target: linked in place, it never has another name.
        killed = kill_traced_when(stereomesh, d, args, lambda n: n != [])
        left = names(d)
        check(killed, "new target: the run was killed as a name appeared")
        check(left in (["t.geo"], ["a.msh", "t.geo"]), f"new target: no temporary left after SIGKILL ({left})")
        if "a.msh" in left:
            check(read(os.path.join(d, "a.msh")) == whole, "new target: a.msh, once there, is the whole mesh")

        # An existing target: killed while the temporary is named, just before the rename.
        with open(os.path.join(d, "a.msh"), "wb") as f:
            f.write(OLD)
        killed = kill_traced_when(stereomesh, d, args, lambda n: any("tmp" in x for x in n))
        left = names(d)
        check(killed, "existing target: the run was killed with the temporary named")
        check(read(os.path.join(d, "a.msh")) == OLD, "existing target: the old file is intact")
        extra = [x for x in left if x not in ("a.msh", "t.geo")]
        ours = re.compile(r"^\.a\.msh\.stereomesh-tmp-[0-9]+-[A-Za-z0-9]+$")
        check(all(ours.match(x) for x in extra), f"existing target: what is left has the swept pattern ({extra})")
        r = run(stereomesh, d, args)
        check(r.returncode == 0 and names(d) == ["a.msh", "t.geo"],
              f"existing target: the next run removes it ({names(d)})")
        check(read(os.path.join(d, "a.msh")) == whole, "existing target: the next run writes the whole mesh")

        # Kills spread over a plain run: the old file or the whole new one, and only swept strays.
        for k in range(1, 9):
            with open(os.path.join(d, "a.msh"), "wb") as f:
                f.write(OLD)
            p = subprocess.Popen([stereomesh] + args, cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(took * (0.55 + 0.06 * k))
            p.kill()
            p.wait()
            body = read(os.path.join(d, "a.msh"))
            extra = [x for x in names(d) if x not in ("a.msh", "t.geo")]
            check(body in (OLD, whole) and all(ours.match(x) for x in extra),
                  f"kill at {0.55 + 0.06 * k:.2f} of a run: old or whole file, no other stray ({extra})")
        r = run(stereomesh, d, args)
        check(r.returncode == 0 and names(d) == ["a.msh", "t.geo"], "after the kills one run leaves no stray")

        # The sweep: only this target's temporaries whose writer is gone.
        dead = subprocess.Popen(["true"])
        dead.wait()
        keep = [f".a.msh.stereomesh-tmp-{os.getpid()}-0",      # a live writer
                f".b.msh.stereomesh-tmp-{dead.pid}-0",          # another target
                f".a.msh.stereomesh-tmp-{dead.pid}-",           # not our pattern: no suffix
                f"a.msh.stereomesh-tmp-{dead.pid}-0",           # not our pattern: no dot
                f".a.msh.stereomesh-tmp-x{dead.pid}-0"]         # not our pattern: no pid
        gone = [f".a.msh.stereomesh-tmp-{dead.pid}-0", f".a.msh.stereomesh-tmp-{dead.pid}-Ab12Cd"]
        for x in keep + gone:
            with open(os.path.join(d, x), "wb") as f:
                f.write(b"partial")
        r = run(stereomesh, d, args)
        check(r.returncode == 0 and names(d) == sorted(["a.msh", "t.geo"] + keep),
              f"sweep: dead-pid temporaries of a.msh removed, the rest kept ({names(d)})")
    return exit_status()


if __name__ == "__main__":
    main_with_binary(main)
