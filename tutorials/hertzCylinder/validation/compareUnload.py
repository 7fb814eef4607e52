#!/usr/bin/python3
"""hertzCylinder -unload: load, unload halfway, lift off; the contact opens.

Allrun -unload runs three load steps (0/D, $unloading): t = 1 the load
step of the tutorial (the block's bottom held), t = 2 the block's bottom
lowered by DELTA/2 (half the approach), t = 3 lowered by 1.1 DELTA (the
cylinder, its top held at -DELTA, lifts off by 0.1 DELTA). The checks,
their tolerances and where the tolerances come from live here; the
tutorial prints them, the tests (tests/regression) reads them with --json.

Loaded states (compareHertz.compare at t = 1 and t = 2): frictionless
elastic contact has no memory, so the half-unloaded state is Hertz's for
its own measured load, with the tolerances of the load step (p0 within
3 %, a within 1.5 slave-face widths). A multiplier stuck at its loaded
value would show there as a too wide contact.

Unloading (contactReport, postProcessing/contactReport/0/<slave>.dat):
  - the normal force decreases from step to step (no step raises it);
  - at t = 3 the force is zero: |F_N| <= 1e-6 F_N(t = 1). The steps stop
    at residual 1e-9, which leaves about 1e-9 of the force; 1e-6 is the
    margin the serial-parallel checks use;
  - at t = 3 no face is active.

The lifted state (t = 3): with no contact force both bodies are stress
free and have moved rigidly, the cylinder by its top's displacement, the
block by its bottom's, so every slave face's gap is its reference gap to
the block's top (a plane) plus the lift, the difference of the two
prescribed displacements (read from the written D):
  - max |g - (y_f - y_top + lift)| <= 1e-6 lift over the faces in reach
    of the search (contactGap; the 1e-9 residual leaves about 1e-9 of
    DELTA);
  - max |sigma| <= 1e-6 of the peak pressure at t = 1 (sigma; the same
    margin over the residual).

Multipliers (methods with stored multipliers, augmentedLagrange and
crossConstraint, and a method with multiplierUpdate converged:
contactReport's <slave>Multipliers.dat, one row per face
and update with the multiplier the inner correctors held and the gap and
pressure they converged to). A face separates in step t when it held a
positive multiplier at the start of the step and holds zero at its end.
  - The faces that separate are the faces that leave the active set:
    their number equals activeFaces(t-1) - activeFaces(t).
  - Their multipliers decay monotonically until they reach zero: every
    update lowers them, none raises one or changes its sign (the slowest
    decay, max lambda_{j+1}/lambda_j over the updates down to the first
    zero, must be below 1: no tolerance, a multiplier that moves up or
    stalls fails).
  - The multiplier force sum_f lambda_f |S_f| of each unloading step
    falls monotonically from the loaded state's to the step's result, no
    update overshoots it: max (F_{j+1} - F_j)/F_N(t = 1) <= 1e-9, the
    outer-corrector tolerance, which is as far as a converged multiplier
    is defined.
  - crossConstraint: the decay is the exponential multiplier update of an
    open face, lambda_{j+1} = lambda_j exp(-eps g_j/lambda_j), eps =
    penaltyScale K/h (K = 2 mu + lambda of the slave's law, h = V/A of
    the face's cell): smooth, a factor exp(-x) < 1 with x = eps g/lambda,
    not a snap to zero. On a face still coupled the new multiplier is
    the pressure the inner correctors converged to, so this checks that
    they converged to the law; on a released face it is the law's value.
  - With multiplierUpdate corrector (the family's default) no
    update follows the correctors, the multipliers move with them: at
    t = 2 and 3 the faces with lambda > 0 in the written contactMultiplier
    must be exactly the active faces.
    Checked on every open face and update down to 1e-6 lambda_j (below,
    the new multiplier, kPa or less, nears the resolution of the solve's
    pressure, whose residual traction on open faces is tens of Pa): the
    exponent ln(lambda_j/lambda_{j+1}) against x within 1e-4 of x. The
    1e-9 residual moves a gap by about 1e-9 DELTA, eps 1e-9 DELTA/lambda
    or some 1e-7 of x; 1e-4 is the margin.
  augmentedLagrange: lambda_{j+1} = <lambda_j - eps g_j> snaps an open
  face's multiplier to zero once eps g > lambda; its faces are checked
  for the monotone decay and the force only.

Plot (hertzUnload.png): the pressure of the two loaded states against
Hertz, the normal force of each step, and the multipliers of the faces
that separate, update by update.
"""
import math
import os
import sys

