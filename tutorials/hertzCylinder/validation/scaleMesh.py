#!/usr/bin/python3
"""hertzCylinder: scale every cell count of system/blockMeshDict, keeping
the gradings (the middle entry of each (fraction cells expansion) section
of the multi-gradings, and the n* macros). Allrun's -refine N uses it with
an integer N (N^2 times the cells); make bench also with 0.5.

    validation/scaleMesh.py system/blockMeshDict <factor>
"""
import argparse
import re


def scale_block_mesh(path, factor):
    """Rewrite the blockMeshDict at `path` with every cell count times
    `factor` (rounded, at least 1)."""
    def scale(m):
        return "%s%d%s" % (m.group(1), max(1, round(int(m.group(2)) * factor)), m.group(3))

    text = open(path).read()
    text = re.sub(r"^\w+Grading\s.*$",
                  lambda line: re.sub(r"(\(\s*[0-9.]+\s+)(\d+)(\s+[0-9.]+\s*\))", scale,
                                      line.group(0)),
                  text, flags=re.M)
    text = re.sub(r"^(n\w+\s+)(\d+)(;)", scale, text, flags=re.M)
    open(path, "w").write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("blockMeshDict")
    ap.add_argument("factor", type=float)
    args = ap.parse_args()
    if not args.factor > 0:
        ap.error("the factor must be > 0, not %g" % args.factor)
    scale_block_mesh(args.blockMeshDict, args.factor)


if __name__ == "__main__":
    main()
