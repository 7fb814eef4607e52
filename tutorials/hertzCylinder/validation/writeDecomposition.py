#!/usr/bin/python3
"""hertzCylinder: write constant/cellDecomposition for decomposePar's
`manual` method: processor 0 gets the cells whose centre has x < 3 mm (of
both bodies), processor 1 the rest, so the cut runs through the contact
zone (a ~ 6 mm) on both contact patches.

Cell centres come from 0/C, written by
    postProcess -func writeCellCentres -time 0
(v1912's manualDecomp reads the file named by manualCoeffs/dataFile as a
labelIOList from the mesh's faces instance, i.e. constant/, one processor
number per cell in cell order.)
"""
import argparse
import os
import sys

for _p in (os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../src/postProcessing/python"),
           os.path.join(os.environ.get("C4F_ROOT", ""), "src/postProcessing/python")):
    if os.path.isdir(os.path.join(_p, "c4fpost")):
        sys.path.insert(0, _p)
        break
from c4fpost import foamio  # noqa: E402

import numpy as np  # noqa: E402

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  contact4foam tutorial: hertzCylinder -- written by
  validation/writeDecomposition.py (processor 0: x < %g m)
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       labelList;
    location    "constant";
    object      cellDecomposition;
}

"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--split", type=float, default=3e-3,
                    help="x of the cut [m] (default 3e-3)")
    args = ap.parse_args()
    C = foamio.read_internal(os.path.join(args.case, "0", "C"))
    proc = (C[:, 0] >= args.split).astype(int)
    out = os.path.join(args.case, "constant", "cellDecomposition")
    with open(out, "w") as f:
        f.write(HEADER % args.split)
        f.write("%d\n(\n" % proc.size)
        f.write("\n".join(str(p) for p in proc))
        f.write("\n)\n\n// ************************************************************************* //\n")
    n0 = int((proc == 0).sum())
    print("cellDecomposition: %d cells, %d on processor 0 (x < %g m), %d on processor 1 -> %s"
          % (proc.size, n0, args.split, proc.size - n0, out))
    if n0 == 0 or n0 == proc.size:
        sys.exit("writeDecomposition: one processor would be empty")


if __name__ == "__main__":
    main()
