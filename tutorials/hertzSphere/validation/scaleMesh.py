#!/usr/bin/python3
"""hertzSphere: scale every cell count of system/blockMeshDict, keeping
the gradings (c4fpost.blockmesh). Allrun -refine uses it with a
number > 0 (factor^3 times the cells); make bench with 1.5.

    validation/scaleMesh.py system/blockMeshDict <factor> [<output>]
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
from c4fpost import blockmesh  # noqa: E402

if __name__ == "__main__":
    blockmesh.main()
