#!/usr/bin/python3
"""hertzCylinderPrisms: compare the contact pressure on the skewed prisms with Hertz.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

Data (latest time or --time, reference configuration): contactPressure and
contactActive on the slave patch (blockContact, or cylinderContact after
Allrun -slave cylinder: the patch with `master no` in the written D), its
face centres from constant/polyMesh (c4fpost.foamio.patch_geometry); x is
the face centre's abscissa.

Materials: constant/mechanicalProperties, one law for both bodies (E, nu,
plane strain): E* = E/(2 (1 - nu^2)) (Johnson 1985, eq. 4.22); R = 0.1 m,
the block flat. The closed forms are c4fpost.hertz's, as hertzCylinder's
compareHertz.py uses them.

Load. The model is the half x >= 0, one cell (dz) thick, so the load per
unit length of the FULL cylinder is P' = 2 F_N / dz, F_N the last
normalForce of contactReport (postProcessing/contactReport/0/<slave>.dat,
the sum of p |Sf| over the slave faces). Hertz's a and p0 are evaluated
for that load, so the test does not depend on how well DELTA was
estimated. The vertical resultant of contactPressure, 2 sum p |Sf| |n_y| /
dz, is printed beside it (the same on the flat block top).

Checks (the targets for a slave patch whose cells are skewed: about 16
faces across a, cells that are right triangles all leaning one way, 26.6
degrees non-orthogonal at the slave faces; hertzCylinder's orthogonal mesh
with 23 faces across a gives 1.2 %):
  - peak pressure: max_f p_f against Hertz p(x) at the centre of that face
    (x = h/2 for the first face: p = p0 sqrt(1 - h^2/4a^2), 0.05 % below
    p0 for h = a/16; evaluating Hertz there removes that bias). Tolerance
    P0_TOL = 1.5 % of the Hertz value.
  - pressure inside the contact: the RMS over the faces with x < 0.8 a of
    p_f - p_Hertz(x_f), over p0. Beyond 0.8 a the pressure's slope
    p0 x / (a sqrt(a^2 - x^2)) grows without bound and a face value cannot
    follow it (as hertzSphere's compareSphere.py). Tolerance RMS_TOL =
    1.5 % of p0.
The half-width of the active faces (the outer edge of the last one) is
printed against Hertz's a, not checked.
"""
import json
import os
import sys

from c4fpost import contactreport, foamio, hertz, patchtest, report

import numpy as np

NAME = "hertzCylinderPrisms"
R = 0.1                   # cylinder radius [m], hertzCylinderPrisms.geo
PATCHES = ("blockContact", "cylinderContact")
P0_TOL = 0.015            # fraction of the Hertz pressure at the peak face
RMS_TOL = 0.015           # fraction of p0, faces with x < RMS_SPAN a
RMS_SPAN = 0.8


def failed(time, slave, why):
    """Both checks failed: nothing to compare with."""
    print("%s: %s on %s at time %s" % (NAME, why, slave, time))
    inf = float("inf")
    checks = [dict(name="%s/%s" % (NAME, k), value=0.0, reference=0.0, error=inf,
                   tolerance=tol, units=why, passed=False)
              for k, tol in (("peak_pressure", P0_TOL), ("pressure_rms", RMS_TOL))]
    return dict(time=time, checks=checks, P=0.0)


def compare(case, time=None):
    """The comparison at `time` (a directory name; default the latest)."""
    time = time or foamio.latest_time(case)
    slave = patchtest.slave_patch(case, time, PATCHES)
    (b1, b2), materials = foamio.body_constants(case)
    Es = hertz.contact_modulus(*b1, *b2)
    dz = foamio.thickness(case)

    Cf, Sf = foamio.patch_geometry(case, slave)
    n = Cf.shape[0]
    area = np.linalg.norm(Sf, axis=1)
    ny = np.abs(Sf[:, 1]) / area
    p = foamio.read_patch(os.path.join(case, time, "contactPressure"), slave, n)
    active = foamio.read_patch(os.path.join(case, time, "contactActive"), slave, n) > 0.5
    order = np.argsort(Cf[:, 0])
    x, p, active, area, ny = Cf[order, 0], p[order], active[order], area[order], ny[order]
    # face width projected on x (faces one cell thick in z)
    wx = area / dz * ny

    rep = (contactreport.row_at(case, slave, float(time)) if time != foamio.latest_time(case)
           else contactreport.last_row(case, slave))
    if not rep or "normalForce" not in rep:
        return failed(time, slave, "no contactReport row")
    P = 2.0 * rep["normalForce"] / dz
    Presultant = 2.0 * float(np.sum(p * area * ny)) / dz
    if not active.any() or P <= 0:
        return failed(time, slave, "no contact")
    aH = hertz.half_width(P, R, Es)
    p0H = hertz.peak_pressure(P, aH)
    pH = hertz.pressure(x, P, R, Es)

    iMax = int(np.argmax(p))
    p0Ref = float(pH[iMax])
    inner = x < RMS_SPAN * aH
    rms = float(np.sqrt(np.mean((p[inner] - pH[inner]) ** 2))) / p0H
    iLast = int(np.nonzero(active)[0].max())
    aNum = float(x[iLast] + 0.5 * wx[iLast])
    hA = float(wx[int(np.argmin(np.abs(x - aH)))])
    holes = int((~active[:iLast + 1]).sum())

    method = None
    try:
        method = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    except (KeyError, OSError):
        pass

    checks = [
        dict(name=NAME + "/peak_pressure", value=float(p[iMax]), reference=p0Ref,
             error=abs(float(p[iMax]) - p0Ref) / p0Ref, tolerance=P0_TOL,
             units="Pa (error: fraction of Hertz at the peak face)"),
        dict(name=NAME + "/pressure_rms", value=rms, reference=0.0, error=rms,
             tolerance=RMS_TOL, units="fraction of p0, x < %.1f a" % RMS_SPAN),
    ]
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])
    return dict(time=time, method=method, slave=slave, materials=materials, Es=Es, P=P,
                Presultant=Presultant, report=rep, aH=aH, p0H=p0H, aNum=aNum, hA=hA,
                holes=holes, rms=rms, nActive=int(active.sum()), nInner=int(inner.sum()),
                x=x.tolist(), p=p.tolist(), pH=pH.tolist(), active=active.tolist(),
                checks=checks)