import compareHertz
from c4fpost import contactreport, elastic, foamio, hertz, methods, patchtest, report

import numpy as np

NAME = "hertzCylinder"
FORCE_TOL = 1e-6          # of F_N(t = 1)
GAP_TOL = 1e-6            # of the lift
STRESS_TOL = 1e-6         # of the peak pressure at t = 1
DECAY_TOL = 1e-4          # of the exponent eps g / lambda
UPDATE_FORCE_TOL = 1e-9   # of F_N(t = 1): a rise of the multiplier force
RESOLVED = 1e-6           # lambda_{j+1}/lambda_j above which the decay is checked
LOADED, HALF, LIFTED = "1", "2", "3"


def check(name, value, reference, error, tolerance, units="", passed=None):
    return dict(name="%s/%s" % (NAME, name), value=float(value), reference=float(reference),
                error=float(error), tolerance=float(tolerance), units=units,
                passed=bool(error <= tolerance) if passed is None else bool(passed))


def eps_of_faces(case, slave, method):
    """eps = penaltyScale K/h of every slave face (uzawaMethod's), or None
    for a method without it."""
    if methods.get(method).multipliers != "augmented":
        return None
    s = methods.coeff(case, method, "penaltyScale")
    mats = foamio.materials(case)
    E, nu, ps = mats[None] if None in mats else mats[slave.replace("Contact", "")]
    K = elastic.impK(E, nu, ps)
    _, V = foamio.cell_centres_volumes(case)
    _, Sf = foamio.patch_geometry(case, slave)
    h = V[foamio.patch_face_cells(case, slave)] / np.linalg.norm(Sf, axis=1)
    return s * K / h


def face_index(Cf, x, y):
    """The slave face whose centre is (x, y) (the rows' face centres)."""
    d = (Cf[:, 0] - x) ** 2 + (Cf[:, 1] - y) ** 2
    i = int(np.argmin(d))
    if d[i] > 1e-18:
        raise RuntimeError("no slave face at (%g, %g)" % (x, y))
    return i


