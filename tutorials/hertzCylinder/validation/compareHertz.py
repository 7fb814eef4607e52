#!/usr/bin/python3
"""hertzCylinder: compare the contact pressure on the cylinder with Hertz.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
them with --json.

Data (latest time or --time, reference configuration): contactPressure on the slave
patch (cylinderContact, or blockContact after Allrun -slave block: the
patch with `master no` in the written D; positive in compression), or
on the master with --patch (the pressure the slave's tractions put on it,
per its own area), its face centres and area vectors from
constant/polyMesh (c4fpost.foamio.patch_geometry).

Which body's pressure. Each patch's pressure is per its own reference
area at its own face centres, and the slave is paired with the master in
the current configuration. Under a rigid indenter the block's surface
contracts by e_xx = -(1 - 2 nu)(1 + nu) p/E (plane strain, Johnson 1985,
eq. 2.21; -1.3 % at the centre here with nu = 0.33), so the same forces
on the indenter's faces are 1/(1 + e_xx) times the block's pressure over
a strip that much narrower: with the near-rigid cylinder the cylinder's
peak is 1.3 % above the block's whichever body is the slave. Compare the
roles on one body (tests/regression/test_dissimilar.py).

Materials (constant/mechanicalProperties, one law or a zoned law with the
zones cylinder and block): E* from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
(Johnson 1985, eq. 4.22); with --estar block the block's alone,
E_b/(1 - nu_b^2), the rigid-indenter limit. With dissimilar materials the
normal and tangential problems couple through Dundurs' beta (Johnson
sec. 5.4), which the frictionless contact here does not feel: Hertz
holds as for like materials.

Load. The model is the half x >= 0, one cell (dz) thick, so the load per
unit length of the FULL cylinder is
    P' = 2 sum_f p_f |Sf_f| |n_y,f| / dz,
the vertical resultant of the normal contact pressure on the half patch
(|n_y| > 0.99 inside the contact strip on either patch). It is
the MEASURED load: Hertz's a and p0 are evaluated for it, so the test does
not depend on how well DELTA was estimated. The resultants of
contactTraction and of the contactReport function object are printed
beside it when present.

Checks:
  - peak pressure: max_f p_f against Hertz p(x) at the centre of that face
    (the first face's centre is at x = h/2, where p = p0 sqrt(1 - h^2/4a^2),
    0.05 % below p0 for h = a/23: evaluating Hertz there instead of at
    x = 0 removes that bias). Tolerance 3 % of the Hertz value. Sources
    of error: the discretisation (a/h ~ 23 slave faces across the
    semi-width; the finite-volume pressure is the traction of the
    cell-centred solution at the face), the finite block (W = H = 32 a;
    Hertz assumes half-spaces) and the outer correctors stopping at 1e-7.
    The 3 % is the project's target for this mesh; it has not been
    measured yet (the contact condition was being written when this case
    was set up) and should be revisited with a mesh study like plateHole's.
  - contact semi-width: a_num is the outer edge of the outermost active face,
    x_last + w_last/2 (w = face width projected on x). The discrete edge lies
    between that face's centre and the next face's centre, so a_num is the
    midpoint estimate with a resolution error up to half a face width; the
    active set is taken from contactActive when written, else p > 1e-6 max p.
    Tolerance 1.5 slave-face widths (the width of the face at x = a_Hertz):
    half a face from the sampling plus one face for the discretisation of
    the gap near the edge, where the pressure vanishes like sqrt(a - x).
  The interpolated zero of a p^2 = p0^2 (1 - x^2/a^2) least-squares fit over
  the active faces is printed as a second estimate of a (not checked).

constitutiveLaw (p_N = c_N (-g_N)^n, c_N and n from the written D): the interface
has a compliance of its own, so the reference is Hertz's problem with that
law between the surfaces (c4fpost.hertz.interface_law_contact, the
half-plane solution with the law, for the measured load): a stiff law is
Hertz (c_N 1e22, n 2: p0 0.06 % below it), a soft one spreads the pressure
(c_N 1e17, n 2, Allrun -law soft: p0 17 % lower, a 3 mm wider than Hertz
at the load it takes). peak_pressure and contact_half_width compare with
that reference, with the tolerances above, and
  - max penetration: -min g_N (contactGap) against the law's penetration
    at the reference pressure of that face, (p_ref/c_N)^(1/n): the
    penetration is part of the answer, not an error. Tolerance P0_TOL/n,
    what the tolerance of the pressure leaves through the law.
"""
import json
import os
import sys

