"""selfContactStrip: self-contact (issue 23), a C-shaped strip whose
upper arm, pressed down, closes the slot onto the lower arm; the strip's
free faces are one patch, its own shadowPatch. compareSelfContact.py's
checks for every method of the selection table: the force across the
slot at every step against CalculiX's (roof and floor as two surfaces
there), within 2 % of the load on the arm (measured 0.1 to 1.1 %); no
active face while the slot is open, none away from the arm's end (the
exclusions of c4f::search::SelfContactFilter); the contact zone's start
within two cells of CalculiX's. Then parallel = serial and a restart in
the middle of the load."""

import pytest

import harness
import runs
from c4fpost import contactreport, methods

METHODS = list(methods.table())
PATCH = "strip"


def group(method):
    return pytest.mark.xdist_group("selfContactStrip_" + method)


def forces_equal(ck, case, ref, name, tol, what):
    """The normal force of every time equal to ref's to tol of the largest
    (open steps carry none)."""
    rows = {x["time"]: x["normalForce"] for x in contactreport.rows(case, PATCH)}
    refs = {x["time"]: x["normalForce"] for x in contactreport.rows(ref, PATCH)}
    ck.add(name + "/same_steps", sorted(rows) == sorted(refs),
           note="(%d and %d steps)" % (len(rows), len(refs)))
    scale = max([abs(f) for f in refs.values()] + [1e-30])
    for t in sorted(set(rows) & set(refs)):
        err = abs(rows[t] - refs[t]) / scale
        ck.add("%s/force_t%g_%s" % (name, t, what), err <= tol, rows[t], refs[t], err, tol)


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m)) for m in METHODS])
def test_self_contact_strip_against_calculix(method):
    ck = harness.Checks()
    r = runs.self_contact_strip(method)
    ck.run(r, "selfContactStrip_" + method)
    ck.verify()


@pytest.mark.xdist_group("selfContactStrip_" + runs.LM)
def test_self_contact_strip_parallel_equals_serial():
    """Allrun -parallel: scotch's cut puts the strip on both processors;
    each gathers the faces its own can reach, its own among them (the
    exclusions then by merged reference points across processors). The
    force of every step equal to the serial run's to 1e-6 of the largest."""
    ck = harness.Checks()
    name = "selfContactStrip_%s_parallel" % runs.LM
    ref = harness.need(runs.self_contact_strip(runs.LM), "selfContactStrip_" + runs.LM)
    r = runs.self_contact_strip(runs.LM, parallel=True)
    if ck.run(r, name):
        forces_equal(ck, r["case"], ref, name, 1e-6, "equals_serial")
    ck.verify()


@pytest.mark.xdist_group("selfContactStrip_" + runs.LM)
def test_self_contact_strip_restart_mid_load():
    """The LM run restarted from t = 4 (times 5 and 6 removed, the arm's
    end on the lower arm) redoes the last two steps to the same force: the
    self-contact state is the slave's, written with D."""
    ck = harness.Checks()
    name = "selfContactStrip_%s_restart" % runs.LM
    ref = harness.need(runs.self_contact_strip(runs.LM), "selfContactStrip_" + runs.LM)
    harness.restart_mid_load(ck, ref, name, PATCH, "4", ("5", "6"))
    ck.verify()


def report_rows(case, patch):
    return {x["time"]: x for x in contactreport.rows(case, patch)}


@pytest.mark.parametrize("friction", ["frictionless", "coulomb"])
@pytest.mark.xdist_group("selfContactStrip_twoPatches")
def test_self_contact_equals_two_patches(friction):
    """The strip as one self-contact patch and as the two-patch pair
    roof/floor (the roof the slave in both: the one-pass choice): the same
    normal and tangential force at every step, to 1e-3 of the largest
    (measured 6e-5 frictionless: the search distance and the patch-wide
    h of the two models differ). With Coulomb friction (mu 0.3) the arm's
    end slides along the lower arm as it lands: F_T = mu F_N where it
    slips."""
    ck = harness.Checks()
    name = "selfContactStrip_%s_%s_vs_twoPatches" % (runs.LM, friction)
    fr = None if friction == "frictionless" else friction
    one = runs.self_contact_strip(runs.LM, friction=fr)
    two = runs.self_contact_strip(runs.LM, friction=fr, two_patches=True)
    for r, what in ((one, "self"), (two, "twoPatches")):
        ck.add("%s/%s_Allrun" % (name, what), r["rc"] == 0,
               note="rc=%d, see %s" % (r["rc"], r["case"]))
        if r["rc"] == 0:
            ck.steps_converged(r["case"], "%s/%s" % (name, what))
    if one["rc"] == 0 and two["rc"] == 0:
        a, b = report_rows(one["case"], PATCH), report_rows(two["case"], "roof")
        ck.add(name + "/same_steps", sorted(a) == sorted(b),
               note="(%d and %d steps)" % (len(a), len(b)))
        scale = max([abs(x["normalForce"]) for x in b.values()] + [1e-30])
        for t in sorted(set(a) & set(b)):
            for col in ("normalForce", "tangentialForce"):
                err = abs(a[t][col] - b[t][col]) / scale
                ck.add("%s/%s_t%g" % (name, col, t), err <= 1e-3, a[t][col], b[t][col],
                       err, 1e-3)
    ck.verify()


FINITE = [m for m in METHODS if methods.table()[m].finite_strain]


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m)) for m in FINITE])
def test_self_contact_strip_finite_strain(method):
    """Allrun -finiteStrain (nonlinearGeometry yes, St Venant-Kirchhoff)
    against CalculiX under NLGEOM (validation/calculix-nlgeom.csv, the
    pressure a dead load as the tutorial's): the same checks, for every
    method with finiteStrain=yes."""
    ck = harness.Checks()
    r = runs.self_contact_strip(method, finite=True)
    ck.run(r, "selfContactStrip_%s_finiteStrain" % method)
    ck.verify()


@pytest.mark.xdist_group("selfContactStrip_" + runs.LM)
def test_secant_through_active_set_changes():
    """andersonActiveSetChange secant (docs/solver.md): on an active-set
    change Anderson keeps the last iterate and steps by the secant through
    the change, where the default restart takes two plain steps. On the
    strip, whose faces close along the slot one after another over the
    steps, the forces of every step are the default run's to 1e-6 of the
    largest (both stop at the tolerance) and it takes fewer correctors:
    484 against 530 (2026-12-07); the same count fails, so a secant that
    does nothing is caught."""
    ck = harness.Checks()
    name = "selfContactStrip_%s_secant" % runs.LM
    ref = harness.need(runs.self_contact_strip(runs.LM), "selfContactStrip_" + runs.LM)
    r = harness.tutorial_run("selfContactStrip", name, ["-method", runs.LM],
                             controls="andersonActiveSetChange secant;")
    if ck.run(r, name):
        forces_equal(ck, r["case"], ref, name, 1e-6, "equals_restart")
        n, n0 = harness.total_correctors(r["case"]), harness.total_correctors(ref)
        ck.add(name + "/fewer_correctors", n < n0, n, n0, n - n0, -1)
    ck.verify()