def multiplier_checks(case, slave, method, rows, mult, Cf, area):
    """The separating faces of each unloading step, their decay, and the
    multiplier force of each update."""
    eps = eps_of_faces(case, slave, method)
    active = {"%g" % r["time"]: r["activeFaces"] for r in rows}
    checks, histories, forces = [], {}, {}
    slowest, worstDecay, nDecay, forceRise = 0.0, 0.0, 0, -math.inf
    inLoop = methods.coeff_text(case, method, "multiplierUpdate") == "corrector"
    for t in (HALF, LIFTED):
        sel = np.abs(mult["time"] - float(t)) < 1e-9
        if inLoop:
            # multiplierUpdate corrector: the multipliers move with the
            # correctors, no update follows them; the written ones are the
            # converged iterate's, positive exactly on the active faces
            lam = foamio.read_patch(os.path.join(case, t, "contactMultiplier"), slave,
                                    Cf.shape[0])
            n = int(np.sum(lam > 0))
            nA = active["%g" % float(t)]
            checks.append(check("t%s_multiplier_faces" % t, n, nA, abs(n - nA), 0,
                                "faces with lambda > 0 (reference: active faces)"))
            continue
        faces = sorted(set(zip(mult["x"][sel], mult["y"][sel])))
        sep = []
        Fj = np.zeros(int(mult["update"][sel].max()) + 1)
        for (x, y) in faces:
            f = sel & (mult["x"] == x) & (mult["y"] == y)
            order = np.argsort(mult["update"][f])
            lam = mult["multiplier"][f][order]
            g = mult["gap"][f][order]
            Fj[mult["update"][f][order].astype(int)] += lam * area[face_index(Cf, x, y)]
            if lam[0] > 0 and lam[-1] == 0:
                sep.append((x, y, lam, g))
        forces[t] = Fj
        forceRise = max(forceRise, float(np.max(np.diff(Fj))) if Fj.size > 1 else -math.inf)
        histories[t] = sep
        prev = active.get("%g" % (float(t) - 1))
        n = len(sep)
        dA = (prev - active["%g" % float(t)]) if prev is not None else float("nan")
        checks.append(check("t%s_separating_faces" % t, n, dA, abs(n - dA), 0,
                            "faces (reference: active faces leaving the set)"))
        for (x, y, lam, g) in sep:
            k = int(np.argmax(lam == 0))
            slowest = max(slowest, float(np.max(lam[1:k + 1] / lam[:k])))
            if eps is None or method != "crossConstraint":
                continue
            e = eps[face_index(Cf, x, y)]
            for j in range(len(lam) - 1):
                if g[j] > 0 and lam[j + 1] > RESOLVED * lam[j]:
                    xj = e * g[j] / lam[j]
                    worstDecay = max(worstDecay, abs(math.log(lam[j] / lam[j + 1]) - xj) / xj)
                    nDecay += 1
    nSep = sum(len(v) for v in histories.values())
    if nSep:
        checks.append(check("separating_multipliers_monotone", slowest, 1.0,
                            max(slowest - 1.0, 0.0), 0.0,
                            "max lambda_j+1/lambda_j down to zero, %d faces" % nSep,
                            passed=slowest < 1))
    F1 = rows[0]["normalForce"]
    if not inLoop:
        checks.append(check("unload_multiplier_force_monotone", forceRise / F1, 0.0,
                            max(forceRise / F1, 0.0), UPDATE_FORCE_TOL,
                            "max (F_j+1 - F_j)/F_N(t = 1) over the updates"))
    if method == "crossConstraint" and not inLoop:
        checks.append(check("separating_multipliers_exponential_decay", worstDecay, 0.0,
                            worstDecay if nDecay else math.inf, DECAY_TOL,
                            "max |ln(l_j/l_j+1) - eps g/l_j| / (eps g/l_j), %d updates"
                            % nDecay))
    return checks, histories, forces


