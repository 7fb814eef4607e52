#!/usr/bin/python3
"""slidingBlock: in full slip the friction force is mu times the normal force.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
them with --json.

Data (every written time; the checks at the last one): on the slave patch
upperBottom, contactTraction t (the traction the lower block exerts on the
upper one), contactPressure p (its normal part, positive in compression)
and contactStick (1 stick, 0 slip, -1 open); the contactReport rows
(normalForce = sum p |S|, tangentialForce = sum |t_T| |S|); mu from
coulombCoeffs of 0/D.

Forces from the traction field, face by face: the normal part is p, the
tangential part |t_T| = sqrt(|t|^2 - p^2) (the solver's p is the normal
component of its traction, so this needs no normal of ours; the
interface's normal is tilted by the blocks' rotation, about 1e-2 here, so
t_x would not do: p times that tilt is 3 % of mu p). Then
    F_N = sum_f p_f |Sf_f|,   F_T = sum_f |t_T,f| |Sf_f|.

Checks at the last time (the top pushed 0.04 m, about four times the
stick limit: full slip):
  - F_T/(mu F_N) = 1 to 1e-6 relative, from contactReport and from the
    traction field: in full slip every face carries |t_T| = mu p (the
    Coulomb return map), so the sums do too; what is left is the outer
    correctors' tolerance (1e-9) and the 12 written digits. Without
    friction F_T is 0 and these fail.
  - every contact face slips: no face with contactStick 1 among those in
    contact (contactStick >= 0), and at least one in contact. Fails when
    the field is missing.
  - the friction force opposes the motion: the top moves along +x, so the
    lower block holds the upper one back, -F_x/F_T = 1 (F_x = sum t_x
    |S|) within 0.1 (the interface's tilt, ~1e-2, makes the pressure's x
    part up to 3 % of F_T; a reversed friction force gives -1).
The ratio F_T/(mu F_N) of every step is printed (partial slip before the
limit, 1 beyond it).
"""
import os
import sys

from c4fpost import contactreport, foamio, report

import numpy as np

NAME = "slidingBlock"
SLAVE = "upperBottom"
RATIO_TOL = 1e-6
DIRECTION_TOL = 0.1


def check(name, value, reference, error, tolerance, units, note=""):
    return dict(name="%s/%s" % (NAME, name), value=float(value), reference=float(reference),
                error=float(error), tolerance=float(tolerance), units=units,
                passed=bool(error <= tolerance), note=note)


def step_forces(case, time, area):
    """F_N, F_T, F_x and the stick counts of the slave at `time` from the
    fields (None for the stick counts without contactStick)."""
    n = area.size

    def field(name):
        path = os.path.join(case, time, name)
        return foamio.read_patch(path, SLAVE, n) if os.path.exists(path) else None

    t, p, stick = field("contactTraction"), field("contactPressure"), field("contactStick")
    if t is None or p is None:
        return None
    tT = np.sqrt(np.clip(np.einsum("ij,ij->i", t, t) - p * p, 0.0, None))
    out = dict(FN=float(np.sum(p * area)), FT=float(np.sum(tT * area)),
               Fx=float(np.sum(t[:, 0] * area)))
    if stick is not None:
        st = np.rint(stick)
        out.update(inContact=int((st >= 0).sum()), sticking=int((st == 1).sum()),
                   slipping=int((st == 0).sum()), open=int((st < 0).sum()))
    return out


