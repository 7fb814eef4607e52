#!/usr/bin/python3
"""cattaneoMindlin: compare the friction traction on the cylinder with
Cattaneo-Mindlin (two identical cylinders, system/blockMeshDict).

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
them with --json.

Data (latest time, t = 2 after Allrun, or --time; reference configuration,
x measured from the contact centre, where the two bodies touch at x = 0):
on the slave patch cylinderContact, contactTraction t (the traction the
base exerts on the cylinder), contactPressure p (positive in compression)
and contactStick (1 stick, 0 slip, -1 open); the face centres and area
vectors from constant/polyMesh; mu from coulombCoeffs of 0/D, E* from
constant/mechanicalProperties (one law for both bodies: identical
materials, so the normal and the tangential problems decouple and the
pressure stays Hertz's).

Direction. The contact normal is that of the current configuration. The
two cylinders are the same body turned by 180 deg about the contact
point, so the deformed contact is flat (y = 0) and the normal is e_y to
the solver's tolerance; the direction still comes from the deformed
surface. The solver's traction is
p n + q with n that normal. Here n and the unit tangent s (oriented along
+x) are those of the deformed slave surface, the polyline through the face
centres moved by their D (central differences along x); t.n - p is
printed (measured 2.3e-4 of p0 with coulomb: the polyline's normal
against the solver's). The cylinder's top is moved
along +x, so the base holds the cylinder back: the friction traction on
the cylinder points along -x, and the measured q of a face is -t.s,
positive when it opposes the applied motion. A friction force in the wrong direction makes
Q' negative and fails the load-ratio check.

Loads (per unit length; the model is one cell, dz, thick and FULL):
    P' = sum_f p_f |Sf_f| / dz,   Q' = sum_f q_f |Sf_f| / dz
(the vertical and horizontal resultants of contactTraction are printed
beside them); the contactReport row of the same time (normalForce =
sum p |S|, tangentialForce = sum |t_T| |S|) must give the same to 1 % (the
same sums, up to the sign of q, which is one-signed in Cattaneo-Mindlin,
and the normal, the solver's against the polyline's).

Closed form (c4fpost.cattaneo, c4fpost.hertz) for the MEASURED P' and Q':
a and p0 Hertz's (plane strain, the effective radius R/2 = 0.05 m of the
two cylinders of R = 0.1 m), c/a = sqrt(1 - Q'/(mu P')),
q(x) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)] for |x| < c and
mu p(x) for c <= |x| <= a.

Checks:
  - load ratio: Q'/(mu P') within 0.2 of 0.5, the partial-slip regime the
    case is built for (UX in 0/D; c/a between 0.55 and 0.84, several faces
    of stick and of slip). Without friction Q' is 0 and this fails.
  - stick-zone half-width from contactStick: c_stick is half the extent of
    the faces with contactStick = 1 (outer edge to outer edge; the centre
    of that extent is printed: identical materials centre the stick zone
    at the contact centre). Tolerance 1.5 slave-face widths (the width at
    x = c): half a face from sampling the edge by whole faces, one face for
    the discretisation next to the edge, where mu p - q rises like
    sqrt(c - |x|) (as hertzCylinder's a). Fails when the field is missing.
  - stick-zone half-width from the traction: c_q, half the extent of the
    faces with mu p - |q| > Q_DEPART mu p0 (the faces where the traction
    is below the Coulomb limit; in the slip zone the face-wise law gives
    q = mu p to the solver's tolerance, one face inside c the closed form
    is 0.24 mu p0 below it). Same tolerance.
  - RMS over the faces with |x| < a of q_measured - q_closed form, below
    5 % of mu p0 (the target of issue 10 for >= 20 faces across a;
    hertzCylinder's pressure on the same faces is within 1.2 % of p0 at the
    peak, with odd-even oscillations of about 1 %, and q inherits mu times
    those plus the stick-zone edge's sqrt, which the faces sample
    coarsely). Measured (lagrangeMultiplier) 1.48 % at 23.5 faces across
    a, 1.16 % at 46.9 (-refine 2), 0.75 % at 93.9 (-refine 4): most of it
    from the faces holding a and c, whose values depend on where a and c
    fall in them. On the earlier cylinder-on-block model 2.41, 1.12 and
    0.96 %, and 3.84 % while faces closing in the normal step were tied
    where they started (docs/friction.md).
  - q under the normal load alone (t = 1, when the run has it and is not
    frictionless): RMS over |x| < a below 0.5 % of mu p0 (identical
    bodies carry none; measured 0.005 %, 0.15 % on the cylinder on a
    block).
  - P' and Q' from contactReport against the sums above (1 %).
"""
import os
import sys

