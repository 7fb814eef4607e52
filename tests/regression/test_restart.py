"""Restarts: a finished run continued from its written time must pick up
its contact (and friction, and barrier) state and continue converged.
Each test shares its xdist group with the run it restarts."""
import os
import re
import shutil

import numpy as np
import pytest

import harness
import runs
from c4fpost import contactreport, foamio
from harness import methods_where

LM = runs.LM


def restart_reproduces(ck, finished, name, max_correctors=5, slave="cylinderContact"):
    """Continue a finished one-step run for a second step at the same load:
    with the contact state written with the time (active set, pressure,
    master force, direction-mixed coefficients) it must start converged.
    2 correctors is what it takes (the first solve's residual is the
    written precision's, 6e-9 here); 5 leaves margin, a lost state takes
    hundreds. The slave's written contactTraction (the output field) at
    the new time is the finished one's to 1e-5 of its largest magnitude
    (measured up to 5e-7, augmentedLagrange's reconstructed restart; a lost
    traction is 1): a step that converges in its first corrector writes the traction of
    that solve, not the zero a slave started from before its traction was
    written with the time."""
    r = harness.restart_run(finished)
    steps = re.findall(r"^Time = (\S+)\s+correctors = (\d+).*F_N = (\S+)", r["out"], flags=re.M)
    if r["rc"] or len(steps) != 1 or steps[0][0] != "2":
        ck.add(name + "/run", False, note="rc=%d, steps %s, see %s" % (r["rc"], steps, r["case"]))
        return False
    first = re.findall(r"F_N = (\S+)",
                       open(os.path.join(finished, "log.solidContactFoam")).read())[-1]
    ncorr, f1, f2 = int(steps[0][1]), float(first), float(steps[0][2])
    ck.add(name + "/correctors", ncorr <= max_correctors, ncorr, 2, ncorr - 2,
           max_correctors - 2)
    err = abs(f2 - f1) / abs(f1)
    ck.add(name + "/normal_force_equals_step_1", err <= 1e-6, f2, f1, err, 1e-6)
    n = foamio.patch_face_cells(finished, slave).size
    t1 = np.asarray(foamio.read_patch(
        os.path.join(finished, foamio.latest_time(finished), "contactTraction"), slave, n))
    t2 = np.asarray(foamio.read_patch(
        os.path.join(r["case"], "2", "contactTraction"), slave, n))
    scale = float(np.abs(t1).max()) or 1.0
    err = float(np.abs(t2 - t1).max()) / scale if t1.shape == t2.shape else float("inf")
    ck.add(name + "/slave_traction_written", err <= 1e-5, err, 0.0, err, 1e-5)
    return True


def barrier_kappa_carried(ck, finished, name, patch, ref=None):
    """The barrier's per-face kappa (barrierStiffness, the method's state
    in the slave's entry of D) survives: the restart of `finished`
    (restart_reproduces, `finished`_restart) ends its step with the
    written kappa, face by face, and no doubling (the gap it starts from
    is the converged one); with `ref`, `finished`'s kappa equals that run's
    (a reconstructed parallel run against the serial one: decomposePar and
    reconstructPar map it face by face). Exact to the 12 written digits:
    tolerance 1e-10."""
    def kappa(case):
        time = foamio.latest_time(case)
        n = foamio.patch_face_cells(case, patch).size
        return time, np.asarray(foamio.read_patch(os.path.join(case, time, "D"), patch, n,
                                                  key="barrierStiffness"))
    restart = finished + "_restart"
    if not os.path.isdir(restart):
        ck.add(name + "/kappa_carried", False, note="no restart case %s" % restart)
        return
    t1, k1 = kappa(finished)
    t2, k2 = kappa(restart)
    err = float(np.abs(k2 - k1).max() / np.abs(k1).max()) if k1.shape == k2.shape else 1.0
    ck.add(name + "/kappa_carried", t2 != t1 and err <= 1e-10, err, 0.0, err, 1e-10)
    row = contactreport.last_row(restart, patch) or {}
    ck.add(name + "/no_kappa_update", row.get("multiplierUpdates") == 0,
           note="(multiplierUpdates %s)" % row.get("multiplierUpdates"))
    if ref is not None:
        _, k0 = kappa(ref)
        err = float(np.abs(k1 - k0).max() / np.abs(k0).max()) if k0.shape == k1.shape else 1.0
        ck.add(name + "/kappa_equals_serial", err <= 1e-10, err, 0.0, err, 1e-10)


@pytest.mark.xdist_group("hertzCylinder_" + LM)
def test_hertzCylinder_restart_starts_converged():
    ck = harness.Checks()
    restart_reproduces(ck, harness.need(runs.hertz(LM)), "hertzCylinderRestart")
    ck.verify()