def plot(res, png):
    plt = patchtest.pyplot()
    aH, p0H = res["aH"], res["p0H"]
    x, p = np.array(res["x"]), np.array(res["p"])
    active = np.array(res["active"], bool)
    xr = 1.6 * max(aH, res["aNum"])
    sel = x < xr
    xx = np.linspace(0, xr, 600)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True,
                                 gridspec_kw=dict(height_ratios=(2, 1)))
    a1.plot(xx * 1e3, hertz.pressure(xx, res["P"], R, res["Es"]) / 1e6, "k-",
            label="Hertz for contactReport's P' = %.4g N/m" % res["P"])
    a1.plot(x[sel & active] * 1e3, p[sel & active] / 1e6, "o", ms=4,
            label="solidContactFoam, %s: active faces" % (res["method"] or "contact"))
    a1.plot(x[sel & ~active] * 1e3, p[sel & ~active] / 1e6, "x", ms=4, color="C7",
            label="open faces")
    a1.axvline(aH * 1e3, color="k", ls=":", lw=1)
    a1.set_ylabel("contact pressure [MPa]")
    a1.set_title("%s: p0 Hertz %.0f MPa, numerical %.0f MPa (%+.2f %%)"
                 % (NAME, p0H / 1e6, p.max() / 1e6,
                    100 * (res["checks"][0]["value"] / res["checks"][0]["reference"] - 1)))
    a1.set_ylim(0, 1.15 * max(p0H, p.max()) / 1e6)
    a1.grid(alpha=0.3)
    a1.legend(fontsize=8)
    err = (p - np.array(res["pH"])) / p0H
    a2.plot(x[sel] * 1e3, 100 * err[sel], "o-", ms=3, lw=0.5)
    a2.axhline(0.0, color="k", lw=1)
    a2.axvline(RMS_SPAN * aH * 1e3, color="C3", ls="--", lw=1,
               label="%.1f a: RMS %.2f %% of p0 inside" % (RMS_SPAN, 100 * res["rms"]))
    a2.axvline(aH * 1e3, color="k", ls=":", lw=1)
    a2.set_xlabel("x [mm] on %s (face centres)" % res["slave"])
    a2.set_ylabel("(p - Hertz)/p0 [%]")
    a2.set_xlim(0, xr * 1e3)
    a2.grid(alpha=0.3)
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "hertzPrismsPressure.png", [
        ("--time", dict(default=None, help="the time to compare (default: the latest)"))])
    res = compare(args.case, args.time)
    if res["P"] <= 0:
        report.print_checks(res["checks"])
        if args.json:
            with open(args.json, "w") as f:
                json.dump(res["checks"], f, indent=1)
        return 1
    print("%s: contact pressure on %s against Hertz (time %s, method %s)"
          % (NAME, res["slave"], res["time"], res["method"]))
    print("  materials: %s" % res["materials"])
    print("  E* = %.6g Pa, R = %g m; contactReport P' = %.6g N/m (full cylinder, %d"
          " correctors); the vertical resultant of contactPressure %+.3g %% of it"
          % (res["Es"], R, res["P"], res["report"].get("outerCorrectors", -1),
             100 * (res["Presultant"] / res["P"] - 1)))
    print("  Hertz: a = %.5g mm, p0 = %.6g MPa" % (res["aH"] * 1e3, res["p0H"] / 1e6))
    p = np.array(res["p"])
    print("  numerical: p_max = %.6g MPa (%+.3g %% of p0, %+.3g %% of Hertz at its face),"
          " %d active faces, a = %.5g mm (edge of the last active face; %.1f faces of"
          " %.4g mm across Hertz's a)"
          % (p.max() / 1e6, 100 * (p.max() / res["p0H"] - 1),
             100 * (res["checks"][0]["value"] / res["checks"][0]["reference"] - 1),
             res["nActive"], res["aNum"] * 1e3, res["aH"] / res["hA"], res["hA"] * 1e3))
    print("  RMS of p - p_Hertz over the %d faces with x < %.1f a: %.3g %% of p0"
          % (res["nInner"], RMS_SPAN, 100 * res["rms"]))
    if res["holes"]:
        print("  WARNING: %d inactive faces inside the contact strip" % res["holes"])
    x, pH = np.array(res["x"]), np.array(res["pH"])
    print("%10s %10s %14s %14s %10s %6s" % ("x [mm]", "x/a", "p [MPa]", "Hertz [MPa]",
                                             "err/p0", "active"))
    for i in np.nonzero(x < 1.25 * res["aH"])[0]:
        print("%10.4f %10.4f %14.6g %14.6g %10.4f %6d"
              % (x[i] * 1e3, x[i] / res["aH"], p[i] / 1e6, pH[i] / 1e6,
                 (p[i] - pH[i]) / res["p0H"], res["active"][i]))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
