#!/usr/bin/python3
"""contactPatchTest3D -finiteStrain: the uniaxial finite-strain state
across a non-matching interface, in 3D.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

The two boxes (column height L = 1 m, slave 10 x 8 faces on master 7 x 5) are
neo-Hookean under nonlinearGeometry yes and pressed to 0.8 of their
height in one step; the exact state is uniform and uniaxial, its closed
form (the lateral stretch s from a zero lateral Cauchy stress, then
sigma'_zz) is c4fpost.finitestrain's. The contact pressure the solver
writes is per current area: -sigma'_zz on every slave face.

Checks:
  - the step converged (outer residual below solidMechanics' tolerance,
    1e-9 as in the small-strain test);
  - exact methods (answer=exact in solidContactFoam -listMethods): in
    every cell |sigma'_zz/sigma_exact - 1| <= 1e-6 and D' within 1e-6
    Delta of the exact field; every slave face's pressure within 1e-6 of
    -sigma_exact;
  - the penalty family (a spring in series: uniform with an offset):
    (max - min) sigma'_zz/|sigma_exact| <= 1e-6, the offset printed;
  - every method: the other components of sigma' at most 1e-6
    |sigma_exact| in every cell (uniaxial).
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
