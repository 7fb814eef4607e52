#!/usr/bin/env python3
"""selfContactStrip: the force across the slot against CalculiX, and no
false contact.

The reference is CalculiX 2.20 (Debian calculix-ccx) on the same strip,
with the slot's roof and floor as two surfaces (CalculiX has no
self-contact): validation/calculix.py makes the model, runs ccx and writes
validation/calculix.csv (time, pressure, force across the slot, start of
the contact zone on the roof), with CPE8 elements of 0.5 mm; under
Allrun -finiteStrain (nonlinearGeometry yes, St Venant-Kirchhoff) the
NLGEOM run's validation/calculix-nlgeom.csv. Between
CalculiX's 1 mm and 0.5 mm meshes the force changed by 0.5 % at most; the
tutorial's mesh (1 mm along the upper arm) is within 5 % of it where the
arm's end has just landed and 1.4 % at the last step, its mesh twice finer
within 2 % and 0.5 %, converging on it at first order (both extrapolated
to h = 0 agree within 0.5 %).

Checks, every step:
  - the force F across the slot (contactReport's normalForce: each contact
    counted once) against CalculiX's, the error a fraction of the pressure
    load on the upper arm, p 90 mm dz (the force is a part of it, what
    the arm's end does not carry back to the spine): within F_TOL;
  - open steps (CalculiX's force 0): no active face;
  - every active face a face of the slot beside the arm's end (x > 80 mm,
    y 10 or 12 mm): the faces around the patch's corners and bends, and
    the two sides of each arm, are never pairs;
  - the last step: the contact zone's start on the roof within two of its
    cells (ZONE_TOL) of CalculiX's.

Usage: compareSelfContact.py [case] [--png FILE] [--json FILE]
"""
import math
import os
import sys

from c4fpost import contactreport, foamio, report

import numpy as np

PATCH = "strip"
ARM = 0.09                # the loaded length of the upper arm [m]
F_TOL = 0.02              # of the pressure load on the upper arm
ZONE_TOL = 2              # cells of the roof
ROOF_Y = 0.012            # the slot's roof and floor [m]
FLOOR_Y = 0.010
NEAR_END = 0.08           # active faces must lie right of this [m]


def finite_strain(case):
    """Whether the case ran under nonlinearGeometry (Allrun -finiteStrain)."""
    v = foamio.read_coeff(os.path.join(case, "system", "fvSolution"), "solidMechanics",
                          "nonlinearGeometry", "no")
    return str(v) in ("yes", "on", "true", "1", "1.0")


def reference(case):
    name = "calculix-nlgeom.csv" if finite_strain(case) else "calculix.csv"
    path = os.path.join(case, "validation", name)
    rows = [[float(v) for v in line.split(",")]
            for line in open(path) if line.strip() and not line.startswith("#")]
    return {r[0]: dict(p=r[1], F=r[2], start=r[3]) for r in rows}


def faces(case, t, field, n):
    path = os.path.join(case, t, field)
    return foamio.read_patch(path, PATCH, n) if os.path.exists(path) else np.zeros(n)