from c4fpost import contactreport, foamio, hertz, methods, patchtest, report

import numpy as np

R = 0.1                   # cylinder radius [m], system/blockMeshDict
PATCHES = ("cylinderContact", "blockContact")
P0_TOL = 0.03             # fraction of the Hertz peak pressure
A_TOL_FACES = 1.5         # slave face widths at x = a


def contact_modulus(case, estar):
    """E* of the two bodies, or of the block alone (estar == 'block'), and
    a one-line description of the materials."""
    (cyl, blk), what = foamio.body_constants(case, ("cylinder", "block"))
    both = hertz.contact_modulus(cyl[0], cyl[1], blk[0], blk[1])
    if estar == "block":
        alone = blk[0] / (1.0 - blk[1] ** 2)
        return alone, what + "; E* of the block alone (two bodies: %.6g Pa, %+.3g %%)" \
            % (both, 100 * (both / alone - 1))
    return both, what


def interface_law(case, time, method):
    """c_N and n of <method>Coeffs in the D written at `time` (the
    slave's entry: the coefficients the run used, macros expanded)."""
    text = foamio.strip(open(os.path.join(case, time, "D")).read())
    coeffs = foamio.sub_dict(text, method + "Coeffs")
    return dict(cN=float(foamio.entry(coeffs, "cN")), n=float(foamio.entry(coeffs, "n")))


def no_contact(time, wx, slave):
    """Both checks failed: nothing to compare with."""
    print("compareHertz: no contact on %s at time %s" % (slave, time))
    inf = float("inf")
    checks = [
        dict(name="hertzCylinder/peak_pressure", value=0.0, reference=0.0, error=inf,
             tolerance=P0_TOL, units="Pa (error: fraction of Hertz)", passed=False),
        dict(name="hertzCylinder/contact_half_width", value=0.0, reference=0.0, error=inf,
             tolerance=A_TOL_FACES * float(wx[0]), units="m", passed=False),
    ]
    return dict(time=time, checks=checks, P=0.0)