def compare(case, estar="both"):
    ts = foamio.times(case)
    if ts[:3] != [LOADED, HALF, LIFTED]:
        raise RuntimeError("expected the times 1 2 3 of Allrun -unload in %s, found %s"
                           % (case, ts))
    loaded = compareHertz.compare(case, estar, LOADED)
    half = compareHertz.compare(case, estar, HALF)
    checks = []
    for tag, res in (("t1", loaded), ("t2", half)):
        for c in res["checks"]:
            c = dict(c)
            c["name"] = c["name"].replace(NAME + "/", "%s/%s_" % (NAME, tag), 1)
            checks.append(c)
    slave = loaded.get("slave") or patchtest.slave_patch(case, LOADED, compareHertz.PATCHES)
    method = loaded.get("method")
    master = [p for p in compareHertz.PATCHES if p != slave][0]

    rows = contactreport.rows(case, slave)
    F = np.array([r["normalForce"] for r in rows])
    F1 = F[0]
    rise = float(np.max(np.diff(F)) / F1)
    checks.append(check("unload_force_decreasing", rise, 0.0, max(rise, 0.0), 0.0,
                        "max (F_k+1 - F_k)/F_1 over the steps"))
    checks.append(check("t3_normal_force", F[-1], 0.0, abs(F[-1]) / F1, FORCE_TOL,
                        "N (error: fraction of F_N(t = 1))"))
    checks.append(check("t3_active_faces", rows[-1]["activeFaces"], 0,
                        rows[-1]["activeFaces"], 0, "faces"))

    # The lifted state: rigid motions, no stress
    Cf, Sf = foamio.patch_geometry(case, slave)
    CfM, _ = foamio.patch_geometry(case, master)
    n = Cf.shape[0]
    D3 = os.path.join(case, LIFTED, "D")
    nFaces = {p: v[1] for p, v in foamio.read_boundary(case).items()}
    # fixedNormalSlip writes its prescribed displacement, not a value
    top = foamio.read_patch(D3, "cylinderTop", nFaces["cylinderTop"], key="fixedValue")[:, 1].mean()
    bottom = foamio.read_patch(D3, "blockBottom", nFaces["blockBottom"])[:, 1].mean()
    # the slave's displacement minus the master's
    lift = (top - bottom) if slave == "cylinderContact" else (bottom - top)
    gExact = np.abs(Cf[:, 1] - CfM[:, 1].mean()) + lift
    g = foamio.read_patch(os.path.join(case, LIFTED, "contactGap"), slave, n)
    # faces beyond the search distance carry it as their gap (the largest)
    inRange = g < g.max() * (1 - 1e-12)
    gErr = float(np.max(np.abs(g - gExact)[inRange]))
    checks.append(check("t3_gap_rigid_lift", float(g.min()), float(gExact.min()), gErr / lift,
                        GAP_TOL, "m (error: max |g - (g_0 + lift)| / lift)"))
    sig = foamio.read_internal(os.path.join(case, LIFTED, "sigma"))
    p1 = float(np.max(loaded["p"]))
    sErr = float(np.abs(sig).max())
    checks.append(check("t3_stress_free", sErr, 0.0, sErr / p1, STRESS_TOL,
                        "Pa (error: fraction of p0 at t = 1)"))

    mult = contactreport.multipliers(case, slave)
    histories, forces = {}, {}
    if mult is not None:
        mc, histories, forces = multiplier_checks(case, slave, method, rows, mult, Cf,
                                                  np.linalg.norm(Sf, axis=1))
        checks += mc

    return dict(method=method, slave=slave, loaded=loaded, half=half, rows=rows,
                lift=lift, gErr=gErr, nInRange=int(inRange.sum()), sErr=sErr, histories=histories, forces=forces,
                checks=checks)


