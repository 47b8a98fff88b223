#!/usr/bin/python3
"""Split partition files are written in bounded memory: -part 300 with
Mesh.PartitionSplitMeshFiles = 1 on a square of about 130,000 nodes builds and writes one
part at a time, so its peak memory is about that of writing the same partition as one
file. Building every piece first (each with a copy of the node coordinates) took 8 times
as much (990 MB against 120 MB) and ran out of memory under the limit used here.

 - the single-file partitioned write runs under an address-space limit of twice its
   measured peak resident memory plus 64 MB;
 - the split write runs under the same limit, writes the 300 files and nothing else;
 - its peak resident memory is within a quarter (plus 16 MB) of the single file's.

    partitions_split_memory.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed).
"""
import os
import resource
import subprocess
import sys
import tempfile

from checks import check, exit_status, main_with_binary

PARTS = 300

SQUARE = """Point(1) = {0, 0, 0, 0.003}; Point(2) = {1, 0, 0, 0.003};
Point(3) = {1, 1, 0, 0.003}; Point(4) = {0, 1, 0, 0.003};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
"""



def run(stereomesh, d, script, out_dir, limit=None):
    """Exit status and peak resident memory (bytes) of one run, under an optional
    address-space limit (bytes). One thread, so that the limit does not depend on how
    many thread stacks and malloc arenas the machine's cores would bring."""
    os.makedirs(os.path.join(d, out_dir))

    def limited():
        if limit is not None:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    p = subprocess.Popen([stereomesh, "-2", script, "-part", str(PARTS), "-nt", "1", "-o", f"{out_dir}/m.msh"],
                         cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, preexec_fn=limited)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, usage.ru_maxrss * 1024, err.decode(errors="replace")[-300:]


def main(stereomesh):
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "one.geo"), "w") as f:
            f.write(SQUARE)
        with open(os.path.join(d, "split.geo"), "w") as f:
            f.write(SQUARE + "Mesh.PartitionSplitMeshFiles = 1;\n")
        status, one_peak, err = run(stereomesh, d, "one.geo", "free")
        check(status == 0, "the single-file partitioned write runs" + ("" if status == 0 else f" ({err!r})"))
        limit = 2 * one_peak + (64 << 20)
        print(f"single file: peak {one_peak >> 20} MB; address-space limit {limit >> 20} MB")
        status, _, err = run(stereomesh, d, "one.geo", "one", limit)
        check(status == 0, "the single-file write runs under the limit" + ("" if status == 0 else f" ({err!r})"))
        status, split_peak, err = run(stereomesh, d, "split.geo", "split", limit)
        print(f"split files: peak {split_peak >> 20} MB")
        check(status == 0, "the split write runs under the limit" + ("" if status == 0 else f" ({err!r})"))
        want = sorted(f"m_{k}.msh" for k in range(1, PARTS + 1))
        check(sorted(os.listdir(os.path.join(d, "split"))) == want, f"the split write leaves the {PARTS} files only")
        check(split_peak <= one_peak * 1.25 + (16 << 20),
              f"split peak {split_peak >> 20} MB within a quarter of the single file's {one_peak >> 20} MB")
    return exit_status()


if __name__ == "__main__":
    main_with_binary(main)
