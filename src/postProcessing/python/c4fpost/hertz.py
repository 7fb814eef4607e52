"""Hertz line contact (plane strain): two parallel cylinders, or a cylinder on
a flat, pressed together by a load P' per unit length (Johnson, Contact
Mechanics, 1985, sec. 4.2 and 5.6):

  1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2      contact modulus
  1/R  = 1/R1 + 1/R2                          (R2 = inf for a flat)
  a    = sqrt(4 P' R / (pi E*))               semi-width of the contact strip
  p0   = 2 P' / (pi a)  = a E* / (2 R)        peak pressure
  p(x) = p0 sqrt(1 - x^2/a^2),  |x| <= a

Check against the NAFEMS-type example (R = 100 mm steel cylinder on a steel
flat, E = 210 GPa, nu = 0.3, P' = 35 kN/mm): a = 6.21 mm, p0 = 3585 MPa.

Hertz point contact: two spheres, or a sphere on a flat, pressed together
by a load P (Johnson 1985, sec. 4.2, eq. 4.22-4.23; the sphere_ functions):

  a^3  = 3 P R / (4 E*)                       radius of the contact circle
  p0   = 3 P / (2 pi a^2) = 2 a E* / (pi R)   peak pressure
  p(r) = p0 sqrt(1 - r^2/a^2),  r <= a
  delta = a^2 / R                             approach of distant points

Check against MOOSE's hertz_contact test (two spheres R1 = R2 = 2, so
R = 1; E = 1.40625e7 Pa, nu = 0.25 for both, E* = 7.5e6 Pa, P = 1e4 N):
a = 0.1, delta = 0.01, p0 = 4.77e5 Pa.

    >>> Es = contact_modulus(210e9, 0.3, 210e9, 0.3)
    >>> a = half_width(3.5e7, 0.1, Es); round(a * 1e3, 2)
    6.21
    >>> round(peak_pressure(3.5e7, a) / 1e6)
    3585
    >>> Es = contact_modulus(1.40625e7, 0.25); Es
    7500000.0
    >>> a = sphere_radius(1e4, effective_radius(2, 2), Es); round(a, 6)
    0.1
    >>> round(sphere_peak_pressure(1e4, a))
    477465

`python3 -m c4fpost.hertz` runs these and the other self-checks.

Only the closed forms: the readers of meshes, fields and dictionaries are
in foamio.
"""
import math

import numpy as np


# --------------------------------------------------------------------------
# Closed form

def contact_modulus(E1, nu1, E2=None, nu2=None):
    """E* with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (body 2 defaults to
    body 1). Plane strain."""
    if E2 is None:
        E2, nu2 = E1, nu1
    return 1.0 / ((1.0 - nu1 ** 2) / E1 + (1.0 - nu2 ** 2) / E2)


def effective_radius(R1, R2=math.inf):
    """R with 1/R = 1/R1 + 1/R2; R2 = inf (default) is a flat."""
    return 1.0 / (1.0 / R1 + (0.0 if math.isinf(R2) else 1.0 / R2))


def half_width(P, R, Estar):
    """Semi-width a of the contact strip for the load P' per unit length."""
    return math.sqrt(4.0 * P * R / (math.pi * Estar))


def peak_pressure(P, a):
    """p0 = 2 P' / (pi a)."""
    return 2.0 * P / (math.pi * a)


def load_for_half_width(a, R, Estar):
    """P' that gives the semi-width a (inverse of half_width)."""
    return math.pi * Estar * a * a / (4.0 * R)


def pressure(x, P, R, Estar):
    """p(x) = p0 sqrt(1 - x^2/a^2) inside the strip, 0 outside."""
    a = half_width(P, R, Estar)
    p0 = peak_pressure(P, a)
    x = np.asarray(x, float)
    return p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))


def sphere_radius(P, R, Estar):
    """Radius a of the contact circle of a sphere (effective radius R) for
    the load P: a^3 = 3 P R / (4 E*)."""
    return (3.0 * P * R / (4.0 * Estar)) ** (1.0 / 3.0)


def sphere_peak_pressure(P, a):
    """p0 = 3 P / (2 pi a^2)."""
    return 3.0 * P / (2.0 * math.pi * a * a)


def sphere_load_for_radius(a, R, Estar):
    """P that gives the contact radius a (inverse of sphere_radius)."""
    return 4.0 * Estar * a ** 3 / (3.0 * R)


def sphere_pressure(r, P, R, Estar):
    """p(r) = p0 sqrt(1 - r^2/a^2) inside the contact circle, 0 outside."""
    a = sphere_radius(P, R, Estar)
    p0 = sphere_peak_pressure(P, a)
    r = np.asarray(r, float)
    return p0 * np.sqrt(np.clip(1.0 - (r / a) ** 2, 0.0, None))


