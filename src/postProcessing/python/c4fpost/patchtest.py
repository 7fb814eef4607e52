"""What the contact patch tests share (tutorials/contactPatchTest in 2D and
contactPatchTest3D): a column of two blocks, height L, pressed together by
Delta across a non-matching interface. The exact state is a uniform normal
stress sigma = -E Delta / L (E the column's modulus) with the contact
pressure |sigma| on every face; with the penalty method the penalty spring
is in series with the column, and the state is uniform too, with
    sigma_pen = -E Delta / (L + E/eps_N),    eps_N = penaltyScale K / h
(K = 2 mu + lambda, h = V/A of the slave face cells), so every cell's
relative error is the offset 1 - L/(L + E/eps_N).

With the constitutive interface law p = cN (-g)^n in series the state is
uniform as well: |sigma| L/E + (|sigma|/cN)^(1/n) = Delta
(constitutive_stress), and every slave face penetrates by (|sigma|/cN)^(1/n).

With the barrier (p = -kappa b'(d), the clamped log barrier of range dhat)
the bodies stay apart by a uniform gap d, so the column is shortened by
Delta + d (the applied displacement is the total from the touching
configuration): |sigma| L/E = Delta + d with p(d) = |sigma|
(barrier_solution).

The validation scripts keep the constants of their case and the tolerances,
with where the tolerances come from; this module reads the fields, builds
the checks from those numbers, and prints and plots what the two have in
common. A check is a dict as c4fpost.report describes.

Which of these answers a contact method gives is one of its traits
(`answer` of solidContactFoam -listMethods, c4fpost.methods): a new method
is checked by the answer it declares, with no list here.
"""
import math
import os
import re

import numpy as np

from c4fpost import contactreport, foamio, methods

# symmTensor order in OpenFOAM files: xx xy xz yy yz zz
_SYMM = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))

def method_check(method):
    """How a patch test checks `method`, from its traits' answer:
    dict(kind=...) with kind exact, penalty (then scale, the entry of the
    penalty scale: eps = scale K/h), constitutive or barrier."""
    answer = methods.get(method).answer
    if answer == "penalty":
        return dict(kind="penalty", scale="penaltyScale")
    return dict(kind=answer)


def constitutive_stress(modulus, delta, length, cN, n):
    """|sigma| of a column (modulus, length) shortened by delta with the
    interface law p = cN (-g)^n in series:
        modulus (delta - (sigma/cN)^(1/n))/length = sigma,
    by bisection on (0, modulus delta/length] (the left side falls and the
    right rises, so the root is unique)."""
    lo, hi = 0.0, modulus * delta / length
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if modulus * (delta - (mid / cN) ** (1.0 / n)) / length > mid:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def barrier_pressure(d, dhat, kappa):
    """The barrier's pressure p = -kappa b'(d) = kappa (dhat - d)(dhat/d - 1
    - 2 ln(d/dhat)) for 0 < d < dhat, 0 beyond (src/kernels/contact/
    barrierLaw)."""
    if d >= dhat:
        return 0.0
    return kappa * (dhat - d) * (dhat / d - 1.0 - 2.0 * math.log(d / dhat))


def barrier_solution(modulus, delta, length, dhat, kappa):
    """(|sigma|, d) of a column (modulus, length) shortened by delta with the
    barrier in series, the gap d held open: modulus (delta + d)/length =
    p(d) = |sigma|, by bisection on (0, dhat) (p falls from infinity to 0,
    the left side rises: the root is unique)."""
    lo, hi = 0.0, dhat
    for _ in range(300):
        mid = 0.5 * (lo + hi)
        if barrier_pressure(mid, dhat, kappa) > modulus * (delta + mid) / length:
            lo = mid
        else:
            hi = mid
    d = 0.5 * (lo + hi)
    return modulus * (delta + d) / length, d


def stress_tensor(case, time, ncells):
    """sigma of every cell at `time`, an (ncells, 3, 3) array."""
    s6 = foamio.read_internal(os.path.join(case, time, "sigma"), ncells)
    S = np.empty((ncells, 3, 3))
    for k, (i, j) in enumerate(_SYMM):
        S[:, i, j] = S[:, j, i] = s6[:, k]
    return S


def slave_patch(case, time, patches):
    """The one of `patches` whose entry in the D written at `time` says
    master no (false): Allrun -slave may have swapped the roles."""
    text = open(os.path.join(case, time, "D")).read()
    for patch in patches:
        m = re.search(r"^\s*%s\s*\{([^}]*)\}" % patch, text, flags=re.M)
        if m and re.search(r"\bmaster\s+(no|false|off|0)\s*;", m.group(1)):
            return patch
    raise RuntimeError("no slave patch among %s in %s/D" % (list(patches), time))


