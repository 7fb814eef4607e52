#!/usr/bin/python3
"""contactPatchTestTets: the stress and the contact pressure must be uniform across non-matching tetrahedra.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

contactPatchTest3D's test (its comparePatchTest3D.py gives the derivations
in full) on tetrahedra: two boxes 1 x 1 x 0.5 m stacked in z, each meshed
by gmsh on its own (upper: edges of 0.1 m, its bottom upperBottom the
slave; lower: 0.14 m, its top lowerTop the master; column height
L = 1 m), pressed together by moving the upper top down by Delta = 0.01 m
(normal component only) with the lower bottom held in z. Symmetry planes
at x = 0 and y = 0, traction-free faces at x = 1 and y = 1: for any nu
the exact state is uniaxial stress,
    sigma_zz = -E Delta / L = -1e4 Pa (E = 1e6 Pa),
all other components 0, in every cell, and the contact pressure is
1e4 Pa on every face. A linear displacement is represented exactly on
any mesh (leastSquares gradients are exact for it), so the patch test is
passed exactly or not at all.

Frame. With Allrun -rotate (30 degrees about (1 2 3)) the stress is
compared in the boxes' frame, sigma' = R^T sigma R, R from the patch
normals (R e_z the outward normal of upperTop, R e_x that of symmetryX
negated); not rotated, R = I to round-off.

The answer each method gives follows from its traits (c4fpost.patchtest,
as comparePatchTest3D.py): exact (lagrangeMultiplier, ...; and
-noContact, the exact state given to both contact patches), penalty (the
series spring eps_N = penaltyScale K/h, h = V/A of the slave cells: on
tetrahedra h differs from face to face, and the offset is predicted with
its mean), constitutive law or barrier (their series solutions; the
barrier's needs one stiffness kappa = kappaScale K/h on every face, which
tetrahedra do not give: its check fails, saying so). The
predicted uniform stress sigma_pred (the exact -E Delta/L, or the series
solution) is checked with c4fpost.patchtest's checks (the tolerances of
comparePatchTest3D.py: 1e-6 of |sigma| for the exact state and every
uniformity; the penalty's offset to 1e-3 of itself), and:
  - contact_pressure: max over the slave faces of |p_f - |sigma_pred|| /
    |sigma_pred|, with the tolerance of the stress check (1e-6 for the
    exact methods; the penalty's offset tolerance, max(1e-3 offset, 1e-6));
  - other_components: max over the cells of |sigma'_ij| / |sigma_exact|
    for ij = xx, yy, xy, xz, yz; tolerance 1e-6;
  - load_direction: the top displacement of 0/D against R (0 0 -Delta),
    1e-8 of Delta;
  - contact_force (and contactReport's normalForce) against |sigma_pred|
    times the slave's area;
  - converged: the last step of log.solidContactFoam converged, its
    residual below solidMechanics' tolerance.
The master's contact pressure (the slave's, transferred) is printed, not
checked.
"""
import os
import sys

from c4fpost import elastic, foamio, patchtest, report

import numpy as np

NAME = "contactPatchTestTets"
DELTA = 0.01    # downward displacement of upperTop [m], 0/D
L = 1.0         # height of the two-box column [m], contactPatchTestTets.geo
SLAVE = "upperBottom"
MASTER = "lowerTop"
TOP = "upperTop"           # outward normal R e_z
SYMMETRY_X = "symmetryX"   # outward normal -R e_x
EXACT_TOL = 1e-6
OFFSET_TOL = 1e-3   # fraction of the penalty offset
LOAD_TOL = 1e-8
TEST = patchtest.PatchTest(NAME, SLAVE, MASTER, DELTA, L, EXACT_TOL, OFFSET_TOL)
OTHERS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}