@pytest.mark.xdist_group("hertzCylinder_augmentedLagrange")
def test_reconstructed_parallel_augmentedLagrange_restart_in_serial():
    """The reconstructed case of the decomposed augmentedLagrange run
    restarted in serial continues its converged step (the multipliers and
    the contact state survive reconstructPar): at most 3 correctors."""
    ck = harness.Checks()
    name, par = runs.hertz_parallel("augmentedLagrange")
    restart_reproduces(ck, harness.need(par, name), "hertzCylinderReconstructedRestart",
                       max_correctors=3)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.xdist_group(
    "hertzCylinder_" + m)) for m in methods_where(answer="barrier")])
def test_reconstructed_parallel_barrier_restart_keeps_kappa(method):
    """The reconstructed case of the decomposed barrier run restarted in
    serial continues its converged step (measured 1 corrector) with the
    kappa reconstructPar mapped, equal to the serial run's."""
    ck = harness.Checks()
    name, par = runs.hertz_parallel(method)
    case = harness.need(par, name)
    tag = "hertzCylinderReconstructedRestart_" + method
    if restart_reproduces(ck, case, tag, max_correctors=3):
        barrier_kappa_carried(ck, case, tag, "cylinderContact",
                              ref=harness.need(runs.hertz(method)))
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.xdist_group(
    "contactPatchTest_" + m)) for m in methods_where(answer="barrier")])
def test_barrier_restart_keeps_doubled_kappa(method):
    """The restart at the same load of the run whose kappa doubled
    (test_contactPatchTest's kappaScale 0.01): with the doubled kappa read
    back (barrierStiffness in the slave's entry of D) the converged step
    continues in 1 corrector with no doubling (measured); a lost kappa
    would start from kappaScale K/h, whose gap is half the written one,
    and double it again in ~30 correctors."""
    ck = harness.Checks()
    name, r = runs.barrier_kappa_update(method)
    case = harness.need(r, name)
    tag = name + "Restart"
    if restart_reproduces(ck, case, tag, max_correctors=3, slave="lowerTop"):
        barrier_kappa_carried(ck, case, tag, "lowerTop")
    ck.verify()


@pytest.mark.xdist_group("cattaneoMindlin_" + LM)
def test_cattaneoMindlin_restart_keeps_friction_state():
    """Continue the finished frictional run for one more step at the load
    of its last step (the tables clamp beyond their last time): with the
    friction history written with the time (stick points, slip, stick
    flags) it continues converged in at most 3 correctors (issue 10's;
    1 measured with the tutorial's writePrecision 15; with 12 the last
    digit of D, through the multiplier's stiffness, was 2.5e-9 of the
    residual and the restart took 6 correctors, a slipping face sticking
    on the way) with the same forces and friction state (to 1e-6), every
    stick flag as it was (a slipping face turned to stick while the
    slave's traction was not written with the time: 43/3 stick/slip
    faces against 34/12). Then from the first
    written time on, the run must retrace the finished one: every step
    after the restart needs the stick points, flags and slip written at
    that time (a lost state changes the stick set)."""
    ck = harness.Checks()
    finished = harness.need(runs.cattaneo(LM))
    name, patch, max_correctors = "cattaneoMindlinRestart", "cylinderContact", 3
    last = foamio.latest_time(finished)
    nxt = "%g" % (float(last) + 1)
    r = harness.restart_run(finished, end_time=nxt)
    steps = re.findall(r"^Time = (\S+)\s+correctors = (\d+)", r["out"], flags=re.M)
    if r["rc"] or len(steps) != 1 or steps[0][0] != nxt:
        ck.add(name + "/run", False, note="rc=%d, steps %s, see %s" % (r["rc"], steps, r["case"]))
        ck.verify()
    case = r["case"]
    ncorr = int(steps[0][1])
    ck.add(name + "/correctors", ncorr <= max_correctors, ncorr, 1, ncorr - 1,
           max_correctors - 1)
    rf, c = contactreport.last_row(finished, patch), contactreport.last_row(case, patch)
    if rf and c and rf.get("normalForce"):
        err = abs(c["normalForce"] - rf["normalForce"]) / abs(rf["normalForce"])
        ck.add(name + "/normal_force_equal", err <= 1e-6, c["normalForce"], rf["normalForce"],
               err, 1e-6)
    ck.friction_fields_agree(finished, case, name, patch, 1e-6)

    times = foamio.times(finished)
    case = finished + "_restartFirst"
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(finished, case, ignore=shutil.ignore_patterns(
        "processor*", "VTK", "log.*", "postProcessing", *times[1:]))
    cd = os.path.join(case, "system/controlDict")
    text = re.sub(r"^startFrom\s+[^;]+;", "startFrom latestTime;", open(cd).read(), flags=re.M)
    text = re.sub(r"^endTime\s+[^;]+;", "endTime %s;" % last, text, flags=re.M)
    open(cd, "w").write(text)
    rc, _ = harness.run([harness.SOLVER], cwd=case,
                        log=os.path.join(case, "log.solidContactFoam"))
    if rc or foamio.latest_time(case) != last:
        ck.add(name + "First/run", False, note="rc=%d, see %s" % (rc, case))
    else:
        ck.friction_fields_agree(finished, case, name + "First", patch, 1e-6)
    ck.verify()