def uniformity(s, exact):
    """(max |s - exact|/|exact|, (max s - min s)/|exact|) over the cells."""
    rel = np.abs(s - exact) / abs(exact)
    return float(rel.max()), float((s.max() - s.min()) / abs(exact))


def set_passed(checks):
    """passed = error <= tolerance, where a check does not say already."""
    for c in checks:
        c.setdefault("passed", bool(c["error"] <= c["tolerance"]))


class PatchTest:
    """One patch test: `name` prefixes the check names; the contact pair
    `slave` / `master`; the column's `delta` and `length` (L); `exact_tol`,
    the tolerance of the exact state (a fraction of |sigma_exact|), and
    `offset_tol`, that of the penalty offset (a fraction of the offset)."""

    def __init__(self, name, slave, master, delta, length, exact_tol, offset_tol):
        self.name = name
        self.slave = slave
        self.master = master
        self.delta = delta
        self.length = length
        self.exact_tol = exact_tol
        self.offset_tol = offset_tol

    def slave_geometry(self, case, V):
        """Face centres Cf and areas |Sf| of the slave patch, its face cells
        and h = V/A of those cells."""
        Cf, Sf = foamio.patch_geometry(case, self.slave)
        area = np.linalg.norm(Sf, axis=1)
        cells = foamio.patch_face_cells(case, self.slave)
        return Cf, area, cells, V[cells] / area

    def stress_checks(self, case, res, comp, penalty, modulus, K, h, method=None,
                      scale="penaltyScale", stress=None):
        """The checks on the normal stress `comp` (syy, szz) of a column of
        the given modulus, from res's exact, maxRel and spread: with
        `penalty`, the offset that eps_N predicts (the entry `scale` of
        the method's coefficients, c4fpost.methods.coeff: 0/D's or the
        class's default; the mean over the slave cells' h) and the
        uniformity; otherwise the exact
        state. With `stress` (every cell's `comp`, for a method whose answer
        is the penalty's, perturbedLagrange) the penalty state is checked as
        an exact one: max |stress - sigma_pen|/|sigma_pen| and the
        uniformity within exact_tol. Adds predicted and offset (with the
        penalty also penaltyScale and eps) to res. Returns (checks,
        predicted stress, tolerance of the contact force)."""
        maxRel, spread = res["maxRel"], res["spread"]
        units = "fraction of |sigma_exact|"
        if not penalty:
            predicted = res["exact"]
            res.update(predicted=predicted, offset=0.0)
            return [dict(name="%s/%s_max_rel_error" % (self.name, comp), value=maxRel,
                         reference=0.0, error=maxRel, tolerance=self.exact_tol,
                         units=units)], predicted, self.exact_tol
        s = methods.coeff(case, method, scale)
        eps = s * K / h
        if np.ptp(eps) > 1e-12 * eps.max():
            print("NOTE: the slave cells' h = V/A varies (%g .. %g); using the mean"
                  % (h.min(), h.max()))
        eps = float(eps.mean())
        predicted = -modulus * self.delta / (self.length + modulus / eps)
        offset = 1.0 - self.length / (self.length + modulus / eps)
        res.update(penaltyScale=s, eps=eps, predicted=predicted, offset=offset)
        uniform = dict(name="%s/%s_uniformity" % (self.name, comp), value=spread, reference=0.0,
                       error=spread, tolerance=self.exact_tol, units=units)
        if stress is not None:
            rel = float(np.abs(np.asarray(stress) - predicted).max() / abs(predicted))
            res.update(penaltyRel=rel)
            return [dict(name="%s/%s_equals_penalty" % (self.name, comp), value=rel,
                         reference=0.0, error=rel, tolerance=self.exact_tol,
                         units="fraction of |sigma_pen|"), uniform], predicted, self.exact_tol
        # The offset to offset_tol of itself, but never finer than the
        # exact state's tolerance: a stiff slave's penalty (eps = s K/h of
        # the slave) leaves an offset of 2.5e-5, whose 1e-3 is below what
        # the outer tolerance resolves
        tol = max(self.offset_tol * offset, self.exact_tol)
        checks = [
            dict(name="%s/%s_penalty_offset" % (self.name, comp), value=maxRel,
                 reference=offset, error=abs(maxRel - offset), tolerance=tol, units=units),
            uniform,
        ]
        return checks, predicted, tol

    def constitutive_checks(self, case, time, res, comp, stress, modulus, nfaces,
                            method="constitutiveLaw"):
        """The checks of a column with the interface law p = cN (-g)^n (cN
        and n of <method>Coeffs in 0/D): the normal stress `comp` (the cells'
        `stress`) equals constitutive_stress everywhere and is uniform, and
        every slave face's penetration -g (contactGap) equals
        (|sigma|/cN)^(1/n) with sigma the computed mean stress; all three to
        exact_tol (the law is exact and the state uniform; what is left is
        the outer correctors' residual). Adds predicted, offset, cN, n,
        maxRel, penetration and penetrationRef to res; returns (checks,
        predicted stress, tolerance of the contact force)."""
        cN, n = methods.coeff(case, method, "cN"), methods.coeff(case, method, "n")
        predicted = -constitutive_stress(modulus, self.delta, self.length, cN, n)
        maxRel, spread = uniformity(stress, predicted)
        gap = foamio.read_patch(os.path.join(case, time, "contactGap"), self.slave, nfaces)
        pen = -np.asarray(gap)
        ref = (abs(float(stress.mean())) / cN) ** (1.0 / n)
        perr = float(np.abs(pen - ref).max() / ref)
        res.update(predicted=predicted, offset=1.0 - predicted / res["exact"], cN=cN, n=n,
                   maxRel=maxRel, spread=spread, penetration=float(pen.mean()),
                   penetrationRef=ref)
        units = "fraction of |sigma_pred|"
        checks = [
            dict(name="%s/%s_constitutive_law" % (self.name, comp), value=maxRel,
                 reference=0.0, error=maxRel, tolerance=self.exact_tol, units=units),
            dict(name="%s/%s_uniformity" % (self.name, comp), value=spread, reference=0.0,
                 error=spread, tolerance=self.exact_tol, units=units),
            dict(name="%s/penetration_law" % self.name, value=float(pen.mean()), reference=ref,
                 error=perr, tolerance=self.exact_tol, units="fraction of (sigma/cN)^(1/n)"),
        ]
        return checks, predicted, self.exact_tol

    def barrier_checks(self, case, time, res, comp, stress, modulus, nfaces, h,
                       method="barrier"):
        """The checks of a column with the barrier in series: dhat of
        <method>Coeffs in 0/D (or dhatScale (its default from the solver) times the
        largest slave h), kappa the field barrierStiffness written on the
        slave (uniform: the kappa the step converged with, doublings
        included); the normal stress `comp` (the cells' `stress`) equals
        -|sigma| of barrier_solution everywhere and is uniform, and every
        slave face's gap (contactGap) equals its d; all to exact_tol (the
        law is exact and the state uniform; the gap to exact_tol of
        max(d, 1e-3 Delta): it carries the residual's error of D, about
        1e-11 m; measured 1.6e-8 of d = 1.2e-3 Delta). Adds predicted, offset, dhat, kappa, gap and gapRef to res;
        returns (checks, predicted stress, tolerance of the contact
        force)."""
        try:
            dhat = methods.coeff(case, method, "dhat")
        except (KeyError, AttributeError, TypeError, ValueError):
            dhat = methods.coeff(case, method, "dhatScale") * float(np.max(h))
        kappa = np.asarray(foamio.read_patch(os.path.join(case, time, "barrierStiffness"),
                                             self.slave, nfaces))
        # kappa = s K/h: uniform up to the round-off of h = V/A, about 1e-11
        # on a rotated mesh (its points are written with 12 digits)
        if np.ptp(kappa) > 1e-9 * kappa.max():
            raise RuntimeError("barrierStiffness is not uniform on %s: %g .. %g"
                               % (self.slave, kappa.min(), kappa.max()))
        kappa = float(kappa.mean())
        sigma, d = barrier_solution(modulus, self.delta, self.length, dhat, kappa)
        predicted = -sigma
        maxRel, spread = uniformity(stress, predicted)
        gap = np.asarray(foamio.read_patch(os.path.join(case, time, "contactGap"), self.slave,
                                           nfaces))
        # The gap to exact_tol of itself, or of 1e-3 Delta where it is
        # smaller: the outer residual (1e-9) leaves about 1e-11 m in D, which
        # a gap of 2e-7 m (kappa doubled from kappaScale 0.01) would read as
        # 6.5e-6 of itself
        gscale = max(d, 1e-3 * self.delta)
        gerr = float(np.abs(gap - d).max() / gscale)
        res.update(predicted=predicted, offset=1.0 - predicted / res["exact"], dhat=dhat,
                   kappa=kappa, maxRel=maxRel, spread=spread, gap=float(gap.mean()), gapRef=d)
        units = "fraction of |sigma_pred|"
        checks = [
            dict(name="%s/%s_barrier_law" % (self.name, comp), value=maxRel,
                 reference=0.0, error=maxRel, tolerance=self.exact_tol, units=units),
            dict(name="%s/%s_uniformity" % (self.name, comp), value=spread, reference=0.0,
                 error=spread, tolerance=self.exact_tol, units=units),
            dict(name="%s/gap_barrier_law" % self.name, value=float(gap.mean()), reference=d,
                 error=gerr, tolerance=self.exact_tol,
                 units="fraction of max(d, 1e-3 Delta)"),
            dict(name="%s/gap_open" % self.name, value=float(gap.min()), reference=0.0,
                 error=0.0, tolerance=0.0, units="m", passed=bool(gap.min() > 0)),
        ]
        return checks, predicted, self.exact_tol

    def force_checks(self, case, time, res, area, predicted, tol):
        """The total normal force on the slave patch, sum_f p_f |Sf_f|, and
        the last normalForce of its contactReport when there is one, against
        |predicted| times the patch area. Adds report, F, Fref and slaveP
        (the faces' contactPressure) to res; returns the checks."""
        p = foamio.read_patch(os.path.join(case, time, "contactPressure"), self.slave, area.size)
        F = float(np.sum(p * area))
        Fref = abs(predicted) * float(area.sum())
        checks = [dict(name=self.name + "/contact_force", value=F, reference=Fref,
                       error=abs(F - Fref) / Fref, tolerance=tol, units="N")]
        rep = contactreport.last_row(case, self.slave)
        if rep and "normalForce" in rep:
            Fr = rep["normalForce"]
            checks.append(dict(name=self.name + "/contactReport_normalForce", value=Fr,
                               reference=Fref, error=abs(Fr - Fref) / Fref, tolerance=tol,
                               units="N"))
        res.update(report=rep, F=F, Fref=Fref, slaveP=p.tolist())
        return checks

    def master_pressure(self, case, time, res, R=None):
        """Adds the master patch's face centres' x (x' = R^T x with R) and
        contactPressure to res as masterX and masterP."""
        Cf, _ = foamio.patch_geometry(case, self.master)
        p = foamio.read_patch(os.path.join(case, time, "contactPressure"), self.master, len(Cf))
        res.update(masterX=(Cf if R is None else Cf @ R)[:, 0].tolist(), masterP=p.tolist())

    def print_force(self, res):
        print("  contact force on %s: %.9g N (expected %.9g N)"
              % (self.slave, res["F"], res["Fref"]))
        if res["report"] is None:
            print("  (no postProcessing/contactReport/*/%s.dat)" % self.slave)



