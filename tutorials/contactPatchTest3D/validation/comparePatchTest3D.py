#!/usr/bin/python3
"""contactPatchTest3D: the stress must be uniform and uniaxial across a 3D non-matching interface.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
them with --json.

Two boxes 1 x 1 x 0.5 m stacked in z (upper 10 x 8 x 5 cells, its bottom
upperBottom the slave with 10 x 8 faces; lower 7 x 5 x 5 cells, its top
lowerTop the master with 7 x 5 faces; column height L = 1 m) are pressed
together by moving the upper top down by Delta = 0.01 m (normal component
only) with the lower bottom held in z. Symmetry planes at x = 0 and y = 0,
traction-free faces at x = 1 and y = 1: nothing resists the lateral
expansion, so for ANY nu the exact state is uniaxial stress,
    sigma_zz = -E Delta / L = -1e4 Pa (E = 1e6 Pa),
all other components 0, in every cell (E, not the plane-strain
E/(1 - nu^2) of the 2D patch test), and the contact pressure is 1e4 Pa on
every face. Uniform strain is represented exactly by the discretisation,
so the patch test is passed exactly or not at all.

Frame. With Allrun -rotate the mesh is turned (30 degrees about (1 2 3)),
and the stress is compared in the box's own frame, sigma' = R^T sigma R.
R is read from the mesh, not assumed: its columns are the unit outward
normal of symmetryX negated (R e_x), e_z x e_x (R e_y) and the unit
outward normal of upperTop (R e_z), averaged over the patch faces (the
points are written with 12 digits, so R is exact to ~1e-11). Cell and face
centres are turned back the same way (x' = R^T x) for the table and plot.
Not rotated, R = I to round-off.

Checks (all variants):
  - load_direction: the top displacement in 0/D (topDisplacement) against
    R (0 0 -Delta), relative to Delta; tolerance 1e-8 (Allrun writes it
    with 15 digits, the mesh's R is good to ~1e-11). A -rotate run whose
    load did not turn with the mesh fails here first.
  - other_components: max over cells of |sigma'_ij| / |sigma_exact| for
    ij = xx, yy, xy, xz, yz; tolerance 1e-6, as for sigma'_zz below.
  - converged: the last `Time = 1  correctors = N  residual = r` line of
    log.solidContactFoam has no NOT CONVERGED and r below the solver's
    `tolerance` (solidMechanics in system/fvSolution); value r.

The check of each contact method follows from the answer it gives
(c4fpost.patchtest.METHOD_CHECKS: exact, penalty or constitutive); a
method of solidContactFoam -listMethods with no entry there fails
(`method_check`).

The exact methods (lagrangeMultiplier; augmentedLagrange and
crossConstraint, which close the gap through their multiplier updates to
multiplierTolerance 1e-6: the penetration left is 1e-6 of lambda/eps, some
1e-7 of Delta) and -noContact (the two
bodies decoupled, each contact patch given the exact state the contact run
must converge to: the slave its normal displacement R (0 0 -0.005), the
master the pressure E Delta/L), max over ALL cells of
    |sigma'_zz - sigma_exact| / |sigma_exact|  <=  1e-6.
  1e-6 leaves room for the outer correctors, which stop at a residual of
  1e-9 (system/fvSolution), and for the 12 significant digits of the ASCII
  output, as in the 2D patch test.

penalty (eps_N = s K / h, s = penaltyScale, K = 2 mu + lambda, h = V/A of
the slave face cells = 0.1 m, read from 0/D and the mesh). The penalty
spring is in series with the column. The gap closes to a penetration
g = p/eps_N with p = |sigma|, and the column takes the rest of Delta in
uniaxial stress (the lateral faces are free, so the column's modulus is E,
while the penalty, like the solver, is scaled with the constrained modulus
K = 2 mu + lambda = E (1 - nu)/((1 + nu)(1 - 2 nu))):
    |sigma| L / E + |sigma| / eps_N = Delta
    sigma_pen = -E Delta / (L + E/eps_N) = -E Delta / (L + E h/(s K))
and every cell's relative error is the offset
    offset = 1 - L/(L + E/eps_N) = r/(1 + r),    r = (E/K) h/(s L),
which for nu = 0 (K = E) is the 2D h/(s L)/(1 + h/(s L)): 9.90e-3 for
s = 10; nu = 0.3 gives E/K = 1.3*0.4/0.7 = 0.743 and 7.37e-3. Both boxes
carry the same stress, so they expand sideways alike and the interface
does not slide (the contact is frictionless anyway). Checks:
|max relative error - offset| <= 1e-3 offset (the penalty state is exact
to the same 1e-6 as above, 1e-4 of the ~1e-2 offset; the 2D patch test
meets its prediction to 1e-3 of itself) and
(max - min sigma'_zz)/|sigma_exact| <= 1e-6.

constitutiveLaw (p = cN (-g)^n, cN and n of constitutiveLawCoeffs in 0/D):
the interface is in series with the column, the state uniform with
    |sigma| L/E + (|sigma|/cN)^(1/n) = Delta
(the modulus E: uniaxial stress, as for the penalty), every slave face
penetrating by (|sigma|/cN)^(1/n); the stress against that everywhere, its
spread and every face's penetration against the law, all to 1e-6 (the law
is exact and the state uniform, as the 2D patch test checks it).

barrier (the clamped log barrier, dhat of barrierCoeffs, 1e-3 m = 1e-2 h,
or 1e-3 of the largest slave h; kappa the written field barrierStiffness;
Allrun opens an initial gap of 5e-4 m by lifting the upper box along its
normal, the applied displacement unchanged): the boxes stay apart by a uniform gap
d, so the column is shortened by Delta + d in uniaxial stress (modulus E):
|sigma| L/E = Delta + d with p(d) = |sigma|
(c4fpost.patchtest.barrier_solution). Checks: every cell's sigma'_zz
equals -|sigma| and is uniform, every slave face's gap equals d (to 1e-6
of max(d, 1e-3 Delta)), all to 1e-6 as the exact methods, and every gap
is open.

Contact variants, also: the total normal force on the slave patch,
sum_f p_f |Sf_f|, against |sigma| (exact or penalty) times the patch area
(1 m2), with the same tolerance as the stress; and, when the contactReport
function object wrote postProcessing/contactReport/*/upperBottom.dat, its
last normalForce likewise.
"""

