"""rigidSphere: Hertz with a RIGID sphere (a rigidSurface, no mesh) on an
elastic block, quarter model, five load steps at -refine 1:
compareRigidSphere.py's checks (F against Hertz's F(delta) within 2 % at
every step; at the last step the contact radius within one face and the
peak pressure within 4 %, hertzSphere's tolerances) for the reference
exact method and the plain penalty, and the sphere given as a
triangulated surface (-surface triSurface, 20000 facets of 0.5 mm) against
the analytic one: F of every step within 0.5 % (the facets' sag is 0.3 %
of the first step's indentation at the worst, 1.5 times that in F)."""
import os
import re
import shutil

import pytest

import harness
import runs
from c4fpost import contactreport

TRI_TOL = 0.005


@pytest.mark.xdist_group("rigidSphere")
@pytest.mark.parametrize("method", [runs.LM, runs.PENALTY])
def test_rigid_sphere_hertz(method):
    ck = harness.Checks()
    r = runs.rigid_sphere(method)
    ck.run(r, "rigidSphere_" + method)
    ck.verify()


@pytest.mark.xdist_group("rigidSphere")
def test_rigid_sphere_trisurface_equals_analytic():
    ck = harness.Checks()
    name = "rigidSphere_%s_triSurface" % runs.LM
    r = runs.rigid_sphere(runs.LM, "triSurface")
    if ck.run(r, name):
        ref = harness.need(runs.rigid_sphere(runs.LM), "rigidSphere_" + runs.LM)
        rows = {x["time"]: x for x in contactreport.rows(r["case"], "blockTop")}
        refs = {x["time"]: x for x in contactreport.rows(ref, "blockTop")}
        ck.add(name + "/same_steps", sorted(rows) == sorted(refs),
               note="(%d and %d steps)" % (len(rows), len(refs)))
        for t in sorted(set(rows) & set(refs)):
            f, f0 = rows[t]["normalForce"], refs[t]["normalForce"]
            err = abs(f - f0) / abs(f0)
            ck.add("%s/force_t%g_equals_analytic" % (name, t), err <= TRI_TOL, f, f0, err,
                   TRI_TOL)
    ck.verify()


@pytest.mark.xdist_group("rigidSphere")
def test_rigid_sphere_restart_mid_load():
    """The LM run restarted from t = 3 (times 4 and 5 removed) redoes the
    last two steps to the same force: the contact state is written with D
    and the tool's position is a function of time, so nothing is lost.
    1e-6: the force's change allowed at convergence is the outer
    tolerance's, and the two runs take the same correctors from the same
    written state (measured identical to the printed digits)."""
    ck = harness.Checks()
    name = "rigidSphere_%s_restart" % runs.LM
    ref = harness.need(runs.rigid_sphere(runs.LM), "rigidSphere_" + runs.LM)

    def trim(case):
        for t in ("4", "5"):
            shutil.rmtree(os.path.join(case, t), ignore_errors=True)
        shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)

    r = harness.restart_run(ref, end_time="5", suffix="_restart3", prepare=trim)
    steps = re.findall(r"^Time = (\S+)\s+correctors", r["out"], flags=re.M)
    ok = r["rc"] == 0 and steps == ["4", "5"]
    ck.add(name + "/run", ok, note="rc=%d, steps %s, see %s" % (r["rc"], steps, r["case"]))
    if ok:
        rows = {x["time"]: x for x in contactreport.rows(r["case"], "blockTop")}
        refs = {x["time"]: x for x in contactreport.rows(ref, "blockTop")}
        for t in (4.0, 5.0):
            f, f0 = rows[t]["normalForce"], refs[t]["normalForce"]
            err = abs(f - f0) / abs(f0)
            ck.add("%s/force_t%g_equals_uninterrupted" % (name, t), err <= 1e-6, f, f0,
                   err, 1e-6)
    ck.verify()
