"""A manual decomposition that cuts the contact zone: constant/cellDecomposition
for decomposePar's `manual` method, processor 0 the cells whose centre has
x < split (of both bodies), processor 1 the rest, so that the cut runs
through the contact patches of both bodies. The tutorials' Allrun
-parallel uses it.

Cell centres come from 0/C, written by
    postProcess -func writeCellCentres -time 0
(v1912's manualDecomp reads the file named by manualCoeffs/dataFile as a
labelIOList from the mesh's faces instance, i.e. constant/, one processor
number per cell in cell order.)

    python3 -m c4fpost.decomposition <case> --split <x> [--tutorial <name>]
"""
import argparse
import os
import sys

import numpy as np

from . import foamio

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  contact4foam tutorial: %s -- written by c4fpost.decomposition
  (processor 0: x < %g m)
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


def write_cell_decomposition(case, split, tutorial="contact4foam"):
    """Write constant/cellDecomposition of `case` for the cut x = split;
    returns (cells, cells on processor 0). Exits when a processor would be
    empty."""
    C = foamio.read_internal(os.path.join(case, "0", "C"))
    proc = (C[:, 0] >= split).astype(int)
    out = os.path.join(case, "constant", "cellDecomposition")
    with open(out, "w") as f:
        f.write(HEADER % (tutorial, split))
        f.write("%d\n(\n" % proc.size)
        f.write("\n".join(str(p) for p in proc))
        f.write("\n)\n\n// ************************************************************************* //\n")
    n0 = int((proc == 0).sum())
    print("cellDecomposition: %d cells, %d on processor 0 (x < %g m), %d on processor 1 -> %s"
          % (proc.size, n0, split, proc.size - n0, out))
    if n0 == 0 or n0 == proc.size:
        sys.exit("writeDecomposition: one processor would be empty")
    return proc.size, n0


def main(default_split=None, tutorial="contact4foam", doc=__doc__):
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--split", type=float, default=default_split, required=default_split is None,
                    help="x of the cut [m]" + ("" if default_split is None
                                               else " (default %g)" % default_split))
    args = ap.parse_args()
    write_cell_decomposition(args.case, args.split, tutorial)


if __name__ == "__main__":
    main()