# --------------------------------------------------------------------------
# The 3D patch tests' case readers (contactPatchTest3D, contactPatchTestTets)

def rotation_from_mesh(case, top, symmetry_x):
    """R with columns R e_x, R e_y, R e_z of a (possibly turned) box, from
    the patch normals: R e_z the outward normal of `top`, R e_x that of
    `symmetry_x` negated, each averaged over the patch's faces."""
    def unit_normal(patch):
        _, Sf = foamio.patch_geometry(case, patch)
        n = Sf.sum(axis=0)
        return n / np.linalg.norm(n)
    ez = unit_normal(top)
    ex = -unit_normal(symmetry_x)
    ex -= ez * float(ex @ ez)
    ex /= np.linalg.norm(ex)
    return np.column_stack((ex, np.cross(ez, ex), ez))


def contact_variant(case, slave):
    """(contact, method): contact is False when the slave patch's entry of
    0/D is not a solidContact (Allrun -noContact); method is its `method`
    (None without contact)."""
    text = foamio.strip(open(os.path.join(case, "0", "D")).read())
    entry = foamio.sub_dict(foamio.sub_dict(text, "boundaryField"), slave)
    contact = foamio.entry(entry, "type") == "solidContact"
    return contact, (foamio.entry(entry, "method") if contact else None)


