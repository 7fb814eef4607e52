"""Cattaneo-Mindlin partial slip of a line contact (plane strain): two
elastically identical cylinders, or a cylinder on a flat of the same
material, pressed together by P' per unit length (Hertz, c4fpost.hertz) and
then loaded tangentially by Q' < mu P' with P' held. Coulomb friction mu.

Identical materials do not couple the normal and the tangential problem
(Dundurs' beta = 0), so the pressure stays Hertz's, p(x) = p0 sqrt(1 -
x^2/a^2), and the tangential traction is the full-sliding one minus a
corrective traction over a central stick zone |x| < c (Cattaneo 1938,
Mindlin 1949; Johnson, Contact Mechanics, 1985, ch. 7 "Tangential loading
and sliding contact", the two-dimensional case of incipient sliding, in the
section before sec. 7.3 "Simultaneous variation of normal and tangential
forces"; equation numbers not checked against the book):

  c/a  = sqrt(1 - Q'/(mu P'))                    stick-zone half-width
  q(x) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)],   |x| < c
  q(x) = mu p(x) = mu p0 sqrt(1 - x^2/a^2),              c <= |x| <= a

q acts on each body against the direction in which the other body drags
it, so with x measured from the contact centre (for identical materials
the stick zone is centred there) q is even in x and integrates to Q'.

Why this is the solution (checked numerically by the self-test): on a
half-plane the surface tangential strain due to a tangential traction q is
proportional to the principal value H(x) = (1/pi) PV int q(s)/(x - s) ds
(Johnson 1985, sec. 2.2; the normal pressure's contribution cancels
between identical bodies), so the two surfaces stick where H = 0. For
q = k sqrt(b^2 - s^2), H = k x for |x| < b, hence both terms of q(x) have
H = (mu p0/a) x inside the stick zone and their difference has H = 0 there;
in the slip zones H = (mu p0/a) sign(x) sqrt(x^2 - c^2), the slip growing
from the stick-zone edge outwards.

    >>> round(stick_ratio(0.5), 4)
    0.7071
    >>> round(stick_ratio(0.0), 4), round(stick_ratio(1.0), 4)
    (1.0, 0.0)

`python3 -m c4fpost.cattaneo` runs these and the self-checks.
"""
import math

import numpy as np

from c4fpost import hertz


def stick_ratio(load_ratio):
    """c/a = sqrt(1 - Q'/(mu P')) for the load ratio Q'/(mu P') in [0, 1];
    0 (full sliding) beyond 1."""
    if load_ratio < 0:
        raise ValueError("Q'/(mu P') must be >= 0, not %g" % load_ratio)
    return math.sqrt(max(0.0, 1.0 - load_ratio))


def stick_half_width(P, Q, mu, R, Estar):
    """c = a sqrt(1 - Q'/(mu P')), a Hertz's semi-width for P'."""
    return hertz.half_width(P, R, Estar) * stick_ratio(abs(Q) / (mu * P))


def traction(x, P, Q, mu, R, Estar):
    """q(x) of Cattaneo-Mindlin for the loads P', Q' (per unit length; the
    magnitude of Q' is used, q >= 0 in the direction of the friction force),
    mu, R and E*: mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)] in the
    stick zone, mu p(x) in the slip zones, 0 outside the contact."""
    a = hertz.half_width(P, R, Estar)
    p0 = hertz.peak_pressure(P, a)
    ca = stick_ratio(abs(Q) / (mu * P))
    c = ca * a
    x = np.asarray(x, float)
    q = mu * p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    if c > 0:
        q = q - mu * p0 * ca * np.sqrt(np.clip(1.0 - (x / c) ** 2, 0.0, None))
    return q


def hilbert(x, s_edges, q_strips):
    """H(x) = (1/pi) PV int q(s)/(x - s) ds of a traction given as constants
    q_strips on the strips [s_edges[i], s_edges[i+1]], each strip's
    integral taken exactly (ln|x - s|); x must not be an edge."""
    x = np.asarray(x, float)[:, None]
    lo, hi = s_edges[None, :-1], s_edges[None, 1:]
    return (q_strips[None, :] * np.log(np.abs(x - lo) / np.abs(x - hi))).sum(axis=1) / math.pi


# --------------------------------------------------------------------------