from c4fpost import cattaneo, contactreport, foamio, hertz, report

import numpy as np

NAME = "cattaneoMindlin"
R = 0.2                   # each cylinder's radius [m], system/blockMeshDict
R_EFF = hertz.effective_radius(R, R)   # Hertz's, of the two cylinders
SLAVE = "cylinderContact"
LOAD_RATIO = 0.5          # Q'/(mu P') the case is built for
LOAD_RATIO_TOL = 0.2
C_TOL_FACES = 1.5         # slave-face widths at x = c
RMS_TOL = 0.05            # fraction of mu p0
Q1_TOL = 0.005            # q RMS under the normal load alone (t = 1), of mu p0
Q_DEPART = 0.01           # fraction of mu p0: below the Coulomb limit
REPORT_TOL = 0.01         # contactReport against the traction resultants


def extent(x, w, sel):
    """(half-width, centre) of the faces `sel` from their outer edges; (0,
    nan) when there is none."""
    if not sel.any():
        return 0.0, float("nan")
    lo = float((x[sel] - 0.5 * w[sel]).min())
    hi = float((x[sel] + 0.5 * w[sel]).max())
    return 0.5 * (hi - lo), 0.5 * (hi + lo)


def check(name, value, reference, error, tolerance, units, note=""):
    return dict(name="%s/%s" % (NAME, name), value=float(value), reference=float(reference),
                error=float(error), tolerance=float(tolerance), units=units,
                passed=bool(error <= tolerance), note=note)


