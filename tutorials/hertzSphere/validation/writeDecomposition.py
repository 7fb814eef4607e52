#!/usr/bin/python3
"""hertzSphere: write constant/cellDecomposition for decomposePar's
`manual` method (c4fpost.decomposition): processor 0 gets the cells
whose centre has x < 0.05 m (of both bodies), processor 1 the rest, so the cut runs through the contact zone (a ~ 0.1 m) on both contact patches.

    validation/writeDecomposition.py [case] [--split <x>]
"""

from c4fpost import decomposition

if __name__ == "__main__":
    decomposition.main(0.05, "hertzSphere", __doc__)
