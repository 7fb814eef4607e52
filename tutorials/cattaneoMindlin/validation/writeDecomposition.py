#!/usr/bin/python3
"""cattaneoMindlin: write constant/cellDecomposition for decomposePar's
`manual` method (c4fpost.decomposition): processor 0 gets the cells whose
centre has x < 3 mm (of both bodies), processor 1 the rest, so the cut
runs through the contact zone (a ~ 6.3 mm), inside the stick zone
(c ~ 4.4 mm), on both contact patches.

    validation/writeDecomposition.py [case] [--split <x>]
"""
import os
import sys

# In the repository the package is three levels up; a copied case finds it
# through $C4F_ROOT, which etc/bashrc exports
for _p in (os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../src/postProcessing/python"),
           os.path.join(os.environ.get("C4F_ROOT", ""), "src/postProcessing/python")):
    if os.path.isdir(os.path.join(_p, "c4fpost")):
        sys.path.insert(0, _p)
        break
from c4fpost import decomposition  # noqa: E402

if __name__ == "__main__":
    decomposition.main(3e-3, "cattaneoMindlin", __doc__)
