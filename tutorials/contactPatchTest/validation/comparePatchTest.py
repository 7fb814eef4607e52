#!/usr/bin/python3
"""contactPatchTest: the stress must be uniform across a non-matching interface.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
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

perturbedLagrange (the regularised multiplier lambda = eps <-g_N>, eps =
penaltyScale K/h with penaltyScale from perturbedLagrangeCoeffs, default
10): its answer is the penalty's with the same eps, and it is checked as
an exact one: max over ALL cells |sigma_yy - sigma_pen|/|sigma_pen| <=
1e-6, the uniformity and the force likewise (what is left is the
multiplier tolerance 1e-6, whose remaining error the Uzawa contraction,
about 0.09 per update here, shrinks to ~1e-7, and the 1e-9 residual).

Materials (constant/mechanicalProperties, one law or a zoned law with the
zones lower and upper): the blocks, each L/2 high, are springs in series,
so E above is the column's, L/(L/2/E_lower + L/2/E_upper); K of eps_N is
the slave's (lowerTop, or upperBottom after Allrun -slave upper: the
patch with `master no` in the written D). With -materials stiffUpper
(1000:1) sigma_exact = -1.998e4 Pa.

barrier (the clamped log barrier, dhat of barrierCoeffs or 1e-3 of the
largest slave h, kappa the written field barrierStiffness, Allrun opens
an initial gap by lifting the upper block, the applied displacement
unchanged): the bodies stay apart by a uniform gap d, so the column is
shortened by Delta + d: |sigma| L/E = Delta + d with p(d) = |sigma|
(c4fpost.patchtest.barrier_solution). Checks: every cell's sigma_yy
equals -|sigma| and every slave face's gap equals d, both to 1e-6 (as
the exact methods; the gap, 1.2e-3 of Delta, measured 2.8e-8 off, the
stress 5e-11), and every gap is open.

Both: the total normal force on the slave patch, sum_f p_f |Sf_f|, against
|sigma| (exact or penalty) times the patch area (1 m x dz), with the same
tolerance as the stress; and, when the contactReport function object wrote
postProcessing/contactReport/*/lowerTop.dat, its last normalForce likewise.
"""
import os
import sys

from c4fpost import elastic, foamio, methods, patchtest, report

import numpy as np

DELTA = 0.01    # downward displacement of upperTop [m], 0/D
L = 1.0         # height of the two-block column [m], system/blockMeshDict
PATCHES = {"lowerTop": "lower", "upperBottom": "upper"}   # patch: its block's cellZone
EXACT_TOL = 1e-6
OFFSET_TOL = 1e-3   # fraction of the penalty offset


def patch_test(slave):
    master = [p for p in PATCHES if p != slave][0]
    return patchtest.PatchTest("contactPatchTest", slave, master, DELTA, L, EXACT_TOL,
                               OFFSET_TOL)


