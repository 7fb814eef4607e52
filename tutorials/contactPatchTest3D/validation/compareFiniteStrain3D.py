#!/usr/bin/python3
"""contactPatchTest3D -finiteStrain: the uniaxial finite-strain state
across a non-matching interface, in 3D.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

The two boxes (column height L = 1 m, slave 10 x 8 faces on master 7 x 5) are
neo-Hookean under nonlinearGeometry yes and pressed to 0.8 of their
height in one step: the uniform uniaxial state of c4fpost.finitestrain.

Checks (listed in c4fpost.finitestrain, exact_tol = EXACT_TOL below): the
step converged (solidMechanics' tolerance 1e-9, as in the small-strain
test), the exact methods at the closed form, the penalty family uniform
with an offset, the other stress components zero.
"""
from c4fpost.finitestrain import FiniteStrainPatchTest3D

NAME = "contactPatchTest3D"
L = 1.0          # column height [m], system/blockMeshDict
DELTA = 0.2      # the top's displacement [m] under -finiteStrain (Allrun)
EXACT_TOL = 1e-6
TEST = FiniteStrainPatchTest3D(NAME, "upperBottom", "upperTop", "symmetryX", DELTA, L, EXACT_TOL)


def main():
    return TEST.main(__doc__, "finiteStrain3D.png")


if __name__ == "__main__":
    raise SystemExit(main())
