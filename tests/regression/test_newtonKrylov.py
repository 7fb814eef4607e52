"""The Newton-Krylov outer loop (`-algorithm newtonKrylov`, solidMechanics'
algorithm newtonKrylov): every method on hertzCylinder, the contact patch
test, the finite-strain patch test (frictionless, stick, Coulomb),
Coulomb friction (cattaneoMindlin, slidingBlock), a rigid tool
(rigidSphere) and a decomposed run, each passing its tutorial's validation
and, where the segregated run is the reference, giving its answer to
what the residual tolerance (1e-9) leaves. The Newton vs Anderson table
(iterations, products, wall time) is make bench's (tests/bench/run.py
--only newton)."""
import os
import re

import pytest

import harness
import runs
from c4fpost import methods
from regression.test_restart import restart_reproduces

LM = runs.LM
NEWTON = ["-algorithm", "newtonKrylov"]


def newton_steps(case):
    """(Newton steps, products, unconverged GMRES solves) of every load
    step in the solver's log."""
    text = open(os.path.join(case, "log.solidContactFoam")).read()
    return [tuple(int(v) for v in m) for m in re.findall(
        r"newtonKrylov: (\d+) Newton steps, (\d+) products, (\d+) GMRES", text)]


def newton_ran(ck, r, name, steps=1):
    """The log holds one newtonKrylov line per load step (`steps` of them),
    each with at least one Newton step and every GMRES solve converged.
    Returns newton_steps' list."""
    s = newton_steps(r["case"])
    ck.add(name + "/newton_steps", len(s) == steps and all(n >= 1 for n, _, _ in s),
           note="%s (Newton steps, products, unconverged) per load step" % s)
    ck.add(name + "/gmres_converged", bool(s) and all(u == 0 for _, _, u in s),
           note="%s" % s)
    return s


# Newton from the second corrector: the patch tests converge within the
# segregated correctors a load step starts with (contactPatchTest in 3), so
# that by default no Newton step would be taken
NEWTON_AT_ONCE = "newtonKrylovCoeffs { maxSegregatedStart 1; }"


def newton_run(ck, tutorial, name, args, steps=1, controls=None):
    """The tutorial's Allrun with `args` under Newton-Krylov (shared by
    name; `controls` into solidMechanics), its validation checks and
    newton_ran's; the run, or None where it failed."""
    r = harness.tutorial_run(tutorial, name, list(args) + NEWTON, controls=controls or "")
    if not ck.run(r, name):
        return None
    newton_ran(ck, r, name, steps)
    return r


def hertz_newton_name(method):
    return "hertzCylinder_newtonKrylov_" + method


def group(method):
    # The segregated reference runs in the same worker
    return pytest.mark.xdist_group("hertzCylinder_" + method)


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods.table()])
def test_hertz_newton_equals_segregated(method):
    """compareHertz's checks under Newton-Krylov, and the segregated run's
    force and peak pressure to 1e-6 (measured for LM: 1.5e-9)."""
    ck = harness.Checks()
    name = hertz_newton_name(method)
    r = newton_run(ck, "hertzCylinder", name, ["-method", method])
    if r:
        ck.contact_agrees(harness.need(runs.hertz(method)), r["case"], name, 1e-6,
                          ref_name="segregated")
    ck.verify()


@group(LM)
def test_hertz_newton_steps():
    """Issue 26's at most 15 Newton steps a load step on hertzCylinder
    (LM), the run test_hertz_newton_equals_segregated checks (measured 4
    after 8 segregated correctors; 15 after one, 17 with none)."""
    ck = harness.Checks()
    name = hertz_newton_name(LM)
    case = harness.need(harness.tutorial_run("hertzCylinder", name, ["-method", LM] + NEWTON),
                        "the Newton hertzCylinder run")
    steps = [n for n, _, _ in newton_steps(case)]
    ck.add(name + "/newton_steps_at_most_15", len(steps) == 1 and 1 <= steps[0] <= 15,
           note="%s Newton steps" % steps)
    ck.verify()