def compare(case):
    d0 = os.path.join(case, "0", "D")
    mu = float(foamio.read_coeff(d0, "coulombCoeffs", "mu"))
    method = friction = None
    try:
        method = foamio.read_entry(d0, "method")
        friction = foamio.read_entry(d0, "friction")
    except KeyError:
        pass
    _, Sf = foamio.patch_geometry(case, SLAVE)
    area = np.linalg.norm(Sf, axis=1)

    steps = []
    for time in foamio.times(case):
        f = step_forces(case, time, area)
        if f is None:
            continue
        f["time"] = float(time)
        f["ratio"] = f["FT"] / (mu * f["FN"]) if f["FN"] > 0 else float("nan")
        row = contactreport.row_at(case, SLAVE, float(time))
        if row and "normalForce" in row:
            f["FN_report"], f["FT_report"] = row["normalForce"], row.get("tangentialForce", 0.0)
            f["ratio_report"] = (f["FT_report"] / (mu * f["FN_report"])
                                 if f["FN_report"] > 0 else float("nan"))
        steps.append(f)
    if not steps:
        raise SystemExit("compareSliding: no time with contactTraction and contactPressure")
    last = steps[-1]

    def ratio_check(name, r):
        err = abs(r - 1.0) if r == r else float("inf")
        return check(name, r, 1.0, err, RATIO_TOL, "F_T/(mu F_N)")

    checks = [ratio_check("force_ratio_traction", last["ratio"])]
    if "ratio_report" in last:
        checks.append(ratio_check("force_ratio_contactReport", last["ratio_report"]))
    else:
        checks.append(check("force_ratio_contactReport", 0.0, 1.0, float("inf"), RATIO_TOL,
                            "F_T/(mu F_N)", note="no contactReport row at the last time"))
    if "sticking" in last:
        ok = last["inContact"] > 0
        checks.append(check("faces_not_slipping", last["sticking"], 0,
                            last["sticking"] if ok else float("inf"), 0,
                            "faces with contactStick 1 (of %d in contact)" % last["inContact"]))
    else:
        checks.append(check("faces_not_slipping", 0, 0, float("inf"), 0, "faces",
                            note="no contactStick field at the last time"))
    direction = -last["Fx"] / last["FT"] if last["FT"] > 0 else 0.0
    checks.append(check("friction_opposes_motion", direction, 1.0, abs(direction - 1.0),
                        DIRECTION_TOL, "-F_x/F_T"))
    return dict(mu=mu, method=method, friction=friction, steps=steps, checks=checks)


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    st = res["steps"]
    t = [s["time"] for s in st]
    fig, ax = plt.subplots(figsize=(6, 3.8))
    ax.axhline(res["mu"], color="k", ls="--", lw=1, label=r"$\mu$ = %g" % res["mu"])
    ax.plot(t, [s["FT"] / s["FN"] for s in st], "o-", label="traction field")
    if all("FT_report" in s for s in st):
        ax.plot(t, [s["FT_report"] / s["FN_report"] for s in st], "s", mfc="none", ms=8,
                label="contactReport")
    ax.set_xlabel("load step (t = 1 pressed, t = 2..5 pushed)")
    ax.set_ylabel(r"$F_T / F_N$")
    ax.set_title("slidingBlock (%s, %s)" % (res["method"], res["friction"]), fontsize=9)
    ax.set_ylim(-0.02, 1.3 * res["mu"])
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "slidingForces.png")
    res = compare(args.case)
    print("slidingBlock: friction force on %s (method %s, friction %s, mu %g)"
          % (SLAVE, res["method"], res["friction"], res["mu"]))
    print("%6s %14s %14s %14s %14s %16s %8s" % ("time", "F_N [N]", "F_T [N]",
                                               "F_T/(mu F_N)", "(contactReport)",
                                               "stick/slip/open", "-F_x/F_T"))
    for s in res["steps"]:
        counts = ("%d/%d/%d" % (s["sticking"], s["slipping"], s["open"])
                  if "sticking" in s else "-")
        print("%6g %14.9g %14.9g %14.9g %14.9g %16s %8.4f"
              % (s["time"], s["FN"], s["FT"], s["ratio"], s.get("ratio_report", float("nan")),
                 counts, -s["Fx"] / s["FT"] if s["FT"] > 0 else 0.0))
    for c in res["checks"]:
        if c.get("note"):
            print("  NOTE %s: %s" % (c["name"], c["note"]))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