def compare(case, time=None):
    time = time or foamio.latest_time(case)
    E, nu, ps = foamio.elastic_constants(case, "cylinder")
    Es = hertz.contact_modulus(E, 0.0 if ps else nu)
    d0 = os.path.join(case, "0", "D")
    mu = float(foamio.read_coeff(d0, "coulombCoeffs", "mu"))
    method = friction = None
    try:
        method = foamio.read_entry(d0, "method")
        friction = foamio.read_entry(d0, "friction")
    except KeyError:
        pass
    dz = foamio.thickness(case)

    Cf, Sf = foamio.patch_geometry(case, SLAVE)
    n = Cf.shape[0]
    area = np.linalg.norm(Sf, axis=1)
    order = np.argsort(Cf[:, 0])
    x = Cf[order, 0]
    area = area[order]
    w = area / dz                                   # face width along the arc

    def field(name):
        path = os.path.join(case, time, name)
        return foamio.read_patch(path, SLAVE, n)[order] if os.path.exists(path) else None

    t = field("contactTraction")
    p = field("contactPressure")
    D = field("D")
    stick = field("contactStick")
    if t is None or p is None or D is None:
        raise SystemExit("compareCattaneo: no contactTraction, contactPressure or D at time %s"
                         % time)
    # the deformed slave surface: its unit tangent s (along +x) and normal n
    # (into the cylinder, the direction of the pressure's traction)
    s = np.gradient(Cf[order, :2] + D[:, :2], axis=0)
    s /= np.linalg.norm(s, axis=1)[:, None]
    s *= np.where(s[:, 0] < 0, -1.0, 1.0)[:, None]
    nc = np.stack([-s[:, 1], s[:, 0]], axis=1)
    t = t[:, :2]
    q = -np.einsum("ij,ij->i", t, s)
    P = float(np.sum(p * area)) / dz
    Q = float(np.sum(q * area)) / dz
    resultants = (float(np.sum(t[:, 1] * area)) / dz, -float(np.sum(t[:, 0] * area)) / dz)
    if P <= 0:
        raise SystemExit("compareCattaneo: no contact at time %s (P' = %g)" % (time, P))
    a = hertz.half_width(P, R_EFF, Es)
    p0 = hertz.peak_pressure(P, a)
    ratio = Q / (mu * P)
    ca = cattaneo.stick_ratio(min(max(ratio, 0.0), 1.0))
    c = ca * a
    qRef = cattaneo.traction(x, P, max(Q, 0.0), mu, R_EFF, Es)
    mup = mu * p
    inA = np.abs(x) < a
    normalMismatch = float(np.abs(np.einsum("ij,ij->i", t, nc) - p)[inA].max()) / p0
    rms = float(np.sqrt(np.mean((q[inA] - qRef[inA]) ** 2))) / (mu * p0)
    iC = int(np.argmin(np.abs(np.abs(x) - c)))
    hC = float(w[iC])

    checks = [check("load_ratio", ratio, LOAD_RATIO, abs(ratio - LOAD_RATIO), LOAD_RATIO_TOL,
                    "Q'/(mu P')")]
    if stick is not None:
        cStick, centre = extent(x, w, stick > 0.5)
        holes = int(((stick < 0.5) & (np.abs(x - centre) < cStick)).sum()) if cStick else 0
        checks.append(check("stick_half_width", cStick, c, abs(cStick - c), C_TOL_FACES * hC,
                            "m (tolerance: %.1f face widths)" % C_TOL_FACES))
    else:
        cStick, centre, holes = float("nan"), float("nan"), 0
        checks.append(check("stick_half_width", 0.0, c, float("inf"), C_TOL_FACES * hC,
                            "m", note="no contactStick field at time %s" % time))
    cQ, centreQ = extent(x, w, (mup - np.abs(q) > Q_DEPART * mu * p0) & inA)
    checks.append(check("stick_half_width_from_q", cQ, c, abs(cQ - c), C_TOL_FACES * hC,
                        "m (tolerance: %.1f face widths)" % C_TOL_FACES))
    checks.append(check("q_rms_error", rms, 0.0, rms, RMS_TOL, "fraction of mu p0"))
    # Under the normal load alone (t = 1) identical bodies carry no q
    # (Cattaneo-Mindlin's premise); what the run has there is the stick
    # law's error: faces closing within the step tied where they started
    # gave 5 % of mu p0 (frictionModel)
    q1 = None
    if str(time) != "1" and os.path.isdir(os.path.join(case, "1")) and \
            friction != "frictionless":
        r1 = compare(case, "1")
        x1, q1v = np.array(r1["x"]), np.array(r1["q"])
        in1 = np.abs(x1) < r1["a"]
        q1 = float(np.sqrt(np.mean(q1v[in1] ** 2))) / (r1["mu"] * r1["p0"])
        checks.append(check("q_normal_load", q1, 0.0, q1, Q1_TOL,
                            "fraction of mu p0, RMS over |x| < a at t = 1"))

    rep = contactreport.row_at(case, SLAVE, float(time))
    extra = {}
    if rep and "normalForce" in rep:
        Prep, Qrep = rep["normalForce"] / dz, rep.get("tangentialForce", 0.0) / dz
        extra.update(P_contactReport=Prep, Q_contactReport=Qrep, report=rep)
        checks.append(check("P_contactReport", Prep, P, abs(Prep / P - 1), REPORT_TOL,
                            "N/m (error: fraction of P')"))
        errQ = abs(Qrep / Q - 1) if Q > 0 else float("inf")
        checks.append(check("Q_contactReport", Qrep, Q, errQ, REPORT_TOL,
                            "N/m (error: fraction of Q')"))
    else:
        checks.append(check("contactReport", 0.0, 0.0, float("inf"), 0.0, "",
                            note="no contactReport row at time %s" % time))
    return dict(time=time, method=method, friction=friction, mu=mu, Es=Es, P=P, Q=Q,
                resultants=resultants, normalMismatch=normalMismatch,
                ratio=ratio, a=a, p0=p0, c=c, ca=ca, cStick=cStick, centre=centre,
                holes=holes, cQ=cQ, centreQ=centreQ, hC=hC, rms=rms, q1=q1,
                x=x.tolist(), p=p.tolist(), q=q.tolist(), qRef=qRef.tolist(),
                stick=None if stick is None else stick.tolist(), extra=extra, checks=checks)


