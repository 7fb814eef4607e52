"""hertzCylinder: Hertz line contact (compareHertz.py: p0 within 3 %, a
within 1.5 faces) for every method of the selection table, with the
coefficients of the tutorial's 0/D; the relations between methods that
their traits predict; unloading, a finer mesh, the plain iteration, VTK
output, the contact-free equivalent and the reused search tree.
Serial/parallel comparisons are in test_parallel.py, restarts in
test_restart.py."""
import os

import numpy as np
import pytest

import harness
from c4fpost import methods
import runs
from harness import methods_where, methods_with_coeff

METHODS = list(methods.table())
LM = runs.LM
# The plain penalty: the penalty answer with no multipliers
PENALTY = runs.PENALTY
hertz = runs.hertz


def group(method):
    return pytest.mark.xdist_group("hertzCylinder_" + method)


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m)) for m in METHODS])
def test_hertz_pressure_and_half_width(method):
    """compareHertz's checks; the barrier also keeps every gap open."""
    ck = harness.Checks()
    r = hertz(method)
    name = "hertzCylinder_" + method
    if ck.run(r, name) and methods.table()[method].answer == "barrier":
        ck.barrier_gaps_open(r["case"], name)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_where(multipliers="regularised")])
def test_regularised_multiplier_equals_penalty(method):
    """A regularised multiplier (perturbedLagrange) with the penalty's eps
    (the same penaltyScale in both coefficient dictionaries of 0/D): the
    penalty run's force and peak pressure (measured 4e-10 and 1.6e-8)."""
    ck = harness.Checks()
    case, ref = harness.need(hertz(method)), harness.need(hertz(PENALTY))
    scales = [methods.coeff(c, m, "penaltyScale") for c, m in ((case, method),
                                                                      (ref, PENALTY))]
    assert scales[0] == scales[1], "penaltyScale of %s %g, of %s %g: not the same eps" % (
        method, scales[0], PENALTY, scales[1])
    ck.contact_agrees(ref, case, "hertzCylinder_" + method, 1e-6, ref_name=PENALTY)
    ck.verify()


@group("directElimination")
def test_directElimination_equals_lagrangeMultiplier():
    """directElimination imposes the Lagrange multiplier's g_N = 0 with no
    multiplier: the same answer (force, peak and the stress field to 1e-6;
    measured 1e-9)."""
    ck = harness.Checks()
    de, lm = harness.need(hertz("directElimination")), harness.need(hertz(LM))
    name = "hertzCylinder_directElimination"
    ck.contact_agrees(lm, de, name, 1e-6, ref_name=LM)
    ck.stress_fields_agree(lm, de, name + "/sigma_equals_" + LM, 1e-6)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_with_coeff("gamma0")])
def test_nitsche_penetration_below_penalty(method):
    """Nitsche on hertzCylinder (gamma0 10, penaltyScale 10 in 0/D): at the
    fixed point the gap is the difference of the cells' and the face's
    normal stress over gamma, O(h grad sigma)/gamma, not the penalty's
    p/eps: its max penetration at most 1/10 of the penalty run's with the
    same scale (measured 0.03; a Nitsche that lost its flux term and became
    the penalty would give 1)."""
    from c4fpost import contactreport
    ck = harness.Checks()
    n = contactreport.last_row(harness.need(hertz(method)), "cylinderContact")
    p = contactreport.last_row(harness.need(hertz(PENALTY)), "cylinderContact")
    name = "hertzCylinder_%s/penetration_below_%s" % (method, PENALTY)
    if n is None or p is None:
        ck.add(name, False, note="no contactReport rows")
    else:
        ratio = n["maxPenetration"] / p["maxPenetration"]
        ck.add(name, ratio <= 0.1, n["maxPenetration"], p["maxPenetration"], ratio, 0.1)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_where(answer="constitutive")])