def compare(case, estar="both", time=None, patch=None):
    """The comparison at `time` (a directory name; default the latest) of
    the pressure on `patch` (default the slave; the master's is the
    pressure the slave's tractions put on it, per its own area)."""
    time = time or foamio.latest_time(case)
    slave = patch or patchtest.slave_patch(case, time, PATCHES)
    Es, materials = contact_modulus(case, estar)
    dz = foamio.thickness(case)

    Cf, Sf = foamio.patch_geometry(case, slave)
    n = Cf.shape[0]
    area = np.linalg.norm(Sf, axis=1)
    nf = Sf / area[:, None]
    p = foamio.read_patch(os.path.join(case, time, "contactPressure"), slave, n)
    activePath = os.path.join(case, time, "contactActive")
    if os.path.exists(activePath):
        active = foamio.read_patch(activePath, slave, n) > 0.5
        activeFrom = "contactActive"
    else:
        active = p > 1e-6 * max(p.max(), 0.0) if p.max() > 0 else np.zeros(n, bool)
        activeFrom = "p > 1e-6 max p"

    order = np.argsort(Cf[:, 0])
    x = Cf[order, 0]
    p, active, area, nf = p[order], active[order], area[order], nf[order]
    # face width projected on x (faces are one cell thick in z)
    wx = area / dz * np.abs(nf[:, 1])

    P = 2.0 * float(np.sum(p * area * np.abs(nf[:, 1]))) / dz
    if not active.any() or P <= 0:
        return no_contact(time, wx, slave)
    aH = hertz.half_width(P, R, Es)
    p0H = hertz.peak_pressure(P, aH)

    iLast = int(np.nonzero(active)[0].max())
    aNum = float(x[iLast] + 0.5 * wx[iLast])
    holes = int((~active[:iLast + 1]).sum())
    iA = int(np.argmin(np.abs(x - aH)))
    hA = float(wx[iA])

    iMax = int(np.argmax(p))
    p0Ref = float(hertz.pressure(x[iMax], P, R, Es))

    # Least-squares ellipse through the active faces: p^2 = c0 + c1 x^2
    if active.sum() >= 3:
        c1, c0 = np.polyfit(x[active] ** 2, p[active] ** 2, 1)
        aFit = float(np.sqrt(-c0 / c1)) if c1 < 0 < c0 else float("nan")
    else:
        aFit = float("nan")

    extra = {}
    tPath = os.path.join(case, time, "contactTraction")
    if os.path.exists(tPath):
        tr = foamio.read_patch(tPath, slave, n)[order]
        extra["P_contactTraction"] = 2.0 * float(np.sum(np.abs(tr[:, 1]) * area)) / dz
    rep = (contactreport.row_at(case, slave, float(time)) if time != foamio.latest_time(case)
           else contactreport.last_row(case, slave))
    if rep and "normalForce" in rep:
        extra["P_contactReport"] = 2.0 * rep["normalForce"] / dz
        extra["report"] = rep

    method = None
    try:
        method = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    except (KeyError, OSError):
        pass

    # The reference: Hertz, or Hertz with the constitutive interface law
    law, aRef, what = None, float(aH), "Hertz"
    if method is not None and methods.get(method).answer == "constitutive":
        law = interface_law(case, time, method)
        law.update(hertz.interface_law_contact(P, R, Es, law["cN"], law["n"]))
        p0Ref = float(np.interp(x[iMax], law["x"], law["p"]))
        aRef = law["a"]
        what = "Hertz with the interface law"

    checks = [
        dict(name="hertzCylinder/peak_pressure", value=float(p[iMax]), reference=p0Ref,
             error=abs(float(p[iMax]) - p0Ref) / p0Ref, tolerance=P0_TOL,
             units="Pa (error: fraction of %s)" % what),
        dict(name="hertzCylinder/contact_half_width", value=aNum, reference=aRef,
             error=abs(aNum - aRef), tolerance=A_TOL_FACES * hA,
             units="m (tolerance: %.1f face widths)" % A_TOL_FACES),
    ]
    if law is not None:
        g = foamio.read_patch(os.path.join(case, time, "contactGap"), slave, n)[order]
        iPen = int(np.argmin(g))
        pen = float(-g[iPen])
        penRef = float((np.interp(x[iPen], law["x"], law["p"]) / law["cN"]) ** (1.0 / law["n"]))
        law["maxPenetration"] = pen
        checks.append(dict(name="hertzCylinder/max_penetration", value=pen, reference=penRef,
                           error=abs(pen - penRef) / penRef, tolerance=P0_TOL / law["n"],
                           units="m (error: fraction of (p_ref/cN)^(1/n))"))
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])
    if law is not None:
        law = dict(cN=law["cN"], n=law["n"], a=law["a"], p0=law["p0"],
                   penetration=law["penetration"], maxPenetration=law["maxPenetration"],
                   x=law["x"].tolist(), p=law["p"].tolist())
    return dict(time=time, method=method, P=P, aH=aH, p0H=p0H, aNum=aNum, aFit=aFit, law=law,
                hA=hA, holes=holes, activeFrom=activeFrom, nActive=int(active.sum()),
                slave=slave, materials=materials, Es=Es,
                x=x.tolist(), p=p.tolist(), active=active.tolist(),
                extra=extra, checks=checks)


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    aH, p0H = res["aH"], res["p0H"]
    x = np.array(res["x"])
    p = np.array(res["p"])
    xr = 1.6 * max(aH, res["aNum"])
    sel = x < xr
    xx = np.linspace(0, xr, 600)
    fig, ax = plt.subplots(figsize=(6.5, 4))
    ax.plot(xx * 1e3, hertz.pressure(xx, res["P"], R, res["Es"]) / 1e6, "k-",
            label="Hertz for the measured P' = %.4g N/m" % res["P"])
    if res.get("law"):
        lx, lp = np.array(res["law"]["x"]), np.array(res["law"]["p"])
        ax.plot(lx * 1e3, lp / 1e6, "C0-", lw=1,
                label="Hertz with the law c_N = %g, n = %g" % (res["law"]["cN"], res["law"]["n"]))
    ax.plot(x[sel] * 1e3, p[sel] / 1e6, "o", ms=4,
            label="solidContactFoam (%s faces)" % (res["method"] or "contact"))
    ax.axvline(aH * 1e3, color="k", ls=":", lw=1)
    ax.axvline(res["aNum"] * 1e3, color="C3", ls="--", lw=1,
               label="a: Hertz %.3f mm, numerical %.3f mm" % (aH * 1e3, res["aNum"] * 1e3))
    ax.set_xlabel("x [mm] on %s" % res["slave"])
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_title("hertzCylinder: p0 Hertz %.0f MPa, numerical %.0f MPa"
                 % (p0H / 1e6, p.max() / 1e6))
    ax.set_xlim(0, xr * 1e3)
    ax.set_ylim(0, 1.15 * max(p0H, p.max()) / 1e6)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "hertzPressure.png", [
        ("--estar", dict(choices=("both", "block"), default="both",
                         help="E* of both bodies (default) or of the block alone")),
        ("--time", dict(default=None, help="the time to compare (default: the latest)")),
        ("--patch", dict(choices=PATCHES, default=None,
                         help="the patch whose pressure is compared (default: the slave)"))])
    res = compare(args.case, args.estar, args.time, args.patch)
    if res["P"] <= 0:
        for c in res["checks"]:
            print("FAIL %-45s (no contact)" % c["name"])
        if args.json:
            with open(args.json, "w") as f:
                json.dump(res["checks"], f, indent=1)
        return 1
    print("hertzCylinder: contact pressure on %s against Hertz (time %s, method %s)"
          % (res["slave"], res["time"], res["method"]))
    print("  materials: %s" % res["materials"])
    print("  E* = %.6g Pa, R = %g m; measured P' = %.6g N/m (full cylinder)"
          % (res["Es"], R, res["P"]))
    for k in ("P_contactTraction", "P_contactReport"):
        if k in res["extra"]:
            print("  P' from %-16s = %.6g N/m (%+.3g %% of the pressure resultant)"
                  % (k[2:], res["extra"][k], 100 * (res["extra"][k] / res["P"] - 1)))
    print("  Hertz: a = %.5g mm, p0 = %.6g MPa" % (res["aH"] * 1e3, res["p0H"] / 1e6))
    if res["law"]:
        lw = res["law"]
        print("  Hertz with the interface law p = cN (-g)^n, cN = %g, n = %g: a = %.5g mm,"
              " p0 = %.6g MPa (%+.3g %% of Hertz), penetration %.4g m; numerical max"
              " penetration %.4g m" % (lw["cN"], lw["n"], lw["a"] * 1e3, lw["p0"] / 1e6,
                                       100 * (lw["p0"] / res["p0H"] - 1), lw["penetration"],
                                       lw["maxPenetration"]))
    print("  numerical: %d active faces (%s), a = %.5g mm (edge of the last active face),"
          " a_fit = %.5g mm (ellipse fit), face width at a = %.4g mm"
          % (res["nActive"], res["activeFrom"], res["aNum"] * 1e3, res["aFit"] * 1e3,
             res["hA"] * 1e3))
    if res["holes"]:
        print("  WARNING: %d inactive faces inside the contact strip" % res["holes"])
    if not 4e-3 <= res["aH"] <= 8e-3:
        print("  NOTE: a is outside the 5-7 mm the mesh is graded for (DELTA in 0/D)")
    # the reference of the checks: Hertz, or Hertz with the interface law
    x, p = np.array(res["x"]), np.array(res["p"])
    if res["law"]:
        ref = np.interp(x, res["law"]["x"], res["law"]["p"], right=0.0)
        refName, aRef, p0Ref = "law [MPa]", res["law"]["a"], res["law"]["p0"]
    else:
        ref = hertz.pressure(x, res["P"], R, res["Es"])
        refName, aRef, p0Ref = "Hertz [MPa]", res["aH"], res["p0H"]
    print("%10s %10s %14s %14s %10s %6s" % ("x [mm]", "x/a", "p [MPa]", refName,
                                             "err/p0", "active"))
    show = np.nonzero(x < 1.25 * aRef)[0]
    for i in list(show[::2]) + ([show[-1]] if len(show) % 2 == 0 else []):
        print("%10.4f %10.4f %14.6g %14.6g %10.4f %6d"
              % (x[i] * 1e3, x[i] / aRef, p[i] / 1e6, ref[i] / 1e6,
                 (p[i] - ref[i]) / p0Ref, res["active"][i]))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
