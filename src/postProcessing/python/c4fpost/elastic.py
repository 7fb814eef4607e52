"""Closed forms of linear elasticity the comparisons share.

    >>> impK(1.0, 0.0)
    1.0
"""


def impK(E, nu, planeStress=False):
    """K = 2 mu + lambda, the implicit stiffness the solver and the penalty
    factor use."""
    mu = E / (2.0 * (1.0 + nu))
    lam = nu * E / ((1.0 + nu) * (1.0 - nu)) if planeStress \
        else nu * E / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return 2.0 * mu + lam


if __name__ == "__main__":
    import doctest
    import sys
    failed, _ = doctest.testmod()
    ok = abs(impK(1.0, 0.3) - 0.7 / (1.3 * 0.4)) <= 1e-15
    print("%s K(E=1, nu=0.3), plane strain" % ("PASS" if ok else "FAIL"))
    sys.exit(0 if ok and not failed else 1)