import sys

from c4fpost import elastic, foamio, patchtest, report

import numpy as np

NAME = "contactPatchTest3D"
DELTA = 0.01    # downward displacement of upperTop [m], 0/D
L = 1.0         # height of the two-box column [m], system/blockMeshDict
SLAVE = "upperBottom"
MASTER = "lowerTop"
TOP = "upperTop"           # outward normal R e_z
SYMMETRY_X = "symmetryX"   # outward normal -R e_x
EXACT_TOL = 1e-6
OFFSET_TOL = 1e-3   # fraction of the penalty offset
LOAD_TOL = 1e-8
TEST = patchtest.PatchTest(NAME, SLAVE, MASTER, DELTA, L, EXACT_TOL, OFFSET_TOL)
OTHERS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}


def kind_of(contact, method):
    """The kind of answer to check (patchtest.METHOD_CHECKS): exact without
    contact; None for a method with no check."""
    if not contact:
        return "exact"
    check = patchtest.method_check(method)
    return check["kind"] if check else None


def no_check(method):
    """A method of the run-time selection table with no closed-form check
    here: a FAIL that says so."""
    return dict(name=NAME + "/closed_form_check", value=float("inf"), reference=0.0,
                error=float("inf"), tolerance=0.0, passed=False,
                units="method %s has no entry in c4fpost.patchtest.METHOD_CHECKS" % method)


def no_result(case, contact, method, why):
    """No time written (a step that does not converge stops the solver
    before writing): every stress check fails."""
    inf = float("inf")
    conv, step, ncorr = patchtest.convergence_check(case, NAME)
    kind = kind_of(contact, method)
    if kind == "penalty":
        names = ["szz_penalty_offset", "szz_uniformity"]
    elif kind == "constitutive":
        names = ["szz_constitutive_law", "szz_uniformity", "penetration_law"]
    elif kind == "barrier":
        names = ["szz_barrier_law", "szz_uniformity", "gap_barrier_law", "gap_open"]
    else:
        names = ["szz_max_rel_error"]
    checks = [dict(name="%s/%s" % (NAME, n), value=inf, reference=0.0, error=inf,
                   tolerance=EXACT_TOL, units=why, passed=False)
              for n in names + ["other_components"]]
    checks.append(conv)
    if kind is None:
        checks.append(no_check(method))
    return dict(time=None, method=method, contact=contact, kind=kind, why=why, step=step,
                nCorrectors=ncorr, checks=checks)


