#!/usr/bin/python3
"""finiteStrainPatchTest: the uniaxial finite-strain state across a non-matching interface.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

Two neo-Hookean blocks (lower 10 x 5 cells, upper 7 x 4, 1 m wide, column
height L = 1 m, plane strain) are pressed to a = 1 - Delta/L = 0.8 of their
height, both ends sliding freely, the right side free, the left a symmetry
plane: the exact state is uniform and uniaxial in every cell, F =
diag(s, a, 1). The lateral stretch s makes the lateral Cauchy stress zero,

    tau_xx = mu (s^2 - 1) + lambda ln(J) = 0,   J = a s,

(solved by bisection; tau = mu (b - I) + lambda ln(J) I, the law of
src/kernels/elasticity/hyperelasticLaws.H), and then

    sigma_yy = (mu (a^2 - 1) + lambda ln J)/J,   sigma_zz = lambda ln(J)/J.

The contact pressure the solver writes is per current area (the
total-Lagrangian traction P.N over Nanson's da/dA = s): -sigma_yy on every
face; contactReport's normal force is sigma_yy times the reference
area.

Checks (every method of the tutorial; exact means answer=exact in
solidContactFoam -listMethods):
  - the step converged (outer residual below solidMechanics' tolerance);
  - exact methods: max over ALL cells |sigma_yy/sigma_exact - 1| <= 1e-6,
    the same for sigma_zz, the right side's D_x = s - 1 to 1e-6 and every
    slave face's pressure to 1e-6 of -sigma_exact. As in the small-strain
    patch test, 1e-6 leaves room for the outer residual of 1e-9 and the 12
    digits of the output; measured 6.6e-8 (lagrangeMultiplier);
  - the penalty family (perturbedLagrange, constitutiveLaw): a spring in
    series, so the state is uniform with an offset: (max - min)
    sigma_yy/|sigma_exact| <= 1e-6 and the offset printed;
  - every method: |sigma_xx| and |sigma_xy| <= 1e-6 |sigma_exact| in every
    cell (uniaxial).
"""
import os

from c4fpost import foamio, neohookean, patchtest, report

import numpy as np

NAME = "finiteStrainPatchTest"
L = 1.0                   # column height [m], system/blockMeshDict
DELTA = 0.2               # the upper top's displacement [m], 0/D
SLAVE = "lowerTop"
RIGHT = "right"
EXACT_TOL = 1e-6


def closed_form(E, nu, a):
    """(s, sigma_yy, sigma_zz) of the uniaxial plane-strain neo-Hookean."""
    s, _, syy, szz = neohookean.uniaxial(E, nu, a, 1)
    return s, syy, szz


def check(name, value, reference, error, tolerance, units=""):
    return dict(name="%s/%s" % (NAME, name), value=float(value), reference=float(reference),
                error=float(error), tolerance=float(tolerance), units=units)


def compare(case):
    time = foamio.latest_time(case)
    E, nu, _ = foamio.elastic_constants(case)
    method = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    kind = patchtest.method_check(method)["kind"]
    s, syyExact, szzExact = closed_form(E, nu, 1 - DELTA / L)

    ncells = len(foamio.read_internal(os.path.join(case, time, "sigmaEq")))
    S = patchtest.stress_tensor(case, time, ncells)
    syy, szz = S[:, 1, 1], S[:, 2, 2]
    conv, step, _ = patchtest.convergence_check(case, NAME)
    checks = [conv]
    scale = abs(syyExact)
    checks.append(check("uniaxial", max(np.abs(S[:, 0, 0]).max(), np.abs(S[:, 0, 1]).max()) / scale,
                        0.0, max(np.abs(S[:, 0, 0]).max(), np.abs(S[:, 0, 1]).max()) / scale,
                        EXACT_TOL, "max |sigma_xx|, |sigma_xy| over |sigma_yy exact|"))
    maxRel, spread = patchtest.uniformity(syy, syyExact)
    Cf, _ = foamio.patch_geometry(case, SLAVE)
    p = foamio.read_patch(os.path.join(case, time, "contactPressure"), SLAVE, len(Cf))
    pExact = -syyExact
    if kind == "exact":
        checks.append(check("sigma_yy", maxRel, 0.0, maxRel, EXACT_TOL,
                            "max |sigma_yy/exact - 1| over the cells"))
        rz = float(np.abs(szz / szzExact - 1).max())
        checks.append(check("sigma_zz", rz, 0.0, rz, EXACT_TOL, "max |sigma_zz/exact - 1|"))
        Cr, _ = foamio.patch_geometry(case, RIGHT)
        Dr = foamio.read_patch(os.path.join(case, time, "D"), RIGHT, len(Cr))[:, 0]
        rs = float(np.abs(Dr - (s - 1) * Cr[:, 0]).max() / abs(s - 1))
        checks.append(check("lateral_stretch", rs, 0.0, rs, EXACT_TOL,
                            "max |D_x - (s - 1) x|/(s - 1) on the right side"))
        rp = float(np.abs(p / pExact - 1).max())
        checks.append(check("contact_pressure", rp, 0.0, rp, EXACT_TOL,
                            "max |p/(-sigma_yy) - 1| over the slave faces"))
    else:
        checks.append(check("sigma_yy_uniform", spread, 0.0, spread, EXACT_TOL,
                            "(max - min) sigma_yy / |exact| (offset %.4g)" % maxRel))
    patchtest.set_passed(checks)
    return dict(time=time, method=method, kind=kind, E=E, nu=nu, s=s, syyExact=syyExact,
                szzExact=szzExact, syy=syy.tolist(), p=p.tolist(), pExact=pExact,
                maxRel=maxRel, spread=spread, step=step, checks=checks)


def plot(res, png):
    plt = patchtest.pyplot()
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(np.array(res["syy"]) / res["syyExact"], "o", ms=3, label="cells")
    ax.axhline(1.0, color="k", lw=0.8, label="closed form")
    ax.set_xlabel("cell")
    ax.set_ylabel(r"$\sigma_{yy}/\sigma_{yy,exact}$")
    ax.set_title("finiteStrainPatchTest (%s): a = 0.8, s = %.5f" % (res["method"], res["s"]),
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    args = report.parse_args(__doc__, "finiteStrainPatchTest.png")
    res = compare(args.case)
    print("%s: method %s (%s), E = %g Pa, nu = %g, a = %g" % (
        NAME, res["method"], res["kind"], res["E"], res["nu"], 1 - DELTA / L))
    print("  closed form: lateral stretch s = %.8f, sigma_yy = %.8g Pa, sigma_zz = %.8g Pa,"
          " contact pressure %.8g Pa" % (
              res["s"], res["syyExact"], res["szzExact"], res["pExact"]))
    print("  measured: sigma_yy max |rel err| %.3g, spread %.3g; contact pressure %.8g .. %.8g Pa"
          % (res["maxRel"], res["spread"], min(res["p"]), max(res["p"])))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    raise SystemExit(main())