def _self_test():
    ok = True

    def check(name, value, ref, tol):
        nonlocal ok
        good = abs(value - ref) <= tol
        ok &= good
        print("%s %-46s value=%-12.6g ref=%-12.6g tol=%.3g"
              % ("PASS" if good else "FAIL", name, value, ref, tol))

    # hertzCylinder's numbers: steel on steel, R = 0.1 m, P' = 3.5e7 N/m
    Es = hertz.contact_modulus(210e9, 0.3)
    R, P, mu = 0.1, 3.5e7, 0.3
    a = hertz.half_width(P, R, Es)
    p0 = hertz.peak_pressure(P, a)
    Q = 0.5 * mu * P
    c = stick_half_width(P, Q, mu, R, Es)
    check("c/a at Q'/(mu P') = 0.5", c / a, math.sqrt(0.5), 1e-15)
    # q integrates to Q' (midpoint rule on a fine grid)
    N = 400000
    edges = np.linspace(-a, a, N + 1)
    s = 0.5 * (edges[1:] + edges[:-1])
    q = traction(s, P, Q, mu, R, Es)
    check("integral of q / Q'", float((q * np.diff(edges)).sum()) / Q, 1.0, 1e-6)
    mup = mu * hertz.pressure(s, P, R, Es)
    check("max (q - mu p) / (mu p0) (q <= mu p)", float((q - mup).max()) / (mu * p0),
          0.0, 1e-12)
    check("min q / (mu p0) (q >= 0)", min(0.0, float(q.min())) / (mu * p0), 0.0, 1e-12)
    slip = np.abs(s) >= c
    check("slip zone: max |q - mu p| / (mu p0)",
          float(np.abs(q - mup)[slip].max()) / (mu * p0), 0.0, 1e-12)
    # continuous at the stick-zone edge
    eps = 1e-9 * a
    check("q(c-) / (mu p(c))", float(traction(c - eps, P, Q, mu, R, Es)
                                     / (mu * hertz.pressure(c, P, R, Es))), 1.0, 1e-3)
    # the limits: no tangential load, and Q' = mu P' (full sliding)
    check("Q' = 0: max |q| / (mu p0)", float(np.abs(traction(s, P, 0.0, mu, R, Es)).max())
          / (mu * p0), 0.0, 1e-12)
    check("Q' = mu P': max |q - mu p| / (mu p0)",
          float(np.abs(traction(s, P, mu * P, mu, R, Es) - mup).max()) / (mu * p0), 0.0, 1e-12)
    # the stick condition: H(x) = 0 inside the stick zone, (mu p0/a)
    # sign(x) sqrt(x^2 - c^2) in the slip zones. The strips' piecewise
    # constant traction is exact per strip; what is left is the strip size
    # near the square-root edges at c and a (measured 2e-6 and 4e-6 of
    # mu p0 for N above)
    xs = np.concatenate([np.linspace(-0.95 * c, 0.95 * c, 21),
                         np.linspace(1.05 * c, 0.95 * a, 7), -np.linspace(1.05 * c, 0.95 * a, 7)])
    xs = xs + 0.37 * (edges[1] - edges[0])     # never on a strip edge
    H = hilbert(xs, edges, q) / (mu * p0)
    inside = np.abs(xs) < c
    check("stick zone: max |H| / (mu p0)", float(np.abs(H[inside]).max()), 0.0, 1e-4)
    Href = np.sign(xs) * np.sqrt(np.clip(xs ** 2 - c ** 2, 0.0, None)) / a
    check("slip zones: max |H - sign(x) sqrt(x^2 - c^2)/a|",
          float(np.abs(H - Href)[~inside].max()), 0.0, 1e-4)
    # the full-sliding traction alone would not stick: H = x/a
    Hfull = hilbert(xs, edges, mup) / (mu * p0)
    check("full sliding: max |H - x/a| inside c", float(np.abs(Hfull - xs / a)[inside].max()),
          0.0, 1e-4)
    # and the check can fail: a stick zone 10 % too narrow for the load
    # (the corrective term of c' = 0.9 c scaled to carry the same Q')
    # does not stick: H = (1 - c^2/c'^2) x/a, 0.14 of mu p0 at x = 0.95 c'
    cw = 0.9 * c
    qw = mup - mu * p0 * (c / a) ** 2 * a / cw * np.sqrt(np.clip(1.0 - (s / cw) ** 2, 0.0, None))
    Hw = hilbert(xs, edges, qw) / (mu * p0)
    check("a wrong c: max |H| inside 0.9 c above 1e-2",
          float(np.abs(Hw[np.abs(xs) < cw]).max() > 1e-2), 1.0, 0.0)
    return ok


if __name__ == "__main__":
    import doctest
    import sys
    failed, _ = doctest.testmod()
    sys.exit(0 if _self_test() and not failed else 1)
