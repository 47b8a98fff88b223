"""The pass/fail bookkeeping the stand-alone readback scripts share: each check prints one
`ok` or `FAIL` line, and the script's exit status says whether all held.

    from checks import check, exit_status
    check(r.returncode == 0, "run exits with 0")
    sys.exit(exit_status())
"""
import sys

_FAILED = []


def check(ok, what):
    """Prints the check's line; a failed check is remembered for exit_status()."""
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        _FAILED.append(what)
    return ok


def exit_status():
    """0 when every check held, 1 otherwise (with the count of failed checks printed)."""
    if _FAILED:
        print(f"{len(_FAILED)} check(s) failed")
        return 1
    print("all checks hold")
    return 0


def main_with_binary(main):
    """Runs main(absolute path of argv[1]) and exits with what it returns."""
    import os
    if len(sys.argv) != 2:
        print(f"usage: {sys.argv[0]} STEREOMESH", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(os.path.abspath(sys.argv[1])))
