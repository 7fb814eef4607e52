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
import os
import re
import shutil

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

    def trim(case):
        for t in ("5", "6"):
            shutil.rmtree(os.path.join(case, t), ignore_errors=True)
        shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)

    r = harness.restart_run(ref, end_time="6", suffix="_restart4", prepare=trim)
    steps = re.findall(r"^Time = (\S+)\s+correctors", r["out"], flags=re.M)
    ok = r["rc"] == 0 and steps == ["5", "6"]
    ck.add(name + "/run", ok, note="rc=%d, steps %s, see %s" % (r["rc"], steps, r["case"]))
    if ok:
        rows = {x["time"]: x for x in contactreport.rows(r["case"], PATCH)}
        refs = {x["time"]: x for x in contactreport.rows(ref, PATCH)}
        for t in (5.0, 6.0):
            f, f0 = rows[t]["normalForce"], refs[t]["normalForce"]
            err = abs(f - f0) / abs(f0)
            ck.add("%s/force_t%g_equals_uninterrupted" % (name, t), err <= 1e-6, f, f0,
                   err, 1e-6)
    ck.verify()
