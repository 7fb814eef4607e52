#!/usr/bin/python3
"""hertzCylinder: write constant/cellDecomposition for decomposePar's
`manual` method (c4fpost.decomposition): processor 0 gets the cells
whose centre has x < 3 mm (of both bodies), processor 1 the rest, so the cut runs through the contact zone (a ~ 6 mm) on both contact patches.

    validation/writeDecomposition.py [case] [--split <x>]
"""

from c4fpost import decomposition

if __name__ == "__main__":
    decomposition.main(3e-3, "hertzCylinder", __doc__)