def compare(case):
    contact, method = patchtest.contact_variant(case, SLAVE)
    time = foamio.latest_time(case)
    E, nu, _ = foamio.elastic_constants(case)
    K = elastic.impK(E, nu)
    exact = -E * DELTA / L

    R = patchtest.rotation_from_mesh(case, TOP, SYMMETRY_X)
    C, V = foamio.cell_centres_volumes(case)
    Cr = C @ R
    Cf, area, slaveCells, h = TEST.slave_geometry(case, V)
    # cellSize patch (the slave's entry): one h, sum V / sum A, on every
    # face, as the solver takes it (contactSettings)
    try:
        cellSize = foamio.read_entry(os.path.join(case, "0", "D"), "cellSize")
    except (KeyError, OSError):
        cellSize = "face"
    if cellSize == "patch":
        h = np.full_like(h, float(np.sum(h * area) / np.sum(area)))
    S = patchtest.stress_tensor(case, time, V.size)
    Sr = np.einsum("ki,nkl,lj->nij", R, S, R)
    szz = Sr[:, 2, 2]
    maxRel, spread = patchtest.uniformity(szz, exact)
    others = {k: float(np.abs(Sr[:, i, j]).max() / abs(exact)) for k, (i, j) in OTHERS.items()}
    worst = max(others, key=others.get)
    d = patchtest.top_displacement(case)
    loadErr = float(np.linalg.norm(d - R @ np.array([0.0, 0.0, -DELTA])) / DELTA)

    kind = patchtest.method_check(method)["kind"] if contact else "exact"
    res = dict(time=time, method=method, contact=contact, kind=kind, E=E, nu=nu, K=K,
               exact=exact, maxRel=maxRel, spread=spread, others=others, R=R.tolist(),
               rotated=bool(np.abs(R - np.eye(3)).max() > 1e-6), h=h.tolist(),
               nCells=int(V.size), nSlave=int(area.size))
    checks = [dict(name=NAME + "/load_direction", value=float(np.linalg.norm(d)),
                   reference=DELTA, error=loadErr, tolerance=LOAD_TOL,
                   units="m (error: |D_top - R (0 0 -Delta)|/Delta)")]
    if kind == "constitutive":
        stress, predicted, tol = TEST.constitutive_checks(case, time, res, "szz", szz, E,
                                                          area.size, method)
    elif kind == "barrier":
        try:
            stress, predicted, tol = TEST.barrier_checks(case, time, res, "szz", szz, E,
                                                         area.size, h, method)
        except RuntimeError as e:
            # kappa = kappaScale K/h of each face: on tetrahedra h differs
            # from face to face, and the series solution has no one kappa
            stress = [dict(name=NAME + "/szz_barrier_law", value=float("inf"), reference=0.0,
                           error=float("inf"), tolerance=EXACT_TOL, passed=False,
                           units=str(e))]
            predicted, tol = exact, EXACT_TOL
    else:
        stress, predicted, tol = TEST.stress_checks(
            case, res, "szz", kind == "penalty", E, K, h, method,
            patchtest.method_check(method).get("scale") if contact else None)
    checks += stress
    checks.append(dict(name=NAME + "/other_components", value=others[worst], reference=0.0,
                       error=others[worst], tolerance=EXACT_TOL,
                       units="max |sigma'_%s|/|sigma_exact|" % worst))
    res["report"] = None
    if contact:
        checks += TEST.force_checks(case, time, res, area, predicted, tol)
        p = np.array(res["slaveP"])
        pErr = float(np.abs(p - abs(predicted)).max() / abs(predicted))
        checks.append(dict(name=NAME + "/contact_pressure", value=float(p.mean()),
                           reference=abs(predicted), error=pErr, tolerance=tol,
                           units="Pa (error: max_f |p_f - |sigma_pred||/|sigma_pred|)"))
        TEST.master_pressure(case, time, res, R)
        res.update(slaveX=(Cf @ R)[:, 0].tolist(), pErr=pErr, pMin=float(p.min()),
                   pMax=float(p.max()))
    conv, step, _ = patchtest.convergence_check(case, NAME)
    checks.append(conv)
    res.update(step=step, predicted=predicted, szz=szz.tolist(), z=Cr[:, 2].tolist())
    patchtest.set_passed(checks)
    res["checks"] = checks
    return res