def cylinder_compression(P, R, E, nu, a):
    """Approach of a cylinder's centre towards its contact line under the
    Hertz pressure (Johnson eq. 5.36 per body, plane strain):
        delta = P'(1 - nu^2)/(pi E) (2 ln(4R/a) - 1).
    In two dimensions the approach of a half-space is not defined without a
    datum (it grows as ln of the distance); see the hertzCylinder tutorial
    for how its DELTA was estimated."""
    return P * (1.0 - nu ** 2) / (math.pi * E) * (2.0 * math.log(4.0 * R / a) - 1.0)


def _log_strip(x, s0, s1):
    """The integral of ln|x - s| over s0 <= s <= s1 (u ln|u| - u)."""
    def F(u):
        au = np.abs(u)
        return np.where(au > 0, u * np.log(np.where(au > 0, au, 1.0)) - u, 0.0)
    return F(x - s0) - F(x - s1)


def interface_law_contact(P, R, Estar, cN, n, N=400, span=2.5):
    """Line contact of a cylinder on a flat as Hertz's, with an interface
    law p = cN w^n between the surfaces (w >= 0 the interface's
    compression, contact4foam's constitutiveLaw, Wriggers 2006 eq. 2.20):
    the reference solution of hertzCylinder with that law, for the load P'
    per unit length (full strip).

    Each surface is an elastic half-plane (plane strain; the two bodies in
    one through E*): under a pressure p(s) the surfaces move apart by
    -(2/(pi E*)) int p(s) ln|x - s| ds + const (Johnson 1985, eq. 2.25a
    for each body). Inside the contact the gap of the surfaces is closed
    by the interface's compression,

        x^2/(2R) - delta - (2/(pi E*)) int p(s) ln|x - s| ds + w(x) = 0,
        p = cN w^n,   int p dx = P',

    outside p = 0 and the gap is positive. Discretised with a uniform
    pressure on N strips of x in [0, span a_Hertz] (mirrored: p is even),
    the strips' influence integrated exactly; Newton on (w, delta) over
    the active strips, which an outer loop updates (drop w <= 0, add a
    negative gap) until it holds still. cN -> inf is Hertz; n = 1 a
    Winkler layer in series with the half-planes.

    Returns a dict: x (the strip centres), p, a (the outer edge of the last
    active strip; resolution span a_Hertz/N), p0 (max p), penetration
    (max w, = (p0/cN)^(1/n)) and delta (the approach, up to the constant
    of the two-dimensional half-plane)."""
    aH = half_width(P, R, Estar)
    xmax = span * aH
    h = xmax / N
    s = h * (np.arange(N) + 0.5)
    lo, hi = s - h / 2, s + h / 2
    c = 2.0 / (math.pi * Estar)
    # displacement at s_i of a unit pressure on strip j and on its mirror
    A = -c * (_log_strip(s[:, None], lo[None, :], hi[None, :])
              + _log_strip(s[:, None], -hi[None, :], -lo[None, :]))
    act = s < aH
    # start from the Hertz pressure carried by the interface alone
    w = np.where(act, (np.maximum(pressure(s, P, R, Estar), 1.0) / cN) ** (1.0 / n), 0.0)
    delta = float(np.max(A @ (cN * w ** n) + w + s ** 2 / (2 * R)))
    scale = xmax ** 2 / (2 * R)
    for _ in range(100):
        ia = np.nonzero(act)[0]
        for _ in range(100):
            p = cN * w ** n
            r = (A @ p + w + s ** 2 / (2 * R) - delta)[ia]
            rl = 2 * h * p.sum() - P
            dp = cN * n * w[ia] ** (n - 1)
            J = np.zeros((ia.size + 1, ia.size + 1))
            J[:-1, :-1] = A[np.ix_(ia, ia)] * dp[None, :] + np.eye(ia.size)
            J[:-1, -1] = -1.0
            J[-1, :-1] = 2 * h * dp
            d = np.linalg.solve(J, -np.concatenate([r, [rl]]))
            # no step takes a compression below zero (damped where it would)
            t = 1.0
            down = d[:-1] < 0
            if np.any(down):
                t = min(1.0, float(np.min(-w[ia][down] / d[:-1][down])))
            t = min(max(t, 1e-2), 1.0)
            w[ia] = np.maximum(w[ia] + t * d[:-1], 0.0)
            delta += t * d[-1]
            if t == 1.0 and np.max(np.abs(r)) <= 1e-13 * scale and abs(rl) <= 1e-12 * P:
                break
        p = cN * w ** n
        gap = A @ p + s ** 2 / (2 * R) - delta
        new = act.copy()
        new[act & (w <= 0)] = False
        new[~act & (gap < 0)] = True
        if np.array_equal(new, act):
            break
        w[new & ~act] = (1e-6 * P / xmax / cN) ** (1.0 / n)
        act = new
    else:
        raise RuntimeError("interface_law_contact: the active set did not settle")
    p = cN * w ** n
    r = (A @ p + w + s ** 2 / (2 * R) - delta)[act]
    if np.max(np.abs(r)) > 1e-10 * scale or abs(2 * h * p.sum() - P) > 1e-10 * P:
        raise RuntimeError("interface_law_contact: Newton did not converge (gap residual"
                           " %.3g m, load residual %.3g)" % (np.max(np.abs(r)),
                                                             2 * h * p.sum() / P - 1))
    return dict(x=s, p=p, a=float(s[act].max() + h / 2), p0=float(p.max()),
                penetration=float(w.max()), delta=float(delta))