def compare(case):
    ref = reference(case)
    Cf, _ = foamio.patch_geometry(case, PATCH)
    n = Cf.shape[0]
    dz = foamio.thickness(case)
    roof = np.isclose(Cf[:, 1], ROOF_Y, atol=1e-6)
    hroof = 0.09/float(np.count_nonzero(roof & (Cf[:, 0] > 0.01)))
    steps, checks = [], []
    for t in [t for t in foamio.times(case) if float(t) > 0]:
        row = contactreport.row_at(case, PATCH, float(t))
        r = ref.get(float(t))
        if row is None or r is None:
            checks.append(dict(name="selfContactStrip/step_%s" % t, value=0.0,
                               reference=1.0, error=float("inf"), tolerance=0.0,
                               units="no contactReport row or CalculiX row"))
            continue
        F = row["normalForce"]
        load = r["p"]*ARM*dz
        active = faces(case, t, "contactActive", n) > 0.5
        p = faces(case, t, "contactPressure", n)
        stray = active & ~((Cf[:, 0] > NEAR_END)
                           & (np.isclose(Cf[:, 1], ROOF_Y, atol=1e-6)
                              | np.isclose(Cf[:, 1], FLOOR_Y, atol=1e-6)))
        touched = roof & (p > 1e-3*max(p.max(), 0.0)) if p.max() > 0 else roof & False
        start = (float(Cf[touched, 0].min() - 0.5*hroof)
                 if touched.any() and int(row["activeFaces"]) > 0 else float("nan"))
        s = dict(time=t, p=r["p"], F=F, Fref=r["F"], load=load,
                 err=abs(F - r["F"])/load, active=int(row["activeFaces"]),
                 stray=int(np.count_nonzero(stray)), start=start, startRef=r["start"],
                 correctors=int(row["outerCorrectors"]))
        steps.append(s)
        checks.append(dict(name="selfContactStrip/force_step%s" % t, value=F,
                           reference=r["F"], error=s["err"], tolerance=F_TOL,
                           units="N (error: fraction of the load on the upper arm)"))
        if r["F"] < 1e-4*load:
            checks.append(dict(name="selfContactStrip/open_step%s" % t,
                               value=float(s["active"]), reference=0.0,
                               error=float(s["active"]), tolerance=0.0,
                               units="active faces while the slot is open"))
        checks.append(dict(name="selfContactStrip/stray_step%s" % t,
                           value=float(s["stray"]), reference=0.0,
                           error=float(s["stray"]), tolerance=0.0,
                           units="active faces away from the arm's end"))
    if steps and steps[-1]["Fref"] >= 1e-4*steps[-1]["load"]:
        last = steps[-1]
        err = abs(last["start"] - last["startRef"])/hroof
        checks.append(dict(name="selfContactStrip/zone_start", value=last["start"],
                           reference=last["startRef"],
                           error=err if math.isfinite(err) else float("inf"),
                           tolerance=ZONE_TOL,
                           units="m (error: roof cells, %.3g m)" % hroof))
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])
    try:
        method = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    except (KeyError, OSError):
        method = None
    return dict(steps=steps, checks=checks, method=method,
                finite=finite_strain(case))


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    st = res["steps"]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([s["p"]/1e6 for s in st], [s["Fref"] for s in st], "k-s",
            label="CalculiX (CPE8, 0.5 mm%s), roof and floor as two surfaces"
            % (", NLGEOM" if res["finite"] else ""))
    ax.plot([s["p"]/1e6 for s in st], [s["F"] for s in st], "o",
            label="solidContactFoam, self-contact, %s" % (res["method"] or "contact"))
    ax.set_xlabel("pressure on the upper arm [MPa]")
    ax.set_ylabel("force across the slot [N] (1 mm thick)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle("selfContactStrip: a C-shaped strip closing on itself")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "selfContactStrip.png")
    res = compare(args.case)
    print("selfContactStrip: force across the slot against CalculiX (method %s%s)"
          % (res["method"], ", finite strain" if res["finite"] else ""))
    print("  %-5s %-9s %-11s %-11s %-8s %-9s %-6s %-6s %-10s %s"
          % ("time", "p[MPa]", "F[N]", "F_ccx[N]", "err[%F]", "err[%load]", "active",
             "stray", "start[mm]", "correctors"))
    for s in res["steps"]:
        rel = 100*(s["F"]/s["Fref"] - 1) if s["Fref"] >= 1e-4*s["load"] else float("nan")
        print("  %-5s %-9.4g %-11.5g %-11.5g %-+8.2f %-9.3f %-6d %-6d %-10.4g %d"
              % (s["time"], s["p"]/1e6, s["F"], s["Fref"], rel, 100*s["err"],
                 s["active"], s["stray"], 1e3*s["start"], s["correctors"]))
    return report.finish(res, args.case, args.png, args.json, plot,
                         complete=bool(res["steps"]))


if __name__ == "__main__":
    sys.exit(main())
