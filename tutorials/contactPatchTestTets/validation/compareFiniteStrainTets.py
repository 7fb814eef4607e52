#!/usr/bin/python3
"""contactPatchTestTets -finiteStrain: the uniaxial finite-strain state
across a non-matching interface of two tetrahedral meshes.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

The two boxes (column height L = 1 m, gmsh tetrahedra of edges 0.1 m above
and 0.14 m below, non-matching triangles at z = 0) are
neo-Hookean under nonlinearGeometry yes and pressed to 0.8 of their
height in one step: the uniform uniaxial state of c4fpost.finitestrain.

Checks (listed in c4fpost.finitestrain, exact_tol = EXACT_TOL below): the
step converged (solidMechanics' tolerance 1e-11, as in the small-strain
test on these tetrahedra), the exact methods at the closed form, the
penalty family uniform with an offset, the other stress components zero.
"""
from c4fpost.finitestrain import FiniteStrainPatchTest3D

NAME = "contactPatchTestTets"
L = 1.0          # column height [m], contactPatchTestTets.geo
DELTA = 0.2      # the top's displacement [m] under -finiteStrain (Allrun)
EXACT_TOL = 1e-6
TEST = FiniteStrainPatchTest3D(NAME, "upperBottom", "upperTop", "symmetryX", DELTA, L, EXACT_TOL)


def main():
    return TEST.main(__doc__, "finiteStrainTets.png")


if __name__ == "__main__":
    raise SystemExit(main())
