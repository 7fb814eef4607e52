"""Closed forms of the compressible neo-Hookean law the finite-strain
comparisons share: tau = mu (b - I) + lambda ln J I (Simo's form, the law
of src/kernels/elasticity/hyperelasticLaws.H).

    >>> s, J, axial, outOfPlane = uniaxial(1.0, 0.0, 0.8, 2)
    >>> abs(s - 1.0) < 1e-12
    True
"""
import math


def uniaxial(E, nu, a, lateral):
    """The homogeneous uniaxial state at axial stretch a with `lateral`
    free lateral directions (1: plane strain, 2: 3D) that carry no Cauchy
    stress: their stretch s solves

        tau_lat = mu (s^2 - 1) + lambda ln J = 0,   J = a s^lateral

    (bisection on [0.5, 2]; tau_lat rises with s). Returns (s, J, the axial
    Cauchy stress (mu (a^2 - 1) + lambda ln J)/J, and lambda ln(J)/J, the
    out-of-plane stress of plane strain)."""
    mu = E / (2 * (1 + nu))
    lam = nu * E / ((1 + nu) * (1 - 2 * nu))
    lo, hi = 0.5, 2.0
    for _ in range(200):
        s = 0.5 * (lo + hi)
        if mu * (s * s - 1) + lam * math.log(a * s ** lateral) > 0:
            hi = s
        else:
            lo = s
    s = 0.5 * (lo + hi)
    J = a * s ** lateral
    return s, J, (mu * (a * a - 1) + lam * math.log(J)) / J, lam * math.log(J) / J


if __name__ == "__main__":
    import doctest
    import sys
    failed, _ = doctest.testmod()
    sys.exit(1 if failed else 0)
