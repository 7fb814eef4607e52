#!/usr/bin/python3
"""contact4foam benchmark of the contact proximity search (`make bench`).

Runs the contactSearchBench utility (built by wmake into $FOAM_USER_APPBIN,
on PATH in the sourced environment), which times, side by side in one run,
the CGAL AABB tree of c4f::search::SurfaceSearch, the brute-force reference
and OpenFOAM's indexedOctree on a wavy quad surface of N faces, N = 1e3 ..
1e6, and prints its tables. The times are reported, not asserted; the run
fails (non-zero exit) only if the searches disagree: CGAL against brute
force, CGAL against the octree, or CGAL after a rebuild against brute force
(distances to 1e-10).

Extra arguments go to the utility, e.g.
    searchBench.py -sizes '(1000 10000)' -bruteSamples 50
The numbers are also written to $C4F_PREFIX/run/bench/searchBench.json.
"""
import json
import os
import shutil
import subprocess
import sys

PREFIX = os.environ.get("C4F_PREFIX", os.path.expanduser("~/.contact4foam"))
WORK = os.path.join(PREFIX, "run", "bench")
UTILITY = "contactSearchBench"


def main():
    exe = shutil.which(UTILITY)
    if exe is None:
        sys.exit("searchBench: %s is not on PATH; source etc/bashrc and build it"
                 " (wmake applications/utilities/contactSearchBench)" % UTILITY)
    os.makedirs(WORK, exist_ok=True)
    out = os.path.join(WORK, "searchBench.json")
    if os.path.exists(out):
        os.remove(out)

    print("contact proximity search: CGAL AABB tree, brute force, OpenFOAM indexedOctree",
          flush=True)
    # The utility's own output (progress, then the tables) goes straight through
    # (PWD set too: OpenFOAM warns when it is not the working directory)
    rc = subprocess.call([exe] + sys.argv[1:] + ["-json", out], cwd=WORK,
                         env=dict(os.environ, PWD=WORK))
    if not os.path.exists(out):
        sys.exit("searchBench: %s failed (exit %d) before writing %s" % (UTILITY, rc, out))

    with open(out) as f:
        data = json.load(f)

    # Count again from the per-size entries rather than trust one total
    failures = []
    for row in data["sizes"]:
        for check in ("brute", "octree", "moved"):
            c = row[check]
            if c["mismatches"]:
                failures.append("N=%d %s: %d of %d mismatch (max |d diff| %g)"
                                % (row["N"], check, c["mismatches"], c["compared"],
                                   c["maxDistanceDiff"]))
            elif c["compared"] == 0 and check != "moved":
                failures.append("N=%d %s: nothing compared" % (row["N"], check))
    if rc and not failures:
        failures.append("%s exited with %d" % (UTILITY, rc))

    if failures:
        print("\nsearchBench: FAIL")
        for line in failures:
            print("  " + line)
        return 1
    print("\nsearchBench: all searches agree (%d sizes); numbers in %s"
          % (len(data["sizes"]), out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