@group(LM)
def test_hertz_newton_fallback():
    """maxNewtonSteps 2 on hertzCylinder (4 Newton steps without, after 8
    segregated correctors): after the second Newton step the segregated
    correctors (Anderson) finish the step, the log says how many, and the
    answer is the segregated run's to 1e-6."""
    ck = harness.Checks()
    name = "hertzCylinder_newtonKrylov_fallback"
    r = harness.tutorial_run("hertzCylinder", name, ["-method", LM] + NEWTON,
                             controls="newtonKrylovCoeffs { maxNewtonSteps 2; }")
    if ck.run(r, name):
        text = open(os.path.join(r["case"], "log.solidContactFoam")).read()
        m = re.search(r"newtonKrylov: (\d+) Newton steps, \d+ products, \d+ GMRES solves "
                      r"unconverged, after \d+ segregated correctors, then (\d+) segregated "
                      r"correctors", text)
        ck.add(name + "/fell_back", m is not None and int(m.group(1)) == 2
               and int(m.group(2)) > 0, note="(%s)" % (m.group(0) if m else "no fallback line"))
        ck.contact_agrees(harness.need(runs.hertz(LM)), r["case"], name, 1e-6,
                          ref_name="segregated")
    ck.verify()


@pytest.mark.parametrize("method", [LM, runs.PENALTY])
def test_patch_test_newton(method):
    """The contact patch test's checks (the exact methods to 1e-6, the
    penalty to its offset) under Newton-Krylov, Newton from the second
    corrector (NEWTON_AT_ONCE)."""
    ck = harness.Checks()
    name = "contactPatchTest_newtonKrylov_" + method
    newton_run(ck, "contactPatchTest", name, ["-method", method],
               controls=NEWTON_AT_ONCE)
    ck.verify()


def test_finite_strain_patch_test_newton():
    """finiteStrainPatchTest (neo-Hookean, 80 % in one step, LM): the
    closed form to 1e-6 under Newton-Krylov (measured 7e-11 in 4 Newton
    steps after 3 segregated correctors). It needs every product to start from the state the Newton
    step's corrector left (the contact faces' values and coefficients):
    without, it stopped at a state 2 off in sigma_yy whose residual was
    below the tolerance."""
    ck = harness.Checks()
    name = "finiteStrainPatchTest_newtonKrylov"
    newton_run(ck, "finiteStrainPatchTest", name, [])
    ck.verify()


def test_finite_strain_patch_test_newton_barrier():
    """The same with the barrier (the upper block lifted 5e-5 m): uniform
    to 1e-6 with its gap (measured 9 Newton steps after 2 segregated
    correctors, F_N equal to the segregated run's to 2e-12). Newton from
    the first corrector, as the barrier took it until its law's
    extension, stalled, and the fallback ended on a non-uniform fixed
    point (sigma_yy spread 3.5)."""
    ck = harness.Checks()
    name = "finiteStrainPatchTest_newtonKrylov_barrier"
    newton_run(ck, "finiteStrainPatchTest", name, ["-method", "barrier"])
    ck.verify()


@pytest.mark.parametrize("friction", ["stick", "coulomb"])
def test_finite_strain_patch_test_newton_friction(friction):
    """The same with the stick law and with Coulomb (mu = 0.3): every face
    tied, the frictionless answer to 1e-6 (measured 4e-9 with both, 4
    Newton steps after 3 segregated correctors). Coulomb ended 10 % off, every face stuck at a state
    its faces had slid to in Newton's first step, while a face coupled
    before it carried any pressure was left free (bound mu p_N = 0): now
    it is tied for that corrector (coulombFrictionModel.C)."""
    ck = harness.Checks()
    name = "finiteStrainPatchTest_newtonKrylov_" + friction
    newton_run(ck, "finiteStrainPatchTest", name, ["-friction", friction])
    ck.verify()


