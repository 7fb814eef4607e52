#!/usr/bin/python3
"""rigidSphere: compare F(delta) of every load step, the contact radius and
the peak pressure with Hertz's rigid indenter.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression test (tests/, pytest) reads
them with --json.

Hertz, a rigid sphere (radius R) on an elastic half-space (Johnson,
Contact Mechanics, 1985, eq. 4.22-4.23 with E2 infinite):
    E* = E / (1 - nu^2),  F = (4/3) E* R^(1/2) delta^(3/2),
    a = sqrt(R delta),    p0 = 3 F / (2 pi a^2).
Materials from constant/mechanicalProperties (one law, the block's).

Data, for every written time t:
  - delta(t): the sphere's indentation, R - (c_y + u_y(t)) with u the
    tool's translation table and c its centre in 0/D (for -surface
    triSurface the centre log.writeSphereStl printed), i.e. the table's
    descent less the -gap lift;
  - F: the load along the indentation, minus contactReport's forceY of
    the quarter patch blockTop (the slave is pushed down), times 4 for the
    whole sphere (SYMMETRY): Hertz's F is the axial load, where
    normalForce sums each face's force along its own normal (0.2 % more at
    a/R = 0.1);
  - contactPressure and contactActive of blockTop (face centres and areas
    from constant/polyMesh, the reference configuration), r = sqrt(x^2 +
    z^2).

Under force control (Allrun -force N) delta is the position the solver
found (contactReport's toolY column) and F the load it held: the same
checks then compare Hertz's F at that delta with the prescribed load.

Checks (h: the slave face width at the contact, 1 mm at -refine 1; a = 4.5
to 10 mm over the five steps, 4.5 to 10 faces):
  - force_step<i>: |F - F_Hertz(delta)| / F_Hertz at every step, tolerance
    F_TOL = 2 % (the issue's target). Measured at -refine 1: within
    0.7 % for lagrangeMultiplier (first step +0.1 %, last -0.6 %), within
    1 % for penalty (its penetration, 5e-6 m at the last step, 0.5 % of
    delta, takes 0.8 % off F). What is left is the mesh: on a coarser far
    field (27000 cells) the last step came out 1.9 % low; and the finite
    block (L = 100 a, fixed bottom: about +1 % of F, blockMeshDict).
  - contact_radius (last step): a_num = sqrt(4 A_active / pi), the circle
    with the active area (compareSphere.py's), against Hertz's a for the
    MEASURED F, tolerance A_TOL_FACES = 1 face width h at r = a (the
    discrete rim runs within half a face of the true one on either side),
    as hertzSphere.
  - peak_pressure (last step): max_f p_f against Hertz's p(r) at that
    face's centre for the measured F, tolerance P0_TOL = 4 %, as
    hertzSphere (the pole face, cut by both symmetry planes, oscillates by
    a few per cent).
Besides, printed: a and p0 against Hertz at delta (a = sqrt(R delta)) and
at the measured F, every step.
"""
import math
import os
import re
import sys

from c4fpost import contactreport, foamio, hertz, report

import numpy as np

R = 0.1                   # sphere radius [m], 0/D
SLAVE = "blockTop"
SYMMETRY = 4.0            # the quarter model
F_TOL = 0.02              # fraction of Hertz's F at delta, every step
A_TOL_FACES = 1.0         # slave face widths at r = a, the last step
P0_TOL = 0.04             # fraction of Hertz's peak pressure, the last step


def rigid_entry(case):
    """(centre y, translation table [(t, uy)]) of the rigid sphere; the
    table None under force control (Allrun -force)."""
    text = foamio.strip_comments(open(os.path.join(case, "0", "D")).read())
    m = re.search(r"translation\s+table\s*\((.*?)\)\s*\)\s*;", text, flags=re.S)
    if not m and re.search(r"\bforceControl\b", text):
        m = re.search(r"\bcentre\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)", text)
        return (float(m.group(1)) if m else R), None
    if not m:
        sys.exit("compareRigidSphere: no 'translation table (...)' in 0/D")
    table = [(float(t), float(uy)) for t, uy in
             re.findall(r"\(\s*(\S+)\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)\s*\)", m.group(1) + ")")]
    m = re.search(r"\bcentre\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)", text)
    if m:
        cy = float(m.group(1))
    else:
        log = os.path.join(case, "log.writeSphereStl")
        mm = re.search(r"centre \(0 (\S+) 0\)", open(log).read()) if os.path.exists(log) else None
        cy = float(mm.group(1)) if mm else R
    return cy, table


