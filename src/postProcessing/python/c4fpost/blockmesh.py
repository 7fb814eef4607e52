"""Mesh levels of a tutorial: scale every cell count of a blockMeshDict,
keeping its gradings.

The cell counts are the macros n<Name> (`nArc 27;`) and the middle entry of
each (fraction cells expansion) section of the multi-gradings on lines
<name>Grading (`arcGrading ((0.19 15 1) (0.81 12 14.5));`). The tutorials'
Allrun -refine and tests/bench/run.py use it.

    python3 -m c4fpost.blockmesh system/blockMeshDict <factor> [<output>]

With <output> the scaled dictionary goes there (Allrun -refine writes
system/blockMeshDict.refined and runs blockMesh -dict on it, so that the
tutorial's own dictionary stays as it is); without, in place.
"""
import argparse
import re


def scale_block_mesh(path, factor, output=None):
    """Rewrite the blockMeshDict at `path` (or write it to `output`) with
    every cell count times `factor` (rounded, at least 1)."""
    def scale(m):
        return "%s%d%s" % (m.group(1), max(1, round(int(m.group(2)) * factor)), m.group(3))

    text = open(path).read()
    text = re.sub(r"^\w+Grading\s.*$",
                  lambda line: re.sub(r"(\(\s*[0-9.]+\s+)(\d+)(\s+[0-9.]+\s*\))", scale,
                                      line.group(0)),
                  text, flags=re.M)
    text = re.sub(r"^(n\w+\s+)(\d+)(;)", scale, text, flags=re.M)
    open(output or path, "w").write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("blockMeshDict")
    ap.add_argument("factor", type=float)
    ap.add_argument("output", nargs="?", default=None)
    args = ap.parse_args()
    if not args.factor > 0:
        ap.error("the factor must be > 0, not %g" % args.factor)
    scale_block_mesh(args.blockMeshDict, args.factor, args.output)


if __name__ == "__main__":
    main()