def compare(case):
    contact, method = patchtest.contact_variant(case, SLAVE)
    try:
        time = foamio.latest_time(case)
    except FileNotFoundError:
        return no_result(case, contact, method,
                         "no time written: see log.solidContactFoam")
    E, nu, planeStress = foamio.elastic_constants(case)
    if planeStress:
        raise SystemExit("%s: planeStress yes makes no sense in 3D" % NAME)
    K = elastic.impK(E, nu)
    exact = -E * DELTA / L

    R = patchtest.rotation_from_mesh(case, TOP, SYMMETRY_X)
    C, V = foamio.cell_centres_volumes(case)
    Cr = C @ R                          # x' = R^T x, row by row
    Cf, area, slaveCells, h = TEST.slave_geometry(case, V)
    masterCells = foamio.patch_face_cells(case, MASTER)

    S = patchtest.stress_tensor(case, time, V.size)
    Sr = np.einsum("ki,nkl,lj->nij", R, S, R)     # R^T sigma R
    szz = Sr[:, 2, 2]
    maxRel, spread = patchtest.uniformity(szz, exact)
    others = {k: float(np.abs(Sr[:, i, j]).max() / abs(exact)) for k, (i, j) in OTHERS.items()}
    worst = max(others, key=others.get)

    d = patchtest.top_displacement(case)
    d0 = R @ np.array([0.0, 0.0, -DELTA])
    loadErr = float(np.linalg.norm(d - d0) / DELTA)

    kind = kind_of(contact, method)
    res = dict(time=time, method=method, contact=contact, kind=kind, E=E, nu=nu, K=K,
               exact=exact,
               maxRel=maxRel, spread=spread, others=others, R=R.tolist(),
               rotated=bool(np.abs(R - np.eye(3)).max() > 1e-6), h=h.tolist(),
               topDisplacement=d.tolist())
    checks = [dict(name=NAME + "/load_direction", value=float(np.linalg.norm(d)),
                   reference=DELTA, error=loadErr, tolerance=LOAD_TOL,
                   units="m (error: |D_top - R (0 0 -Delta)|/Delta)")]
    if kind is None:
        checks.append(no_check(method))
        stress, predicted, forceTol = TEST.stress_checks(case, res, "szz", False, E, K, h)
    elif kind == "constitutive":
        stress, predicted, forceTol = TEST.constitutive_checks(case, time, res, "szz", szz, E,
                                                               Cf.shape[0], method)
    elif kind == "barrier":
        stress, predicted, forceTol = TEST.barrier_checks(case, time, res, "szz", szz, E,
                                                          Cf.shape[0], h, method)
    else:
        stress, predicted, forceTol = TEST.stress_checks(
            case, res, "szz", kind == "penalty", E, K, h, method,
            patchtest.method_check(method).get("scale") if contact else None)
    checks += stress
    checks.append(dict(name=NAME + "/other_components", value=others[worst], reference=0.0,
                       error=others[worst], tolerance=EXACT_TOL,
                       units="max |sigma'_%s|/|sigma_exact|" % worst))

    # Contact force on the slave patch
    res["report"] = None
    if contact:
        checks += TEST.force_checks(case, time, res, area, predicted, forceTol)
        res["slaveX"] = (Cf @ R)[:, 0].tolist()
        TEST.master_pressure(case, time, res, R)

    conv, step, ncorr = patchtest.convergence_check(case, NAME)
    checks.append(conv)
    res.update(step=step, nCorrectors=ncorr)
    patchtest.set_passed(checks)

    # Data for the table and the plot: the column of cells nearest
    # x' = y' = 0.5 in each box, and the cells on either side of the
    # interface
    cols = []
    for body in (Cr[:, 2] < 0.0, Cr[:, 2] > 0.0):
        idx = np.nonzero(body)[0]
        dxy = np.hypot(Cr[idx, 0] - 0.5, Cr[idx, 1] - 0.5)
        first = idx[np.argmin(dxy)]
        col = idx[np.hypot(Cr[idx, 0] - Cr[first, 0], Cr[idx, 1] - Cr[first, 1]) < 1e-9]
        cols.extend(col[np.argsort(Cr[col, 2])].tolist())
    cols = np.array(cols)
    res.update(colX=Cr[cols, 0].tolist(), colY=Cr[cols, 1].tolist(), colZ=Cr[cols, 2].tolist(),
               colSzz=szz[cols].tolist(),
               slaveCellX=Cr[slaveCells, 0].tolist(), slaveCellSzz=szz[slaveCells].tolist(),
               masterCellX=Cr[masterCells, 0].tolist(), masterCellSzz=szz[masterCells].tolist())
    res["checks"] = checks
    return res