def test_soft_interface_law_spreads_pressure(method):
    """hertzCylinder with the soft interface law (Allrun -law soft):
    compareHertz checks it against Hertz's problem with that law between
    the surfaces (p0 3 %, a 1.5 faces, the penetration 1.5 %); here, that
    it spreads the pressure by what the law predicts: the drop of p0 below
    Hertz's (for the measured load) and the growth of a beyond Hertz's
    equal the law's to the same tolerances, and the law's are at least
    twice those tolerances, so that an answer within the stiff law's check
    of Hertz (p0 3 %, a 1.5 faces) fails. Then both pressures against
    Hertz in one plot (plotLaws.py)."""
    ck = harness.Checks()
    name = "hertzCylinder_%s_soft" % method
    stiff = harness.need(hertz(method))
    r = harness.tutorial_run("hertzCylinder", name, ["-method", method, "-law", "soft"])
    if ck.run(r, name) and os.path.exists(os.path.join(r["case"], "log.compareHertz")):
        soft = r["case"]
        compareHertz = harness.validation("hertzCylinder", "compareHertz")
        res = compareHertz.compare(soft)
        law, p = res["law"], np.array(res["p"])
        iMax = int(np.argmax(p))
        p0H = float(compareHertz.hertz.pressure(res["x"][iMax], res["P"], compareHertz.R,
                                                res["Es"]))
        drop = 1.0 - p[iMax] / p0H
        dropRef = 1.0 - float(np.interp(res["x"][iMax], law["x"], law["p"])) / p0H
        tolP = compareHertz.P0_TOL
        ck.add(name + "/p0_drop_below_hertz",
               abs(drop - dropRef) <= tolP and dropRef >= 2 * tolP,
               drop, dropRef, abs(drop - dropRef), tolP,
               note="(the law's drop %.3g >= 2 x %.3g)" % (dropRef, tolP))
        grow = res["aNum"] - res["aH"]
        growRef = law["a"] - res["aH"]
        tolA = compareHertz.A_TOL_FACES * res["hA"]
        ck.add(name + "/a_growth_beyond_hertz",
               abs(grow - growRef) <= tolA and growRef >= 2 * tolA,
               grow, growRef, abs(grow - growRef), tolA,
               note="[m] (the law's growth %.3g m >= 2 x %.3g m)" % (growRef, tolA))
        png = os.path.join(soft, "lawPressure.png")
        rc, _ = harness.run(["/usr/bin/python3",
                             os.path.join(harness.ROOT,
                                          "tutorials/hertzCylinder/validation/plotLaws.py"),
                             stiff, soft, "--png", png], cwd=soft,
                            log=os.path.join(soft, "log.plotLaws"))
        ck.add(name + "/plotLaws", rc == 0 and os.path.exists(png),
               note="(%s)" % png if rc == 0 else "rc=%d, see %s/log.plotLaws" % (rc, soft))
    ck.verify()


@pytest.mark.parametrize("method", methods_where(multipliers="augmented"))
def test_unload_opens_contact_and_multipliers_decay(method):
    """Unloading (Allrun -unload: loaded, half the approach, lifted off;
    compareUnload.py) for the methods with augmented multipliers: the
    contact opens, the force goes to zero, the multipliers of the
    separating faces decay monotonically (crossConstraint: by
    exp(-eps g/lambda) per update). Before the force test skipped an open
    contact, the lifted step never converged (its force was the residual
    traction, changing sign); augmentedLagrange's update line divided by a
    zero multiplier (a floating point exception)."""
    ck = harness.Checks()
    name = "hertzCylinderUnload_" + method
    ck.run(harness.tutorial_run("hertzCylinder", name, ["-method", method, "-unload"]), name)
    ck.verify()


@pytest.mark.parametrize("method", methods_where(multipliers="augmented"))
def test_unload_multipliers_updated_once_converged(method):
    """The same with `multiplierUpdate converged` (the Uzawa loop: an update
    once the correctors have converged): the per-update checks of
    compareUnload.py, the monotone decay of the separating faces'
    multipliers and crossConstraint's exponential decay by
    exp(-eps g/lambda) per update."""
    ck = harness.Checks()
    name = "hertzCylinderUnloadConverged_" + method
    ck.run(harness.tutorial_run(
        "hertzCylinder", name, ["-method", method, "-unload"],
        edit=lambda case: methods.set_coeff(case, method, "multiplierUpdate", "converged")),
        name)
    ck.verify()