# --------------------------------------------------------------------------

def _self_test():
    Es = contact_modulus(210e9, 0.3, 210e9, 0.3)
    R = effective_radius(0.1)
    a = half_width(3.5e7, R, Es)
    p0 = peak_pressure(3.5e7, a)
    ok = True

    def check(name, value, ref, tol):
        nonlocal ok
        good = abs(value - ref) <= tol
        ok &= good
        print("%s %-40s value=%-12.6g ref=%-12.6g tol=%.3g"
              % ("PASS" if good else "FAIL", name, value, ref, tol))

    check("NAFEMS a [mm]", a * 1e3, 6.21, 0.005)
    check("NAFEMS p0 [MPa]", p0 / 1e6, 3585, 0.5)
    check("p0 = a E*/(2R)", p0, a * Es / (2 * R), 1e-6 * p0)
    check("R of two equal cylinders", effective_radius(0.1, 0.1), 0.05, 1e-15)
    check("inverse of half_width", load_for_half_width(a, R, Es), 3.5e7, 1e-6)
    # the pressure integrates to P'
    x = np.linspace(-a, a, 200001)
    xm = 0.5 * (x[1:] + x[:-1])
    check("integral of p(x) / P'", float((pressure(xm, 3.5e7, R, Es) * np.diff(x)).sum()) / 3.5e7,
          1.0, 1e-6)
    check("p outside the strip", float(pressure(1.01 * a, 3.5e7, R, Es)), 0.0, 0.0)
    # the sphere: MOOSE's hertz_contact numbers, and p(r) integrates to P
    EsS = contact_modulus(1.40625e7, 0.25)
    aS = sphere_radius(1e4, effective_radius(2.0, 2.0), EsS)
    check("MOOSE sphere a", aS, 0.1, 1e-12)
    check("MOOSE sphere delta = a^2/R", aS * aS / 1.0, 0.01, 1e-12)
    check("MOOSE sphere p0 [Pa]", sphere_peak_pressure(1e4, aS), 4.77e5, 500)
    check("p0 = 2 a E*/(pi R)", sphere_peak_pressure(1e4, aS), 2 * aS * EsS / math.pi, 1e-6)
    check("inverse of sphere_radius", sphere_load_for_radius(aS, 1.0, EsS), 1e4, 1e-8)
    rr = np.linspace(0, aS, 200001)
    rm = 0.5 * (rr[1:] + rr[:-1])
    check("integral of 2 pi r p(r) / P",
          float((2 * math.pi * rm * sphere_pressure(rm, 1e4, 1.0, EsS) * np.diff(rr)).sum()) / 1e4,
          1.0, 1e-6)
    # the interface law: a stiff one is Hertz (p0 to the strips' resolution,
    # a to 1.5 strips), a soft one spreads, and every one carries P' with the
    # penetration its law gives at p0
    stiff = interface_law_contact(3.5e7, R, Es, 1e22, 2)
    check("stiff interface law p0 / Hertz", stiff["p0"] / p0, 1.0, 1e-3)
    check("stiff interface law a / Hertz", stiff["a"] / a, 1.0, 1.5 * 2.5 / 400)
    soft = interface_law_contact(3.5e7, R, Es, 1e17, 2)
    dx = soft["x"][1] - soft["x"][0]
    check("soft interface law load / P'", 2 * dx * soft["p"].sum() / 3.5e7, 1.0, 1e-10)
    check("soft interface law penetration", soft["penetration"],
          (soft["p0"] / 1e17) ** 0.5, 1e-12)
    check("soft interface law p0 below Hertz", float(soft["p0"] < 0.9 * p0), 1.0, 0.0)
    check("soft interface law a beyond Hertz", float(soft["a"] > 1.3 * a), 1.0, 0.0)
    return ok


if __name__ == "__main__":
    import doctest
    import sys
    failed, _ = doctest.testmod()
    sys.exit(0 if _self_test() and not failed else 1)