def plot(res, png):
    plt = patchtest.pyplot()
    ex = abs(res["exact"])
    # the predicted stress where it is not the exact one
    penalty = res["kind"] in ("penalty", "constitutive", "barrier")
    label = ("series prediction (interface law)" if res["kind"] in ("constitutive", "barrier")
             else "penalty prediction")
    what = "%s%s, nu = %g" % (res["method"] if res["contact"] else "no contact",
                               ", rotated" if res["rotated"] else "", res["nu"])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    patchtest.plot_centre_line(a1, res, penalty, res["colSzz"], res["colZ"],
                               "cells nearest x' = y' = 0.5", 0.0,
                               r"$\sigma'_{zz}$ / |E $\Delta$/L|", "z' [m]", label)
    a2.plot(res["slaveCellX"], np.array(res["slaveCellSzz"]) / -ex, "o", ms=4,
            label=r"$-\sigma'_{zz}$, upper cells on %s (slave, 10 x 8)" % SLAVE)
    a2.plot(res["masterCellX"], np.array(res["masterCellSzz"]) / -ex, "s", ms=7, mfc="none",
            label=r"$-\sigma'_{zz}$, lower cells on %s (master, 7 x 5)" % MASTER)
    if "slaveP" in res:
        a2.plot(res["slaveX"], np.array(res["slaveP"]) / ex, "x", ms=6,
                label="contact pressure, %s faces" % SLAVE)
        a2.plot(res["masterX"], np.array(res["masterP"]) / ex, "+", ms=9,
                label="contact pressure, %s faces" % MASTER)
    patchtest.mark_pressure(a2, res, penalty, label)
    a2.set_xlabel("x' [m] (all y')")
    a2.set_ylabel("/ |E $\\Delta$/L|")
    a2.set_title("at the interface (%s)" % what)
    a2.legend(fontsize=7)
    a2.grid(alpha=0.3)
    # At least +-3 % around the exact value, so that a uniform result shows
    # as a straight line and the penalty offset (~1 %) stays in view
    lo, hi = a1.get_xlim()
    a1.set_xlim(min(lo, -1.03), max(hi, -0.97))
    lo, hi = a2.get_ylim()
    a2.set_ylim(min(lo, 0.97), max(hi, 1.03))
    a1.text(0.03, 0.03, "max |error| %.2g, spread %.2g\n(fractions of |E $\\Delta$/L|)"
            % (res["maxRel"], res["spread"]), transform=a1.transAxes, fontsize=8)
    patchtest.save(fig, (a1, a2), png)


def main():
    args = report.parse_args(__doc__, "patchTest3D.png")
    res = compare(args.case)
    step = res["step"]
    if res["time"] is None:
        print("%s: %s (%s)" % (NAME, res["why"], res["method"] if res["contact"] else "no contact"))
        if step:
            print("  last step: time %s, %d correctors, residual %.3g%s"
                  % (step["time"], step["correctors"], step["residual"],
                     "" if step["converged"] else ", NOT CONVERGED"))
        return report.finish(res, args.case, args.png, args.json, plot, complete=False)
    print("%s: sigma' = R^T sigma R over all cells (time %s, %s)"
          % (NAME, res["time"], ("method " + res["method"]) if res["contact"]
             else "no contact: exact state on both contact patches"))
    patchtest.print_constants(res, "sigma'_zz")
    print("  R (from the mesh%s):" % ("" if res["rotated"] else ", not rotated"))
    for row in res["R"]:
        # no "-0.0000000000" for round-off
        print("    %14.10f %14.10f %14.10f" % tuple(v if abs(v) > 5e-11 else 0.0 for v in row))
    print("  top displacement (0/D): (%.10g %.10g %.10g)" % tuple(res["topDisplacement"]))
    patchtest.print_stress(res, "sigma'_zz", res["kind"] == "penalty")
    if res["kind"] == "constitutive":
        print("  constitutive law cN = %g, n = %g: sigma = %.9g Pa, penetration %.9g m"
              " (expected (sigma/cN)^(1/n) = %.9g m)"
              % (res["cN"], res["n"], res["predicted"], res["penetration"],
                 res["penetrationRef"]))
    if res["kind"] == "barrier":
        print("  barrier dhat = %g m, kappa = %g Pa/m: sigma = %.9g Pa, gap %.9g m"
              " (expected d = %.9g m)"
              % (res["dhat"], res["kappa"], res["predicted"], res["gap"], res["gapRef"]))
    print("  max |sigma'_ij|/|exact|: " + ", ".join("%s %.3g" % kv for kv in res["others"].items()))
    if res["contact"]:
        TEST.print_force(res)
    if step:
        print("  solver: time %s, %d correctors (nCorrectors %d), residual %.3g%s"
              % (step["time"], step["correctors"], res["nCorrectors"], step["residual"],
                 "" if step["converged"] else ", NOT CONVERGED"))
    print("%8s %8s %8s %16s" % ("x'", "y'", "z'", "sigma'_zz [Pa]"))
    for x, y, z, s in zip(res["colX"], res["colY"], res["colZ"], res["colSzz"]):
        print("%8.4f %8.4f %8.4f %16.9g" % (x, y, z, s))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