def top_displacement(case):
    """topDisplacement of 0/D (the Allrun's prescribed top displacement)."""
    text = foamio.strip_comments(open(os.path.join(case, "0", "D")).read())
    m = re.search(r"^\s*topDisplacement\s+\(([^)]*)\)\s*;", text, flags=re.M)
    return np.array(m.group(1).split(), float)


def solid_controls(case):
    """(tolerance, nCorrectors) of solidMechanics in system/fvSolution."""
    text = foamio.strip_comments(open(os.path.join(case, "system", "fvSolution")).read())
    body = re.search(r"\bsolidMechanics\s*\{([^}]*)\}", text).group(1)
    tol = float(re.search(r"\btolerance\s+([^\s;]+)\s*;", body).group(1))
    ncorr = int(re.search(r"\bnCorrectors\s+([^\s;]+)\s*;", body).group(1))
    return tol, ncorr


def last_step(case):
    """The solver's last step summary from log.solidContactFoam:
    dict(time, correctors, residual, converged, contact) or None."""
    path = os.path.join(case, "log.solidContactFoam")
    if not os.path.exists(path):
        return None
    steps = re.findall(r"^Time = (\S+)\s+correctors = (\d+)\s+residual = (\S+)(.*)$",
                       open(path).read(), flags=re.M)
    if not steps:
        return None
    t, n, r, rest = steps[-1]
    return dict(time=t, correctors=int(n), residual=float(r),
                converged="NOT CONVERGED" not in rest, contact=rest.strip())


