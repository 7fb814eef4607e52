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

`python3 hertz.py` runs these and the other self-checks.

The module also has the few polyMesh geometry helpers (face centres and
area vectors of a patch, cell volumes and centres) that the contact
comparisons need; they sit here rather than in foamio.py, which is shared.
ASCII meshes only (writeFormat ascii), like foamio.
"""
import math
import os
import re

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
# polyMesh geometry (ASCII)

def _strip(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r"\bFoamFile\s*\{[^}]*\}", "", text, count=1)


def _body(path):
    """The text inside the top-level counted list 'N ( ... )' of a file."""
    text = _strip(open(path).read())
    m = re.search(r"(\d+)\s*\(", text)
    if not m:
        raise ValueError("no counted list in %s" % path)
    return int(m.group(1)), text[m.end():text.rindex(")")]


def read_points(case):
    """constant/polyMesh/points as an (n, 3) array."""
    n, body = _body(os.path.join(case, "constant/polyMesh/points"))
    pts = np.array(body.replace("(", " ").replace(")", " ").split(), float)
    if pts.size != 3 * n:
        raise ValueError("points: %d values for %d points" % (pts.size, n))
    return pts.reshape(n, 3)


def read_faces(case):
    """constant/polyMesh/faces (ASCII faceList) as a list of index arrays."""
    n, body = _body(os.path.join(case, "constant/polyMesh/faces"))
    faces = [np.array(f.split(), int) for f in re.findall(r"\d+\s*\(([^)]*)\)", body)]
    if len(faces) != n:
        raise ValueError("faces: read %d of %d" % (len(faces), n))
    return faces


def read_labels(case, name):
    """constant/polyMesh/<name> (owner, neighbour) as an int array."""
    n, body = _body(os.path.join(case, "constant/polyMesh", name))
    vals = np.array(body.split(), int)
    if vals.size != n:
        raise ValueError("%s: %d values for %d" % (name, vals.size, n))
    return vals


def face_geometry(points, face):
    """(centre, area vector) of one face the way OpenFOAM computes them:
    triangles fanned from the vertex average, area-weighted centroids."""
    p = points[face]
    c0 = p.mean(axis=0)
    q = np.roll(p, -1, axis=0)
    tri_n = 0.5 * np.cross(p - c0, q - c0)
    tri_c = (p + q + c0) / 3.0
    mag = np.linalg.norm(tri_n, axis=1)
    Sf = tri_n.sum(axis=0)
    Cf = (tri_c * mag[:, None]).sum(axis=0) / mag.sum() if mag.sum() > 0 else c0
    return Cf, Sf


def boundary_patches(case):
    """{patch: (startFace, nFaces)} from constant/polyMesh/boundary."""
    text = _strip(open(os.path.join(case, "constant/polyMesh/boundary")).read())
    out = {}
    for m in re.finditer(r"(\w+)\s*\{([^}]*)\}", text):
        nf = re.search(r"\bnFaces\s+(\d+)", m.group(2))
        sf = re.search(r"\bstartFace\s+(\d+)", m.group(2))
        if nf and sf:
            out[m.group(1)] = (int(sf.group(1)), int(nf.group(1)))
    return out


def patch_geometry(case, patch):
    """Face centres Cf (n, 3) and outward area vectors Sf (n, 3) of a patch,
    in face order, in the mesh's (reference) configuration."""
    start, n = boundary_patches(case)[patch]
    points = read_points(case)
    faces = read_faces(case)
    Cf = np.empty((n, 3))
    Sf = np.empty((n, 3))
    for i in range(n):
        Cf[i], Sf[i] = face_geometry(points, faces[start + i])
    return Cf, Sf


def cell_centres_volumes(case):
    """Cell centres (n, 3) and volumes (n,) as OpenFOAM computes them
    (pyramids from each face to the mean of the cell's face centres)."""
    points = read_points(case)
    faces = read_faces(case)
    owner = read_labels(case, "owner")
    neigh = read_labels(case, "neighbour")
    nf = len(faces)
    ncells = owner.max() + 1
    Cf = np.empty((nf, 3))
    Sf = np.empty((nf, 3))
    for i, f in enumerate(faces):
        Cf[i], Sf[i] = face_geometry(points, f)
    nIn = neigh.size
    # estimated centre: the mean of the face centres
    cEst = np.zeros((ncells, 3))
    nFc = np.zeros(ncells)
    np.add.at(cEst, owner, Cf)
    np.add.at(nFc, owner, 1)
    np.add.at(cEst, neigh, Cf[:nIn])
    np.add.at(nFc, neigh, 1)
    cEst /= nFc[:, None]
    V = np.zeros(ncells)
    C = np.zeros((ncells, 3))
    for cells, sl, sign in ((owner, slice(None), 1.0), (neigh, slice(0, nIn), -1.0)):
        pyr = sign * np.einsum("ij,ij->i", Sf[sl], Cf[sl] - cEst[cells])
        pc = 0.75 * Cf[sl] + 0.25 * cEst[cells]
        np.add.at(V, cells, pyr)
        np.add.at(C, cells, pyr[:, None] * pc)
    C /= V[:, None]
    return C, V / 3.0


