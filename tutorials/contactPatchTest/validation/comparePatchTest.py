#!/usr/bin/python3
"""contactPatchTest: the stress must be uniform across a non-matching interface.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression runner (tests/run.py) reads
them with --json.

Two blocks (lower 10 x 5 cells, upper 7 x 4, 1 m wide, column height
L = 1 m) are pressed together by moving the upper top down by
Delta = 0.01 m with the lower bottom held. With nu = 0 the exact state is
uniaxial and uniform: sigma_yy = -E Delta / L = -1e4 Pa in every cell, and
the contact pressure is 1e4 Pa on every face (E' = E/(1 - nu^2) replaces E
in plane strain with nu != 0; the case has nu = 0).

lagrangeMultiplier (the gap is closed exactly): max over ALL cells of
    |sigma_yy - sigma_exact| / |sigma_exact|  <=  1e-6.
  A patch test is passed exactly or not at all (uniform strain is
  represented exactly by the discretisation); 1e-6 leaves room for the
  outer correctors, which stop at a residual of 1e-9 (system/fvSolution),
  and for the 12 significant digits of the ASCII output.

penalty (eps_N = penaltyScale K / h, K = 2 mu + lambda, h = V/A of the
slave face cells, read from 0/D and the mesh): the penalty spring is in
series with the column, so the state is uniform too, with
    sigma_pen = -E' Delta / (L + E'/eps_N)
and the predicted offset of every cell's relative error is
    offset = 1 - L/(L + E'/eps_N)       (= 1 - L/(L + h/s) for nu = 0).
  Checks: |max relative error - offset| <= 1e-3 offset (the penalty
  solution is exact to the same 1e-6 as above, which is ~1e-4 of the
  ~1e-2 offset: 1e-3 of it has a factor 10 of margin) and
  (max - min sigma_yy)/|sigma_exact| <= 1e-6.

Both: the total normal force on the slave patch, sum_f p_f |Sf_f|, against
|sigma| (exact or penalty) times the patch area (1 m x dz), with the same
tolerance as the stress; and, when the contactReport function object wrote
postProcessing/contactReport/*/lowerTop.dat, its last normalForce likewise.
"""
import json
import os
import sys

# In the repository the package is three levels up; a copied case finds it
# through $C4F_ROOT, which etc/bashrc exports
for _p in (os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../src/postProcessing/python"),
           os.path.join(os.environ.get("C4F_ROOT", ""), "src/postProcessing/python")):
    if os.path.isdir(os.path.join(_p, "c4fpost")):
        sys.path.insert(0, _p)
        break
from c4fpost import foamio, hertz, report, contactreport  # noqa: E402

import numpy as np  # noqa: E402

DELTA = 0.01    # downward displacement of upperTop [m], 0/D
L = 1.0         # height of the two-block column [m], system/blockMeshDict
SLAVE = "lowerTop"
MASTER = "upperBottom"
EXACT_TOL = 1e-6


