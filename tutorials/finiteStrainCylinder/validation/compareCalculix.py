#!/usr/bin/python3
"""finiteStrainCylinder: force against approach, against CalculiX.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

A St Venant-Kirchhoff cylinder (R = 0.1 m, plane strain, half-model) is
pressed into a block of the same law by 20 % of R in ten steps. The
reference is CalculiX 2.20 (Debian calculix-ccx) on the same problem:
*ELASTIC under NLGEOM is the same law (S = C : E of the Green-Lagrange
strain), 8-node quadrilaterals (CPE8) of 2 mm at the contact, 1599
elements, surface-to-surface penalty contact (slope 1e12 Pa/m).
validation/calculix.py makes the model, runs ccx and writes
validation/calculix-<law>.csv (approach [m], force [N] for the 0.01 m
thickness); the file here is its output, and `make bench` runs it anew
(--reference then names its curve).

Checks:
  - every load step converged (its outer residual below solidMechanics'
    tolerance);
  - St Venant-Kirchhoff: at every step |F/F_ccx - 1| <= 2 % (issue 22's
    target for the comparison with an FE code over the curve). Measured
    at the tutorial's mesh (2 mm faces): at most 0.24 % (0.48 % at
    -refine 2).
  - neoHookean (Allrun -law neoHookean, `form decoupled`: CalculiX's
    energy): the same 2 % against CalculiX's NEO HOOKE of the same shear
    and bulk moduli (validation/calculix-neoHookean.csv). Measured: at
    most 0.22 %. (The law's default form, lambda/2 (ln J)^2 - mu ln J for
    the volume, is a different material: +0.27 % at 20 %. Until the
    smoothed normals were made continuous, 2026-11-29, the decoupled
    form's tenth step stalled at a residual of 1.5e-6.)
"""
import os
import re

import numpy as np

from c4fpost import foamio, patchtest, report

NAME = "finiteStrainCylinder"
DELTA_PER_STEP = 0.002    # 0/D: 0.02 m over ten unit steps
TOL = 0.02
# A rigid (or 1000 times stiffer) cylinder: CalculiX's converged force
# (622.15 N at 20 %, its 2 mm and 1.5 mm meshes within 0.01 %, a *RIGID
# BODY and a 1000 times stiffer cylinder within 0.04 %) is 1.9 % below
# ours on the tutorial's mesh and 2.3 % on the mesh twice finer; our rigid
# tool and our 1000 times stiffer meshed cylinder agree to 0.1 %, so the
# difference is the finite-strain block's under a near-rigid indenter
# (issue 22), not the rigid tool's; with the elastic cylinder the two codes
# agree to 0.22 %. The check guards against more.
TOL_RIGID = 0.03


def read_report(case):
    """(time, normal force, converged) of contactReport's rows."""
    d = os.path.join(case, "postProcessing", "contactReport")
    rows = {}
    for start in sorted(os.listdir(d), key=float):
        for name in sorted(os.listdir(os.path.join(d, start))):
            if not re.fullmatch(r"(cylinder|block)Contact(_\d+)?\.dat", name):
                continue
            for line in open(os.path.join(d, start, name)):
                if line.startswith("#") or not line.strip():
                    continue
                v = line.split()
                rows[float(v[0])] = (float(v[1]), int(v[8]))
    t = np.array(sorted(rows))
    return t, np.array([rows[k][0] for k in t]), np.array([rows[k][1] for k in t])


def rigid_cylinder(case):
    """Whether the run had a rigid cylinder (Allrun -cylinder rigid): the
    block's top is then the slave that contactReport reports."""
    d = os.path.join(case, "postProcessing", "contactReport")
    return any(re.fullmatch(r"blockContact(_\d+)?\.dat", name)
               for start in (os.listdir(d) if os.path.isdir(d) else [])
               for name in os.listdir(os.path.join(d, start)))


def read_csv(path):
    a = np.loadtxt(path, delimiter=",", comments="#", ndmin=2)
    return a[:, 0], a[:, 1]


def compare(case, reference=None):
    mp = os.path.join(case, "constant", "mechanicalProperties")
    law = foamio.read_entry(mp, "materialLaw")
    stiff = law == "zoned"
    if stiff:
        # Allrun -cylinder stiff: the block's law
        m = re.search(r"\bblock\s*\{\s*materialLaw\s+(\w+)\s*;",
                      foamio.strip_comments(open(mp).read()))
        law = m.group(1) if m else law
    t, F, conv = read_report(case)
    d = t * DELTA_PER_STEP
    rigid = rigid_cylinder(case) or stiff
    ref = reference or os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "calculix-%s%s.csv" % (law, "-rigid" if rigid else ""))
    check, step, _ = patchtest.convergence_check(case, NAME)
    checks = [check]
    allConv = bool(len(t) == 10 and conv.all())
    checks.append(dict(name=NAME + "/all_steps_converged", value=float(len(t) - conv.sum()),
                       reference=0.0, error=float(10 - conv.sum()), tolerance=0.0,
                       passed=allConv, units="steps not converged of 10"))
    res = dict(law=law, d=d.tolist(), F=F.tolist(), checks=checks, rigid=rigid, stiff=stiff)
    if os.path.exists(ref):
        dr, Fr = read_csv(ref)
        Fi = np.interp(d, dr, Fr)
        rel = F / Fi - 1
        res.update(dref=dr.tolist(), Fref=Fr.tolist(), rel=rel.tolist())
        if law in ("stVenantKirchhoff", "neoHookean"):
            err = float(np.abs(rel).max())
            checks.append(dict(name=NAME + "/force_vs_calculix", value=err, reference=0.0,
                               error=err, tolerance=TOL_RIGID if rigid else TOL,
                               units="max |F/F_CalculiX - 1| over the steps"))
    patchtest.set_passed(checks)
    return res


def plot(res, png):
    plt = patchtest.pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(np.array(res["d"]) * 1e3, res["F"], "o-", label="contact4foam (%s%s)"
            % (res["law"], ", cylinder 1000 x stiffer" if res["stiff"] else
               ", rigid cylinder" if res["rigid"] else ""))
    if "Fref" in res:
        ax.plot(np.array(res["dref"]) * 1e3, res["Fref"], "k--", label="CalculiX")
    ax.set_xlabel("approach of the cylinder's top [mm]")
    ax.set_ylabel("force [N] (0.01 m thick)")
    ax.set_title("finiteStrainCylinder: R = 0.1 m pressed by 20 % of R", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    args = report.parse_args(__doc__, "finiteStrainCylinder.png", options=[
        ("--reference", dict(help="CalculiX's curve (default: "
                             "validation/calculix-<law>.csv)"))])
    res = compare(args.case, args.reference)
    print("%s: law %s%s" % (NAME, res["law"], ", cylinder 1000 x stiffer" if res["stiff"]
                            else ", rigid cylinder" if res["rigid"] else ""))
    for k, (d, F) in enumerate(zip(res["d"], res["F"])):
        line = "  approach %.4f m: F = %.6g N" % (d, F)
        if "rel" in res:
            line += "  (CalculiX %+.3f %%)" % (100 * res["rel"][k])
        print(line)
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    raise SystemExit(main())