def test_refine2_lagrangeMultiplier():
    """The second mesh level (4x the cells, 46 slave faces in contact): the
    mesh the plain iteration stalled on before the interface was
    implicit."""
    ck = harness.Checks()
    ck.run(harness.tutorial_run("hertzCylinder", "hertzCylinder_refine2",
                                ["-method", LM, "-refine", "2"]), "hertzCylinder_refine2")
    ck.verify()


@group(LM)
def test_accelerated_equals_plain_iteration():
    """The accelerated iterate it stops at is a fixed point of the
    corrector: the same force and peak as the plain iteration's (acceleration
    none; measured 6e-10 relative) within what the 1e-9 residual leaves."""
    ck = harness.Checks()
    name = "hertzCylinder_%s_plain" % LM
    plain = harness.tutorial_run("hertzCylinder", name, ["-method", LM],
                                 controls="acceleration none;")
    if ck.run(plain, name):
        ck.contact_agrees(plain["case"], harness.need(hertz(LM)), "hertzCylinderAccelerated",
                          1e-7, ref_name="plain")
    ck.verify()


@group(LM)
def test_vtk_contact_fields_written():
    ck = harness.Checks()
    ck.vtk_written(harness.need(hertz(LM)), "hertzCylinder_" + LM,
                   ["D", "sigma", "contactPressure", "contactGap", "contactTraction",
                    "contactActive"])
    ck.verify()


@group(LM)
def test_contact_free_equivalent_equals_contact():
    """The contact run's converged slave displacement and master traction
    prescribed (c4fpost.contactfree, a non-uniform solidTraction field)
    give the same D without contact, within what the 1e-9 residual of
    either (plain) run leaves: 1e-6, as serial against parallel (measured
    2.2e-7)."""
    import shutil
    from c4fpost import contactfree, foamio
    ck = harness.Checks()
    contact = harness.need(hertz(LM))
    case = contact + "_contactFree"
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(contact, case, ignore=shutil.ignore_patterns(
        "processor*", "VTK", "log.*", "postProcessing", "*.png"))
    contactfree.make_contact_free(case, foamio.latest_time(contact),
                                  "cylinderContact", "blockContact")
    rc, _ = harness.run([harness.SOLVER], cwd=case,
                        log=os.path.join(case, "log.solidContactFoam"))
    if rc:
        ck.add("hertzCylinderContactFree/run", False, note="rc=%d, see %s" % (rc, case))
    else:
        ck.steps_converged(case, "hertzCylinderContactFree")
        ck.displacements_agree(contact, case, "hertzCylinderContactFree/D_equals_contact", 1e-6)
    ck.verify()


@group(LM)
def test_search_tree_reuse_equals_rebuild():
    """The search tree reused until the master moves 0.1 mm
    (rebuildTolerance 1e-4): the stale tree's answers are exact, so only
    the iteration path may differ: the same 1e-6 as serial against
    parallel."""
    import re
    ck = harness.Checks()

    def reuse_tree(case):
        d = os.path.join(case, "0/D")
        text, n = re.subn(r"^(\s*method\s+lagrangeMultiplier;)", r"\1 rebuildTolerance 1e-4;",
                          open(d).read(), flags=re.M)
        if n == 0:
            raise RuntimeError("no 'method lagrangeMultiplier;' in " + d)
        open(d, "w").write(text)
    reuse = harness.tutorial_run("hertzCylinder", "hertzCylinderTreeReuse", edit=reuse_tree)
    ck.contact_agrees(harness.need(hertz(LM)), reuse["case"], "hertzCylinderTreeReuse", 1e-6)
    ck.verify()