def convergence_check(case, name):
    """The check `name`/converged: the last step converged, its outer
    residual below solidMechanics' tolerance. (check, step, nCorrectors)."""
    tol, ncorr = solid_controls(case)
    step = last_step(case)
    if step is None:
        return dict(name=name + "/converged", value=float("inf"), reference=0.0,
                    error=float("inf"), tolerance=tol, passed=False,
                    units="residual (no step summary in log.solidContactFoam)"), step, ncorr
    r = step["residual"]
    return dict(name=name + "/converged", value=r, reference=0.0, error=r, tolerance=tol,
                passed=bool(step["converged"] and r < tol),
                units="outer residual of time %s after %d correctors"
                % (step["time"], step["correctors"])), step, ncorr


def print_constants(res, stress):
    """The material and the exact value of `stress` (its printed name)."""
    print("  E = %g Pa, nu = %g, K = 2mu + lambda = %g Pa; exact %s = %g Pa"
          % (res["E"], res["nu"], res["K"], stress, res["exact"]))


def print_stress(res, stress, penalty):
    """The penalty prediction (with `penalty`) and the error and spread of
    `stress` (its printed name) over the cells."""
    if penalty:
        print("  penalty: scale %g, h = V/A = %g m, eps_N = %g Pa/m -> sigma = %.9g Pa,"
              " offset %.6g" % (res["penaltyScale"], np.mean(res["h"]), res["eps"],
                                res["predicted"], res["offset"]))
    if "penaltyRel" in res:
        print("  max |%s - sigma_pen|/|sigma_pen| = %.4g" % (stress, res["penaltyRel"]))
    print("  max |%s - exact|/|exact| = %.4g, (max - min)/|exact| = %.4g"
          % (stress, res["maxRel"], res["spread"]))


def pyplot():
    """matplotlib.pyplot with the Agg backend (no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def plot_centre_line(ax, res, penalty, stress, height, label, interface, xlabel, ylabel,
                     predicted="penalty prediction"):
    """The stress of the cells of the vertical centre line (`stress`, at
    `height`) as a fraction of |sigma_exact|, the exact stress and, with
    `penalty`, the predicted one (labelled `predicted`), and the interface
    (a dotted line at `interface`)."""
    ax.plot(np.array(stress) / abs(res["exact"]), height, "o", label=label)
    ax.axvline(-1.0, color="k", lw=1, label="exact (gap closed)")
    if penalty:
        ax.axvline(-abs(res["predicted"]) / abs(res["exact"]), color="C3", ls="--", lw=1,
                   label=predicted)
    ax.axhline(interface, color="0.6", ls=":", lw=1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title("stress along the vertical centre line")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)


def mark_pressure(ax, res, penalty, predicted="penalty prediction"):
    """On an axis of p/|sigma_exact|: the exact contact pressure and, with
    `penalty`, the predicted one (labelled `predicted`) as horizontal
    lines."""
    ax.axhline(1.0, color="k", lw=1, label="exact")
    if penalty:
        ax.axhline(abs(res["predicted"]) / abs(res["exact"]), color="C3", ls="--", lw=1,
                   label=predicted)


def save(fig, axes, png):
    for ax in axes:
        ax.ticklabel_format(useOffset=False)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