def thickness(case):
    """Extent of the mesh in z (one cell thick 2-D cases)."""
    z = read_points(case)[:, 2]
    return float(z.max() - z.min())


def read_entry(path, key):
    """First 'key value;' scalar or word in a dictionary file (no macros)."""
    text = _strip(open(path).read())
    m = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), text)
    if not m:
        raise KeyError("%s not in %s" % (key, path))
    v = m.group(1)
    try:
        return float(v)
    except ValueError:
        return v


def read_coeff(path, dict_name, key, default=None):
    """'key value;' inside the first sub-dictionary `dict_name { ... }` of a
    dictionary file (one level, no macros), e.g. penaltyScale of
    perturbedLagrangeCoeffs in 0/D; `default` when the dictionary or the
    key is absent (None: KeyError)."""
    text = _strip(open(path).read())
    m = re.search(r"(?:^|[\s{;])%s\s*\{([^{}]*)\}" % re.escape(dict_name), text)
    v = None
    if m:
        e = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), m.group(1))
        v = e.group(1) if e else None
    if v is None:
        if default is not None:
            return default
        raise KeyError("%s of %s not in %s" % (key, dict_name, path))
    try:
        return float(v)
    except ValueError:
        return v


def _with_includes(path):
    """The text of a dictionary file with its #include "file" lines
    replaced by the files (relative to its directory), comments removed."""
    text = _strip(open(path).read())

    def include(m):
        return _with_includes(os.path.join(os.path.dirname(path), m.group(1)))

    return re.sub(r'^\s*#include\s+"([^"]+)"', include, text, flags=re.M)


def _entry(text, key, default=None):
    m = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), text)
    if not m:
        if default is not None:
            return default
        raise KeyError(key)
    v = m.group(1)
    try:
        return float(v)
    except ValueError:
        return v


def _sub_dict(text, key):
    """The body of the first `key { ... }` in text (braces balanced)."""
    m = re.search(r"(?:^|[\s{;])%s\s*\{" % re.escape(key), text)
    if not m:
        raise KeyError("%s not found" % key)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def _law_constants(text):
    ps = str(_entry(text, "planeStress", "no")).lower() in ("yes", "on", "true", "1")
    return _entry(text, "E"), _entry(text, "nu"), ps


def materials(case):
    """The linear-elastic constants of constant/mechanicalProperties, as
    {zone: (E, nu, planeStress)} for a zoned law and {None: (...)} for one
    law of the whole mesh. #include lines are followed."""
    text = _with_includes(os.path.join(case, "constant/mechanicalProperties"))
    if _entry(text, "materialLaw") != "zoned":
        return {None: _law_constants(text)}
    coeffs = _sub_dict(text, "zonedCoeffs")
    zones = re.findall(r"(?:^|[\s;}])(\w+)\s*\{\s*materialLaw\b", coeffs)
    return {z: _law_constants(_sub_dict(coeffs, z)) for z in zones}


def elastic_constants(case, zone=None):
    """(E, nu, planeStress) from constant/mechanicalProperties: of the one
    law, or of `zone`'s law of a zoned one."""
    mats = materials(case)
    return mats[None] if None in mats else mats[zone]


def impK(E, nu, planeStress=False):
    """K = 2 mu + lambda, the implicit stiffness the solver and the penalty
    factor use."""
    mu = E / (2.0 * (1.0 + nu))
    lam = nu * E / ((1.0 + nu) * (1.0 - nu)) if planeStress \
        else nu * E / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return 2.0 * mu + lam


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
    # geometry: a unit square face, and a 1 x 2 x 3 box's volume
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    Cf, Sf = face_geometry(pts, np.arange(4))
    check("square face area", float(Sf[2]), 1.0, 1e-15)
    check("square face centre x", float(Cf[0]), 0.5, 1e-15)
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
    check("K(E=1, nu=0)", impK(1.0, 0.0), 1.0, 1e-15)
    check("K(E=1, nu=0.3), plane strain", impK(1.0, 0.3), 0.7 / (1.3 * 0.4), 1e-15)
    return ok


if __name__ == "__main__":
    import doctest
    import sys
    failed, _ = doctest.testmod()
    sys.exit(0 if _self_test() and not failed else 1)