def plot(res, png):
    plt = patchtest.pyplot()
    ex = abs(res["exact"])
    penalty = res["kind"] in ("penalty", "constitutive", "barrier")
    label = ("series prediction (interface law)" if res["kind"] in ("constitutive", "barrier")
             else "penalty prediction")
    what = "%s%s, nu = %g" % (res["method"] if res["contact"] else "no contact",
                               ", rotated" if res["rotated"] else "", res["nu"])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    patchtest.plot_centre_line(a1, res, penalty, res["szz"], res["z"],
                               "every cell (%d tetrahedra)" % res["nCells"], 0.0,
                               r"$\sigma'_{zz}$ / |E $\Delta$/L|", "z' [m]", label)
    a1.set_title("stress of every cell")
    if "slaveP" in res:
        a2.plot(res["slaveX"], np.array(res["slaveP"]) / ex, "x", ms=5,
                label="contact pressure, %s faces (slave)" % SLAVE)
        a2.plot(res["masterX"], np.array(res["masterP"]) / ex, "+", ms=7,
                label="contact pressure, %s faces (master)" % MASTER)
    patchtest.mark_pressure(a2, res, penalty, label)
    a2.set_xlabel("x' [m] (all y')")
    a2.set_ylabel("/ |E $\\Delta$/L|")
    a2.set_title("at the interface (%s)" % what)
    a2.legend(fontsize=7)
    a2.grid(alpha=0.3)
    lo, hi = a1.get_xlim()
    a1.set_xlim(min(lo, -1.03), max(hi, -0.97))
    lo, hi = a2.get_ylim()
    a2.set_ylim(min(lo, 0.97), max(hi, 1.03))
    a1.text(0.03, 0.03, "max |error| %.2g, spread %.2g\n(fractions of |E $\\Delta$/L|)"
            % (res["maxRel"], res["spread"]), transform=a1.transAxes, fontsize=8)
    patchtest.save(fig, (a1, a2), png)


def main():
    args = report.parse_args(__doc__, "patchTestTets.png")
    res = compare(args.case)
    print("%s: sigma' = R^T sigma R over all %d cells (time %s, %s)"
          % (NAME, res["nCells"], res["time"], ("method " + res["method"]) if res["contact"]
             else "no contact: exact state on both contact patches"))
    patchtest.print_constants(res, "sigma'_zz")
    print("  R from the mesh%s; top displacement (0/D): (%.10g %.10g %.10g)"
          % ("" if res["rotated"] else " (not rotated)", *patchtest.top_displacement(args.case)))
    print("  slave cells' h = V/A: %.4g .. %.4g m (mean %.4g), %d slave faces"
          % (min(res["h"]), max(res["h"]), np.mean(res["h"]), res["nSlave"]))
    patchtest.print_stress(res, "sigma'_zz", res["kind"] == "penalty")
    print("  max |sigma'_ij|/|exact|: " + ", ".join("%s %.3g" % kv for kv in res["others"].items()))
    if res["contact"]:
        TEST.print_force(res)
        pred = abs(res["predicted"])
        print("  contact pressure on %s: %.9g .. %.9g Pa, max |p - %.9g|/%.9g = %.4g"
              % (SLAVE, res["pMin"], res["pMax"], pred, pred, res["pErr"]))
        pm = np.array(res["masterP"])
        print("  contact pressure on %s (master): %.9g .. %.9g Pa, max |p - %.9g|/%.9g = %.4g"
              % (MASTER, pm.min(), pm.max(), pred, pred, np.abs(pm - pred).max() / pred))
    step = res["step"]
    if step:
        print("  solver: time %s, %d correctors, residual %.3g%s"
              % (step["time"], step["correctors"], step["residual"],
                 "" if step["converged"] else ", NOT CONVERGED"))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