def plot(res, png):
    plt = patchtest.pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.3))
    ax = axes[0]
    for key, lab, col in (("loaded", "t = 1 (loaded)", "C0"), ("half", "t = 2 (half)", "C1")):
        r = res[key]
        x, p = np.array(r["x"]), np.array(r["p"])
        sel = x < 1.6 * res["loaded"]["aH"]
        xx = np.linspace(0, 1.6 * res["loaded"]["aH"], 600)
        ax.plot(xx * 1e3, hertz.pressure(xx, r["P"], compareHertz.R, r["Es"]) / 1e6, "-",
                color=col, lw=1, label="Hertz, P' = %.3g N/m" % r["P"])
        ax.plot(x[sel] * 1e3, p[sel] / 1e6, "o", ms=3, color=col, label=lab)
    ax.axhline(0, color="C2", lw=2, label="t = 3 (lifted off): p = 0")
    ax.set_xlabel("x [mm] on %s" % res["slave"])
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_title("pressure of the loaded states")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = axes[1]
    t = [r["time"] for r in res["rows"]]
    F = [r["normalForce"] for r in res["rows"]]
    ax.plot([0] + t, [0] + F, "ko-")
    for ti, Fi, r in zip(t, F, res["rows"]):
        ax.annotate("%d active" % r["activeFaces"], (ti, Fi), textcoords="offset points",
                    xytext=(5, 5), fontsize=8)
    # the multiplier force of each update, spread over its step
    for t, Fj in sorted(res["forces"].items()):
        tt = float(t) - 1 + np.arange(Fj.size) / max(Fj.size - 1, 1)
        ax.plot(tt, Fj, ".-", color="C1", ms=3, lw=0.8,
                label="sum lambda |S| per update" if t == HALF else None)
    ax.set_xlabel("load step (time); updates spread over the step")
    ax.set_ylabel("normal force on %s [N]" % res["slave"])
    ax.set_title("force: load, half, lifted off")
    ax.plot([], [], "ko-", label="F_N of the converged step")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = axes[2]
    if res["histories"]:
        cmap = plt.get_cmap("viridis")
        for t, ls in ((LIFTED, "--"), (HALF, "-")):
            sep = res["histories"].get(t, [])
            xs = [s[0] for s in sep]
            for (x, _, lam, _) in sep:
                c = ("0.6" if t == LIFTED else
                     cmap((x - min(xs)) / max(max(xs) - min(xs), 1e-30)))
                # zero has no place on a log axis: an x at the bottom marks it
                k = int(np.argmax(lam == 0))
                ax.semilogy(np.arange(k), lam[:k] / 1e6, ls, marker="o", ms=3, color=c)
                ax.plot([k - 1, k], [lam[k - 1] / 1e6, 1e-3], ":", color=c, lw=0.8)
                ax.plot([k], [1e-3], "x", color=c)
            ax.plot([], [], ls, color="C0" if t == HALF else "0.6",
                    label="faces separating at t = %s (%d%s)"
                    % (t, len(sep), ", colour: x" if t == HALF else ""))
        ax.plot([], [], "kx", label="multiplier zero")
        ax.set_ylim(1e-3, 1e4)
        ax.legend(fontsize=7)
        ax.set_title("multipliers of the faces that separate")
    else:
        ax.text(0.5, 0.5, "%s stores no multipliers" % res["method"], ha="center",
                transform=ax.transAxes)
    ax.set_xlabel("multiplier update in the step")
    ax.set_ylabel("multiplier [MPa]")
    ax.grid(alpha=0.3)
    fig.suptitle("hertzCylinder -unload, %s" % res["method"])
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "hertzUnload.png", [
        ("--estar", dict(choices=("both", "block"), default="both",
                         help="E* of both bodies (default) or of the block alone"))])
    res = compare(args.case, args.estar)
    print("hertzCylinder -unload: method %s, slave %s" % (res["method"], res["slave"]))
    print("%6s %14s %8s %6s %10s" % ("time", "F_N [N]", "active", "corr", "updates"))
    for r in res["rows"]:
        print("%6g %14.6g %8d %6d %10d" % (r["time"], r["normalForce"], r["activeFaces"],
                                           r["outerCorrectors"], r.get("multiplierUpdates", 0)))
    for key, t in (("loaded", LOADED), ("half", HALF)):
        r = res[key]
        print("  t = %s: P' = %.6g N/m, Hertz a = %.4g mm, p0 = %.5g MPa; numerical a = %.4g mm,"
              " max p = %.5g MPa" % (t, r["P"], r["aH"] * 1e3, r["p0H"] / 1e6, r["aNum"] * 1e3,
                                     max(r["p"]) / 1e6))
    print("  t = 3: lift %.4g m, max |g - (g0 + lift)| = %.3g m over %d faces in reach,"
          " max |sigma| = %.3g Pa" % (res["lift"], res["gErr"], res["nInRange"], res["sErr"]))
    for t, sep in sorted(res["histories"].items()):
        print("  faces separating at t = %s: %d" % (t, len(sep)))
        for (x, _, lam, _) in sep:
            print("    x = %7.4f mm: %s MPa" % (x * 1e3, " ".join("%.3g" % (v / 1e6) for v in lam)))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