def indentation(case, t):
    """The sphere's depth at time t: from its translation table, or under
    force control the tool's translation contactReport wrote (toolY)."""
    cy, table = rigid_entry(case)
    if table is None:
        row = contactreport.row_at(case, SLAVE, t)
        return R - (cy + row["toolY"]) if row else 0.0
    ts, uy = zip(*table)
    return R - (cy + float(np.interp(t, ts, uy)))


def pressure_at(case, time):
    Cf, Sf = foamio.patch_geometry(case, SLAVE)
    n = Cf.shape[0]
    area = np.linalg.norm(Sf, axis=1)
    p = foamio.read_patch(os.path.join(case, time, "contactPressure"), SLAVE, n)
    active = foamio.read_patch(os.path.join(case, time, "contactActive"), SLAVE, n) > 0.5
    r = np.hypot(Cf[:, 0], Cf[:, 2])
    o = np.argsort(r)
    return r[o], p[o], active[o], area[o]


def compare(case):
    (b1, _), materials = foamio.body_constants(case)
    E, nu = b1
    Es = E / (1.0 - nu * nu)
    times = [t for t in foamio.times(case) if float(t) > 0]
    steps = []
    for t in times:
        d = indentation(case, float(t))
        row = contactreport.row_at(case, SLAVE, float(t))
        F = -SYMMETRY * row["forceY"] if row else 0.0
        FH = 4.0 / 3.0 * Es * math.sqrt(R) * max(d, 0.0) ** 1.5
        r, p, active, area = pressure_at(case, t)
        aNum = math.sqrt(SYMMETRY * float(area[active].sum()) / math.pi)
        aHd = math.sqrt(R * max(d, 0.0))
        aHF = hertz.sphere_radius(F, R, Es) if F > 0 else 0.0
        p0F = hertz.sphere_peak_pressure(F, aHF) if F > 0 else 0.0
        steps.append(dict(time=t, delta=d, F=F, FH=FH,
                          errF=abs(F - FH) / FH if FH > 0 else float("inf"),
                          aNum=aNum, aHd=aHd, aHF=aHF, p0=float(p.max()), p0F=p0F,
                          nActive=int(active.sum()),
                          correctors=int(row["outerCorrectors"]) if row else -1,
                          converged=int(row["converged"]) if row else 0))
    checks = []
    for i, s in enumerate(steps, 1):
        checks.append(dict(name="rigidSphere/force_step%d" % i, value=s["F"], reference=s["FH"],
                           error=s["errF"], tolerance=F_TOL,
                           units="N, whole sphere (error: fraction of Hertz at delta)"))
    last = steps[-1] if steps else None
    res = dict(steps=steps, Es=Es, materials=materials, checks=checks)
    if last is None or last["F"] <= 0:
        checks.append(dict(name="rigidSphere/contact", value=0.0, reference=1.0,
                           error=float("inf"), tolerance=0.0))
    else:
        r, p, active, area = pressure_at(case, last["time"])
        hA = float(np.sqrt(area[int(np.argmin(np.abs(r - last["aHF"])))]))
        iMax = int(np.argmax(p))
        p0Ref = float(hertz.sphere_pressure(r[iMax], last["F"], R, Es))
        checks += [
            dict(name="rigidSphere/contact_radius", value=last["aNum"], reference=last["aHF"],
                 error=abs(last["aNum"] - last["aHF"]), tolerance=A_TOL_FACES * hA,
                 units="m (tolerance: %.1f face widths)" % A_TOL_FACES),
            dict(name="rigidSphere/peak_pressure", value=float(p[iMax]), reference=p0Ref,
                 error=abs(float(p[iMax]) - p0Ref) / p0Ref, tolerance=P0_TOL,
                 units="Pa (error: fraction of Hertz)"),
        ]
        res.update(hA=hA, r=r.tolist(), p=p.tolist(), active=active.tolist())
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])
    try:
        res["method"] = foamio.read_entry(os.path.join(case, "0", "D"), "method")
    except (KeyError, OSError):
        res["method"] = None
    return res


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    st = res["steps"]
    Es = res["Es"]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    dd = np.linspace(0, 1.05 * max(s["delta"] for s in st), 200)
    ax1.plot(dd * 1e3, 4.0 / 3.0 * Es * math.sqrt(R) * dd ** 1.5 / 1e6, "k-",
             label="Hertz, rigid sphere")
    ax1.plot([s["delta"] * 1e3 for s in st], [s["F"] / 1e6 for s in st], "o",
             label="solidContactFoam, %s" % (res["method"] or "contact"))
    ax1.set_xlabel("indentation delta [mm]")
    ax1.set_ylabel("F [MN] (whole sphere)")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    last = st[-1]
    r, p = np.array(res["r"]), np.array(res["p"])
    active = np.array(res["active"], bool)
    aH = last["aHF"]
    sel = r < 1.6 * aH
    rr = np.linspace(0, 1.6 * aH, 600)
    ax2.plot(rr * 1e3, hertz.sphere_pressure(rr, last["F"], R, Es) / 1e9, "k-",
             label="Hertz for the measured F = %.4g MN" % (last["F"] / 1e6))
    ax2.plot(r[sel & active] * 1e3, p[sel & active] / 1e9, "o", ms=3, label="active faces")
    ax2.plot(r[sel & ~active] * 1e3, p[sel & ~active] / 1e9, "x", ms=3, color="C7",
             label="open faces")
    ax2.axvline(aH * 1e3, color="k", ls=":", lw=1)
    ax2.axvline(last["aNum"] * 1e3, color="C3", ls="--", lw=1,
                label="a: Hertz %.2f mm, numerical %.2f mm" % (aH * 1e3, last["aNum"] * 1e3))
    ax2.set_xlabel("r = sqrt(x^2 + z^2) [mm] on %s (time %s)" % (SLAVE, last["time"]))
    ax2.set_ylabel("contact pressure [GPa]")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    fig.suptitle("rigidSphere: rigid sphere R = %g m on an elastic block" % R)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "rigidSphere.png")
    res = compare(args.case)
    print("rigidSphere: rigid sphere on %s against Hertz (method %s)" % (SLAVE, res["method"]))
    print("  materials: %s; E* = E/(1 - nu^2) = %.6g Pa, R = %g m"
          % (res["materials"], res["Es"], R))
    print("  %-5s %-10s %-12s %-12s %-8s %-9s %-9s %-9s %-9s %-9s %-6s %s"
          % ("time", "delta[mm]", "F[N]", "F_Hertz[N]", "errF[%]", "a[mm]", "a(d)[mm]",
             "a(F)[mm]", "p0[GPa]", "p0(F)", "active", "correctors"))
    for s in res["steps"]:
        print("  %-5s %-10.4g %-12.6g %-12.6g %-+8.3f %-9.4g %-9.4g %-9.4g %-9.5g %-9.5g %-6d %d"
              % (s["time"], s["delta"] * 1e3, s["F"], s["FH"], 100 * (s["F"] / s["FH"] - 1),
                 s["aNum"] * 1e3, s["aHd"] * 1e3, s["aHF"] * 1e3, s["p0"] / 1e9,
                 s["p0F"] / 1e9, s["nActive"], s["correctors"]))
    if "hA" in res:
        print("  face width at a: %.4g mm (a/h = %.1f at the last step)"
              % (res["hA"] * 1e3, res["steps"][-1]["aHF"] / res["hA"]))
    return report.finish(res, args.case, args.png, args.json, plot,
                         complete=bool(res["steps"]) and "hA" in res)


if __name__ == "__main__":
    sys.exit(main())
