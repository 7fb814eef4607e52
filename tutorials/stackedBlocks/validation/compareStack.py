#!/usr/bin/python3
"""stackedBlocks: the stress must be uniform through two contact pairs.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

Three blocks (lower h = 0.4 m, E = 1 MPa; middle 0.3 m, 3 MPa; upper
0.3 m, 2 MPa; nu = 0; constant/mechanicalProperties) are pressed together
by moving the upper top down by Delta = 0.01 m with the lower bottom held.
No interface mesh matches, and the middle block is the master of one pair
(lowerTop on middleBottom) and the slave of the other (middleTop on
upperBottom). The blocks are springs in series, so the exact state is
uniaxial and uniform:

    sigma_yy = -Delta / sum_i h_i/E_i                     (exact methods)
    sigma_yy = -Delta / (sum_i h_i/E_i + sum_pairs 1/eps)  (penalty family)

with eps = s K/h of each pair's slave (K = E for nu = 0, h = V/A of the
slave's cells, s the method's penaltyScale: its default from
solidContactFoam -listMethods, or the slave's <method>Coeffs in the
written D).

Checks (latest time):
  - every cell's sigma_yy against sigma_yy above: max relative error
    <= 1e-6 (a patch test is passed exactly or not at all; 1e-6 leaves
    room for the outer correctors' residual 1e-9 and 12 written digits);
  - each pair's normal force (contactReport's last row, both slave
    patches) against |sigma_yy| times the patch area (1 m x 0.1 m), to
    the same 1e-6.
A method of another answer (constitutive, barrier) has no closed form here:
its checks fail with that reason.
"""
import os
import sys

import numpy as np

from c4fpost import contactreport, foamio, methods, report

DELTA = 0.01
AREA = 1.0 * 0.1
BLOCKS = (("lower", 0.0, 0.4), ("middle", 0.4, 0.7), ("upper", 0.7, 1.0))
SLAVES = (("lowerTop", "lower"), ("middleTop", "middle"))
TOL = 1e-6


def compare(case):
    time = foamio.latest_time(case)
    (consts, what) = foamio.body_constants(case, [b[0] for b in BLOCKS])
    compliance = sum((hi - lo) / E for (_, lo, hi), (E, _) in zip(BLOCKS, consts))
    method = foamio.read_entry(os.path.join(case, time, "D"), "method")
    answer = methods.get(method).answer
    checks = []
    if answer not in ("exact", "penalty"):
        checks.append(dict(name="stackedBlocks/closed_form", passed=False, value=0.0,
                           reference=0.0, error=float("inf"), tolerance=0.0,
                           units="no closed form for the answer '%s' of %s" % (answer, method)))
        return dict(time=time, method=method, checks=checks)
    C, V = foamio.cell_centres_volumes(case)
    if answer == "penalty":
        scale = float(foamio.read_coeff(os.path.join(case, time, "D"), method + "Coeffs",
                                        "penaltyScale",
                                        methods.get(method).coeffs["penaltyScale"]))
        E = dict((b[0], c[0]) for b, c in zip(BLOCKS, consts))
        for slave, body in SLAVES:
            cells = np.asarray(foamio.patch_face_cells(case, slave))
            _, Sf = foamio.patch_geometry(case, slave)
            h = V[cells] / np.linalg.norm(Sf, axis=1)
            # every slave cell of a pair has the same h here
            compliance += 1.0 / (scale * E[body] / float(h.mean()))
    exact = -DELTA / compliance
    s = foamio.read_internal(os.path.join(case, time, "sigma"))
    err = float(np.abs(s[:, 3] / exact - 1).max())
    checks.append(dict(name="stackedBlocks/sigma_yy_uniform", passed=err <= TOL, value=err,
                       reference=exact, error=err, tolerance=TOL,
                       units="max over the cells of |sigma_yy/sigma - 1|"))
    for slave, _ in SLAVES:
        row = contactreport.last_row(case, slave) or {}
        F = row.get("normalForce", 0.0)
        e = abs(F / (-exact * AREA) - 1)
        checks.append(dict(name="stackedBlocks/force_%s" % slave, passed=e <= TOL, value=F,
                           reference=-exact * AREA, error=e, tolerance=TOL,
                           units="N (contactReport)"))
    return dict(time=time, method=method, answer=answer, sigma=exact, materials=what,
                y=C[:, 1].tolist(), syy=s[:, 3].tolist(), checks=checks)


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(res["y"], res["syy"], "o", ms=3, label="cells (%s)" % res["method"])
    ax.axhline(res["sigma"], color="k", lw=1, label="exact %.6g Pa" % res["sigma"])
    for _, lo, _ in BLOCKS[1:]:
        ax.axvline(lo, color="C3", ls=":", lw=1)
    ax.set_xlabel("y [m] (dotted: the two contact interfaces)")
    ax.set_ylabel("sigma_yy [Pa]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "stackedStress.png")
    res = compare(args.case)
    print("stackedBlocks: method %s (answer %s), time %s" % (res["method"],
                                                            res.get("answer"), res["time"]))
    if "sigma" in res:
        print("  materials: %s" % res["materials"])
        print("  sigma_yy closed form: %.9g Pa" % res["sigma"])
    return report.finish(res, args.case, args.png, args.json, plot,
                         complete="sigma" in res)


if __name__ == "__main__":
    sys.exit(main())