@pytest.mark.xdist_group("rigidSphere")
def test_rigid_sphere_newton_equals_segregated():
    """rigidSphere (a rigid tool, five steps) under Newton-Krylov: its
    checks and the segregated run's normal force and peak pressure to 1e-6
    (measured 8e-11), in 4 or 5 Newton steps a step after 4 or 5
    segregated correctors. The tutorial's D
    solver is PCG, whose fixed iterations are not a linear map: Newton's
    correctors solve with GAMG instead, and say so in the log (with PCG,
    GMRES had stalled at 0.1 to 0.5 of the residual, and rigid tools were
    refused)."""
    ck = harness.Checks()
    name = "rigidSphere_newtonKrylov"
    r = newton_run(ck, "rigidSphere", name, [], steps=5)
    if r:
        log = open(os.path.join(r["case"], "log.solidContactFoam")).read()
        ck.add(name + "/gamg_in_place_of_pcg",
               "the D solver PCG" in log and "solve with GAMG" in log,
               note="(the substitution is said in the log)")
        steps = [n for n, _, _ in newton_steps(r["case"])]
        ck.add(name + "/newton_steps_per_step", bool(steps) and max(steps) <= 15,
               max(steps or [0]), 15, max(steps or [0]), 15)
        ck.contact_agrees(harness.need(runs.rigid_sphere(LM)), r["case"], name, 1e-6,
                          ref_name="segregated", patch="blockTop")
    ck.verify()


@pytest.mark.xdist_group("cattaneoMindlin_" + LM)
def test_cattaneo_newton_equals_segregated():
    """cattaneoMindlin (Coulomb, two steps) under Newton-Krylov, the stick
    flags of each Newton step frozen like the active set: its checks, and
    the segregated run's normal force and peak to 1e-6."""
    ck = harness.Checks()
    name = "cattaneoMindlin_newtonKrylov"
    r = newton_run(ck, "cattaneoMindlin", name, ["-method", LM], steps=2)
    if r:
        ck.contact_agrees(harness.need(runs.cattaneo(LM)), r["case"], name, 1e-6,
                          ref_name="segregated", patch="cylinderContact")
    ck.verify()


def test_slidingBlock_newton():
    """slidingBlock (Coulomb, full slip over five steps) under Newton-Krylov:
    its checks."""
    ck = harness.Checks()
    name = "slidingBlock_newtonKrylov"
    newton_run(ck, "slidingBlock", name, ["-method", LM], steps=5)
    ck.verify()


@pytest.mark.xdist_group("hertzCylinder_" + LM)
def test_hertz_newton_parallel_equals_serial():
    """hertzCylinder -parallel (the cut through the contact zone) under
    Newton-Krylov: GMRES's dot products summed over the processors, the
    serial Newton run's force and peak to 1e-6."""
    ck = harness.Checks()
    name = "hertzCylinderParallel_newtonKrylov"
    r = newton_run(ck, "hertzCylinder", name, ["-method", LM, "-parallel"])
    if r:
        serial = harness.tutorial_run("hertzCylinder", hertz_newton_name(LM),
                                      ["-method", LM] + NEWTON)
        ck.contact_agrees(harness.need(serial), r["case"], name, 1e-6, ref_name="serial")
    ck.verify()


@pytest.mark.xdist_group("hertzCylinder_" + LM)
def test_hertz_newton_restart():
    """A finished Newton run continued for a second step at the same load
    (the contact state read back with the time) starts converged: at most
    5 correctors, Newton's products included, the same force to 1e-6 and
    the written slave traction to 1e-5 (restart_reproduces)."""
    ck = harness.Checks()
    name = "hertzCylinder_newtonKrylov_restart"
    r = harness.tutorial_run("hertzCylinder", hertz_newton_name(LM), ["-method", LM] + NEWTON)
    if ck.run(r, hertz_newton_name(LM)):
        restart_reproduces(ck, r["case"], name)
    ck.verify()


def test_self_contact_newton():
    """selfContactStrip (the strip closing its slot, six steps) under Newton:
    its checks against CalculiX's force at each contact step. Its first
    step in contact (t = 3) has a Newton trial rejected (2026-11-29: after
    2 Newton steps, then 88 segregated correctors from the best iterate):
    the log says so, and the step converged with the others (the
    tutorial's checks)."""
    ck = harness.Checks()
    name = "selfContactStrip_newtonKrylov"
    r = newton_run(ck, "selfContactStrip", name, ["-method", LM], steps=6)
    if r:
        text = open(os.path.join(r["case"], "log.solidContactFoam")).read()
        handed = re.findall(r"then (\d+) segregated correctors from the best Newton iterate"
                            r" \(a Newton trial ten times above its residual was rejected\)",
                            text)
        ck.add(name + "/rejected_trial_logged", len(handed) >= 1,
               note="%d step(s) went on from the best Newton iterate" % len(handed))
    ck.verify()