def compare(case):
    time = foamio.latest_time(case)
    E, nu, planeStress = hertz.elastic_constants(case)
    Eu = E if planeStress else E / (1.0 - nu * nu)     # uniaxial stress, free sides
    K = hertz.impK(E, nu, planeStress)
    exact = -Eu * DELTA / L

    D0 = os.path.join(case, "0", "D")
    method = hertz.read_entry(D0, "method")
    C, V = hertz.cell_centres_volumes(case)
    Cf, Sf = hertz.patch_geometry(case, SLAVE)
    area = np.linalg.norm(Sf, axis=1)
    slaveCells = foamio.patch_face_cells(case, SLAVE)
    h = V[slaveCells] / area

    sigma = foamio.read_internal(os.path.join(case, time, "sigma"), V.size)
    syy = sigma[:, 3]
    rel = np.abs(syy - exact) / abs(exact)
    maxRel = float(rel.max())
    spread = float((syy.max() - syy.min()) / abs(exact))

    res = dict(time=time, method=method, E=E, nu=nu, K=K, exact=exact, maxRel=maxRel,
               spread=spread, h=h.tolist())
    if method == "penalty":
        s = hertz.read_entry(D0, "penaltyScale")
        eps = s * K / h
        if np.ptp(eps) > 1e-12 * eps.max():
            print("NOTE: the slave cells' h = V/A varies (%g .. %g); using the mean"
                  % (h.min(), h.max()))
        eps = float(eps.mean())
        predicted = -Eu * DELTA / (L + Eu / eps)
        offset = 1.0 - L / (L + Eu / eps)
        tol = 1e-3 * offset
        res.update(penaltyScale=s, eps=eps, predicted=predicted, offset=offset)
        checks = [
            dict(name="contactPatchTest/syy_penalty_offset", value=maxRel, reference=offset,
                 error=abs(maxRel - offset), tolerance=tol, units="fraction of |sigma_exact|"),
            dict(name="contactPatchTest/syy_uniformity", value=spread, reference=0.0,
                 error=spread, tolerance=EXACT_TOL, units="fraction of |sigma_exact|"),
        ]
        forceTol = tol
    else:
        predicted = exact
        res.update(predicted=predicted, offset=0.0)
        checks = [
            dict(name="contactPatchTest/syy_max_rel_error", value=maxRel, reference=0.0,
                 error=maxRel, tolerance=EXACT_TOL, units="fraction of |sigma_exact|"),
        ]
        forceTol = EXACT_TOL

    # Contact force on the slave patch
    p = foamio.read_patch(os.path.join(case, time, "contactPressure"), SLAVE, area.size)
    F = float(np.sum(p * area))
    Fref = abs(predicted) * float(area.sum())
    checks.append(dict(name="contactPatchTest/contact_force", value=F, reference=Fref,
                       error=abs(F - Fref) / Fref, tolerance=forceTol, units="N"))
    rep = contactreport.last_row(case, SLAVE)
    if rep and "normalForce" in rep:
        Fr = rep["normalForce"]
        checks.append(dict(name="contactPatchTest/contactReport_normalForce", value=Fr,
                           reference=Fref, error=abs(Fr - Fref) / Fref, tolerance=forceTol,
                           units="N"))
    res["report"] = rep
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])

    # Data for the table and the plot: the column of cells nearest x = 0.5 in
    # each block, and the interface pressures
    cols = []
    for body in (C[:, 1] < 0.5, C[:, 1] > 0.5):
        idx = np.nonzero(body)[0]
        dx = np.abs(C[idx, 0] - 0.5)
        col = idx[dx <= dx.min() + 1e-9]
        xcol = C[col, 0].min()
        col = col[np.abs(C[col, 0] - xcol) < 1e-9]
        cols.extend(col[np.argsort(C[col, 1])].tolist())
    cols = np.array(cols)
    res.update(colX=C[cols, 0].tolist(), colY=C[cols, 1].tolist(), colSyy=syy[cols].tolist(),
               slaveX=Cf[:, 0].tolist(), slaveP=p.tolist(), F=F, Fref=Fref)
    try:
        CfM, SfM = hertz.patch_geometry(case, MASTER)
        pM = foamio.read_patch(os.path.join(case, time, "contactPressure"), MASTER, len(CfM))
        res.update(masterX=CfM[:, 0].tolist(), masterP=pM.tolist())
    except (KeyError, ValueError, AttributeError):
        pass
    res["checks"] = checks
    return res


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ex = abs(res["exact"])
    pred = abs(res["predicted"])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    y = np.array(res["colY"])
    a1.plot(np.array(res["colSyy"]) / ex, y, "o", label="cells nearest x = 0.5")
    a1.axvline(-1.0, color="k", lw=1, label="exact (gap closed)")
    if res["method"] == "penalty":
        a1.axvline(-pred / ex, color="C3", ls="--", lw=1, label="penalty prediction")
    a1.axhline(0.5, color="0.6", ls=":", lw=1)
    a1.set_xlabel(r"$\sigma_{yy}$ / |E $\Delta$/L|")
    a1.set_ylabel("y [m]")
    a1.set_title("stress along the vertical centre line")
    a1.legend(fontsize=8)
    a1.grid(alpha=0.3)
    a2.plot(res["slaveX"], np.array(res["slaveP"]) / ex, "o", label="lowerTop (slave, 10 faces)")
    if "masterX" in res:
        a2.plot(res["masterX"], np.array(res["masterP"]) / ex, "s", mfc="none",
                label="upperBottom (master, 7 faces)")
    a2.axhline(1.0, color="k", lw=1, label="exact")
    if res["method"] == "penalty":
        a2.axhline(pred / ex, color="C3", ls="--", lw=1, label="penalty prediction")
    a2.set_xlabel("x [m]")
    a2.set_ylabel("contact pressure / |E $\\Delta$/L|")
    a2.set_title("interface pressure (%s)" % res["method"])
    a2.legend(fontsize=8)
    a2.grid(alpha=0.3)
    for ax in (a1, a2):
        ax.ticklabel_format(useOffset=False)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "patchTest.png")
    res = compare(args.case)
    print("contactPatchTest: sigma_yy over all cells (time %s, method %s)"
          % (res["time"], res["method"]))
    print("  E = %g Pa, nu = %g, K = 2mu + lambda = %g Pa; exact sigma_yy = %g Pa"
          % (res["E"], res["nu"], res["K"], res["exact"]))
    if res["method"] == "penalty":
        print("  penalty: scale %g, h = V/A = %g m, eps_N = %g Pa/m -> sigma = %.9g Pa,"
              " offset %.6g" % (res["penaltyScale"], np.mean(res["h"]), res["eps"],
                                res["predicted"], res["offset"]))
    print("  max |sigma_yy - exact|/|exact| = %.4g, (max - min)/|exact| = %.4g"
          % (res["maxRel"], res["spread"]))
    print("  contact force on %s: %.9g N (expected %.9g N)" % (SLAVE, res["F"], res["Fref"]))
    if res["report"] is None:
        print("  (no postProcessing/contactReport/*/%s.dat)" % SLAVE)
    print("%8s %8s %16s" % ("x", "y", "sigma_yy [Pa]"))
    for x, y, s in zip(res["colX"], res["colY"], res["colSyy"]):
        print("%8.4f %8.4f %16.9g" % (x, y, s))
    report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    main()