def compare(case):
    time = foamio.latest_time(case)
    slave = patchtest.slave_patch(case, time, PATCHES)
    test = patch_test(slave)
    mats = foamio.materials(case)
    law = {z: mats[None] if None in mats else mats[z] for z in PATCHES.values()}

    def uniaxial(E, nu, planeStress):
        return E if planeStress else E / (1.0 - nu * nu)     # uniaxial stress, free sides

    # The blocks in series, L/2 each
    Eu = L / sum(0.5 * L / uniaxial(*law[z]) for z in PATCHES.values())
    E, nu, planeStress = law[PATCHES[slave]]
    K = elastic.impK(E, nu, planeStress)
    exact = -Eu * DELTA / L

    method = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    C, V = foamio.cell_centres_volumes(case)
    Cf, area, _, h = test.slave_geometry(case, V)
    syy = patchtest.stress_tensor(case, time, V.size)[:, 1, 1]
    maxRel, spread = patchtest.uniformity(syy, exact)

    res = dict(time=time, method=method, E=Eu, nu=nu, K=K, exact=exact, maxRel=maxRel,
               spread=spread, h=h.tolist(), slave=slave)
    # What to check is the method's declared answer (c4fpost.methods)
    kind = patchtest.method_check(method)["kind"]
    res["kind"] = kind
    if kind == "constitutive":
        checks, predicted, forceTol = test.constitutive_checks(case, time, res, "syy", syy,
                                                               Eu, Cf.shape[0], method)
    elif kind == "barrier":
        checks, predicted, forceTol = test.barrier_checks(case, time, res, "syy", syy, Eu,
                                                          Cf.shape[0], h, method)
    elif kind == "penalty" and methods.get(method).multipliers == "regularised":
        # A regularised multiplier converges to the penalty's state itself,
        # through its updates: checked as exact as an exact method's
        checks, predicted, forceTol = test.stress_checks(case, res, "syy", True, Eu, K, h,
                                                         method, stress=syy)
    else:
        checks, predicted, forceTol = test.stress_checks(case, res, "syy", kind == "penalty",
                                                         Eu, K, h, method)
    # Contact force on the slave patch
    checks += test.force_checks(case, time, res, area, predicted, forceTol)
    patchtest.set_passed(checks)

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
               slaveX=Cf[:, 0].tolist())
    try:
        test.master_pressure(case, time, res)
    except (KeyError, ValueError, AttributeError):
        pass
    res["checks"] = checks
    return res


def plot(res, png):
    plt = patchtest.pyplot()
    ex = abs(res["exact"])
    penalty = res["kind"] == "penalty"
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    patchtest.plot_centre_line(a1, res, penalty, res["colSyy"], res["colY"],
                               "cells nearest x = 0.5", 0.5,
                               r"$\sigma_{yy}$ / |E $\Delta$/L|", "y [m]")
    master = patch_test(res["slave"]).master
    a2.plot(res["slaveX"], np.array(res["slaveP"]) / ex, "o",
            label="%s (slave, %d faces)" % (res["slave"], len(res["slaveX"])))
    if "masterX" in res:
        a2.plot(res["masterX"], np.array(res["masterP"]) / ex, "s", mfc="none",
                label="%s (master, %d faces)" % (master, len(res["masterX"])))
    patchtest.mark_pressure(a2, res, penalty)
    a2.set_xlabel("x [m]")
    a2.set_ylabel("contact pressure / |E $\\Delta$/L|")
    a2.set_title("interface pressure (%s)" % res["method"])
    a2.legend(fontsize=8)
    a2.grid(alpha=0.3)
    patchtest.save(fig, (a1, a2), png)


def main():
    args = report.parse_args(__doc__, "patchTest.png")
    res = compare(args.case)
    print("contactPatchTest: sigma_yy over all cells (time %s, method %s)"
          % (res["time"], res["method"]))
    patchtest.print_constants(res, "sigma_yy")
    patchtest.print_stress(res, "sigma_yy", res["kind"] == "penalty")
    if res["kind"] == "constitutive":
        print("  constitutive law cN = %g, n = %g: sigma = %.9g Pa, penetration %.9g m"
              " (expected (sigma/cN)^(1/n) = %.9g m)"
              % (res["cN"], res["n"], res["predicted"], res["penetration"],
                 res["penetrationRef"]))
    if res["kind"] == "barrier":
        print("  barrier dhat = %g m, kappa = %g Pa/m: sigma = %.9g Pa, gap %.9g m"
              " (expected d with p(d) = |sigma| and |sigma| L/E = Delta + d: %.9g m)"
              % (res["dhat"], res["kappa"], res["predicted"], res["gap"], res["gapRef"]))
    patch_test(res["slave"]).print_force(res)
    print("%8s %8s %16s" % ("x", "y", "sigma_yy [Pa]"))
    for x, y, s in zip(res["colX"], res["colY"], res["colSyy"]):
        print("%8.4f %8.4f %16.9g" % (x, y, s))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