def plot(res, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    a, p0, mu = res["a"], res["p0"], res["mu"]
    x = np.array(res["x"])
    q = np.array(res["q"])
    p = np.array(res["p"])
    xr = 1.4 * a
    sel = np.abs(x) < xr
    xx = np.linspace(-xr, xr, 1201)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    scale = mu * p0
    ax.plot(xx * 1e3, mu * hertz.pressure(xx, res["P"], R_EFF, res["Es"]) / scale, "k--", lw=1,
            label=r"$\mu p(x)$, Hertz for the measured P'")
    ax.plot(xx * 1e3, cattaneo.traction(xx, res["P"], max(res["Q"], 0.0), mu, R_EFF, res["Es"])
            / scale, "k-", label="Cattaneo-Mindlin q(x), c/a = %.3f" % res["ca"])
    ax.plot(x[sel] * 1e3, mu * p[sel] / scale, "s", ms=3, mfc="none", color="C7",
            label=r"$\mu p$ (faces)")
    if res["stick"] is not None:
        st = np.rint(res["stick"])
        for value, style, what in ((1, dict(color="C0"), "stick"),
                                   (0, dict(mfc="none", color="C3"), "slip"),
                                   (-1, dict(ms=2, color="C7"), "open")):
            f = sel & (st == value)
            ax.plot(x[f] * 1e3, q[f] / scale, "o", **dict(dict(ms=4), **style),
                    label="q, %s faces" % what)
    else:
        ax.plot(x[sel] * 1e3, q[sel] / scale, "o", ms=4, color="C0", label="q (faces)")
    for v in (-res["c"], res["c"]):
        ax.axvline(v * 1e3, color="k", ls=":", lw=1)
    if res["cStick"] == res["cStick"] and res["cStick"] > 0:
        for v in (res["centre"] - res["cStick"], res["centre"] + res["cStick"]):
            ax.axvline(v * 1e3, color="C0", ls="--", lw=1)
    ax.set_xlabel("x [mm] on cylinderContact (reference configuration)")
    ax.set_ylabel(r"friction traction / ($\mu p_0$)")
    ax.set_title("cattaneoMindlin (%s, %s): Q'/($\\mu$P') = %.3f, c/a %.3f (exact %.3f)"
                 % (res["method"], res["friction"], res["ratio"],
                    res["cStick"] / res["a"] if res["cStick"] == res["cStick"] else float("nan"),
                    res["ca"]), fontsize=9)
    ax.set_xlim(-xr * 1e3, xr * 1e3)
    ax.set_ylim(-0.05, 1.15)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "cattaneoTraction.png", [
        ("--time", dict(default=None, help="the time to compare (default: the latest)"))])
    res = compare(args.case, args.time)
    print("cattaneoMindlin: friction traction on %s against Cattaneo-Mindlin (time %s,"
          " method %s, friction %s, mu %g)" % (SLAVE, res["time"], res["method"],
                                               res["friction"], res["mu"]))
    print("  E* = %.6g Pa, R* = %g m; measured P' = %.6g N/m (contactPressure), Q' = %.6g N/m"
          " (contactTraction along the deformed surface)" % (res["Es"], R_EFF, res["P"], res["Q"]))
    print("  resultants of contactTraction: vertical %.6g N/m, horizontal %.6g N/m;"
          " max |t.n - p| = %.3g p0" % (res["resultants"] + (res["normalMismatch"],)))
    ex = res["extra"]
    if "P_contactReport" in ex:
        print("  contactReport: P' = %.6g N/m (%+.3g %%), Q' = %.6g N/m"
              % (ex["P_contactReport"], 100 * (ex["P_contactReport"] / res["P"] - 1),
                 ex["Q_contactReport"]))
    print("  Hertz: a = %.5g mm, p0 = %.6g MPa (measured max p %.6g MPa)"
          % (res["a"] * 1e3, res["p0"] / 1e6, max(res["p"]) / 1e6))
    print("  Q'/(mu P') = %.4f; c/a exact sqrt(1 - Q'/(mu P')) = %.4f, c = %.4g mm"
          % (res["ratio"], res["ca"], res["c"] * 1e3))
    if res["stick"] is not None:
        print("  measured (contactStick = 1): c = %.4g mm, c/a = %.4f, centre x = %.4g mm,"
              " %d non-stick faces inside" % (res["cStick"] * 1e3, res["cStick"] / res["a"],
                                              res["centre"] * 1e3, res["holes"]))
    else:
        print("  measured (contactStick): no contactStick field")
    print("  measured (mu p - |q| > %g mu p0): c = %.4g mm, c/a = %.4f, centre x = %.4g mm"
          % (Q_DEPART, res["cQ"] * 1e3, res["cQ"] / res["a"], res["centreQ"] * 1e3))
    print("  RMS of q - closed form over |x| < a: %.4g of mu p0; face width at c %.4g mm"
          % (res["rms"], res["hC"] * 1e3))
    if res["q1"] is not None:
        print("  RMS of q under the normal load alone (t = 1, closed form 0): %.4g of mu p0"
              % res["q1"])
    x, p, q, qr = (np.array(res[k]) for k in ("x", "p", "q", "qRef"))
    st = res["stick"]
    print("%10s %8s %12s %12s %12s %12s %6s" % ("x [mm]", "x/a", "p [MPa]", "mu p [MPa]",
                                               "q [MPa]", "exact [MPa]", "stick"))
    show = np.nonzero(np.abs(x) < 1.1 * res["a"])[0]
    for i in show[::2]:
        print("%10.4f %8.4f %12.6g %12.6g %12.6g %12.6g %6s"
              % (x[i] * 1e3, x[i] / res["a"], p[i] / 1e6, res["mu"] * p[i] / 1e6, q[i] / 1e6,
                 qr[i] / 1e6, "-" if st is None else "%d" % round(st[i])))
    for c in res["checks"]:
        if c.get("note"):
            print("  NOTE %s: %s" % (c["name"], c["note"]))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
