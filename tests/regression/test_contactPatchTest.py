"""contactPatchTest: the 2D patch test across a non-matching interface
(comparePatchTest.py checks each method by the answer its traits give:
exact, the penalty's series-spring offset, the constitutive law's series
solution and penetration, the barrier's series solution and open gap),
for every method of the selection table; the relations between methods;
coefficient variants; and onNonConvergence continue. The frictional patch
test is in test_friction.py, the material and slave variants in
test_dissimilar.py."""
import os
import re

import pytest

import harness
import runs
from c4fpost import contactreport, methods
from harness import methods_where, methods_with_coeff

METHODS = list(methods.table())
LM = runs.LM
# The plain penalty: the penalty answer with no multipliers
PENALTY = runs.PENALTY
patch = runs.patch

# The kinds of answer comparePatchTest.py knows how to check: a method
# whose answer is another has no closed-form check, and fails
ANSWERS = ("exact", "penalty", "constitutive", "barrier")


def group(method):
    return pytest.mark.xdist_group("contactPatchTest_" + method)


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m)) for m in METHODS])
def test_patch_test_closed_form(method):
    """comparePatchTest's checks for the method's answer; the barrier also
    keeps every gap open."""
    ck = harness.Checks()
    answer = methods.table()[method].answer
    if answer not in ANSWERS:
        ck.add("contactPatchTest_%s/closed_form_check" % method, False,
               note="method %s answers '%s' (solidContactFoam -listMethods), which the patch"
                    " test has no closed form for (%s)" % (method, answer, ", ".join(ANSWERS)))
        ck.verify()
    r = patch(method)
    name = "contactPatchTest_" + method
    if ck.run(r, name) and answer == "barrier":
        ck.barrier_gaps_open(r["case"], name)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_where(answer="barrier")])
def test_barrier_kappa_doubles_and_converges(method):
    """The barrier's stiffness update: with kappaScale 0.01 the gap falls
    below gapFloor (1e-2 dhat) while shrinking, so kappa doubles once
    (multiplierUpdates 1) and the step goes on to converge with the new
    kappa: the series solution with the written (doubled) kappa to 1e-6,
    as a step that looked converged at the old kappa would not be. Its
    restart is in test_restart.py."""
    ck = harness.Checks()
    name, r = runs.barrier_kappa_update(method)
    if ck.run(r, name):
        ck.barrier_gaps_open(r["case"], name)
        row = contactreport.last_row(r["case"], "lowerTop") or {}
        ck.add(name + "/kappa_doubled", row.get("multiplierUpdates", 0) >= 1,
               note="(multiplierUpdates %s)" % row.get("multiplierUpdates"))
    ck.verify()


@pytest.mark.parametrize("method", methods_where(answer="barrier"))
def test_barrier_answer_below_its_extension_stops(method):
    """kappaScale 1e-6 with maxKappaFactor 1: the load needs a gap far below
    the law's extension (extensionScale dhat), where the law is no longer
    the barrier's, and kappa may not double: a FatalIOError naming the gap,
    the extension and maxKappaFactor, and no time written (measured: the
    converged gap -1.0e-5 m against an extension of 1e-8 m)."""
    ck = harness.Checks()
    name = "contactPatchTest_%s_belowExtension" % method
    case = harness.fresh_copy("contactPatchTest", name)
    methods.set_coeff(case, method, "kappaScale", "1e-6")
    methods.set_coeff(case, method, "maxKappaFactor", "1")
    ok, note = harness.refused(case, ["-method", method],
                               ["below the barrier's extension", "maxKappaFactor 1",
                                "%sCoeffs" % method, "lowerTop"])
    ck.add(name + "/refused", ok, note=note)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_where(answer="constitutive")])
def test_linear_interface_law_equals_penalty(method):
    """n = 1 is the penalty with eps = cN: eps = penaltyScale K/h of the
    tutorial's penalty (10 x 1e6 Pa / 0.1 m); the same stress field to
    1e-6 (both stop at residual 1e-9)."""
    ck = harness.Checks()
    name = "contactPatchTest_%s_n1" % method

    def linear_law(case):
        methods.set_coeff(case, method, "cN", "1e8")
        methods.set_coeff(case, method, "n", "1")
    r = harness.tutorial_run("contactPatchTest", name, ["-method", method], edit=linear_law)
    if ck.run(r, name):
        ck.stress_fields_agree(harness.need(patch(PENALTY)), r["case"],
                               name + "/sigma_equals_" + PENALTY, 1e-6)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=group(m))
                                    for m in methods_where(multipliers="regularised")])
def test_regularised_multiplier_equals_penalty(method):
    """A regularised multiplier's answer (perturbedLagrange) is the
    penalty's with the same eps (penaltyScale 10 in both coefficient
    dictionaries of 0/D): the same stress field to 1e-6 (measured 4.8e-8:
    the multiplier tolerance's remainder)."""
    ck = harness.Checks()
    case, ref = harness.need(patch(method)), harness.need(patch(PENALTY))
    scales = [methods.coeff(c, m, "penaltyScale") for c, m in ((case, method),
                                                                      (ref, PENALTY))]
    assert scales[0] == scales[1], "penaltyScale of %s %g, of %s %g: not the same eps" % (
        method, scales[0], PENALTY, scales[1])
    ck.stress_fields_agree(ref, case, "contactPatchTest_%s/sigma_equals_%s" % (method, PENALTY),
                           1e-6)
    ck.verify()


@group("directElimination")
def test_directElimination_equals_lagrangeMultiplier():
    """directElimination imposes the Lagrange multiplier's g_N = 0 with
    another active-set rule and no multiplier: the same fixed point, the
    LM run's stress field to 1e-6 (measured 1e-11)."""
    ck = harness.Checks()
    ck.stress_fields_agree(harness.need(patch(LM)), harness.need(patch("directElimination")),
                           "contactPatchTest_directElimination/sigma_equals_" + LM, 1e-6)
    ck.verify()


@pytest.mark.parametrize("method,gamma0", [(m, g) for m in methods_with_coeff("gamma0")
                                           for g in ("1", "100")])
def test_consistent_method_exact_for_any_gamma0(method, gamma0):
    """Nitsche is consistent: the uniform stress to 1e-6 whatever gamma0
    (comparePatchTest's exact check; 10 is the tutorial's), no penalty
    offset."""
    ck = harness.Checks()
    name = "contactPatchTest_%s_gamma0_%s" % (method, gamma0)
    ck.run(harness.tutorial_run("contactPatchTest", name, ["-method", method],
                                edit=lambda case: methods.set_coeff(case, method, "gamma0",
                                                                           gamma0)),
           name)
    ck.verify()


def test_onNonConvergence_continue_writes_and_flags():
    """onNonConvergence continue: a step cut short at 1 corrector is
    written, the log warns, and contactReport says converged = 0."""
    ck = harness.Checks()
    name = "contactPatchTestContinue"
    case = harness.fresh_copy("contactPatchTest", name)
    fv = os.path.join(case, "system/fvSolution")
    text = re.sub(r"^(\s*)nCorrectors\s+\d+;", r"\1nCorrectors 1; onNonConvergence continue;",
                  open(fv).read(), flags=re.M)
    open(fv, "w").write(text)
    harness.run(["blockMesh"], cwd=case, log=os.path.join(case, "log.blockMesh"))
    rc, out = harness.run([harness.SOLVER], cwd=case,
                          log=os.path.join(case, "log.solidContactFoam"))
    row = contactreport.last_row(case, "lowerTop")
    ok = (rc == 0 and os.path.isdir(os.path.join(case, "1")) and "NOT CONVERGED" in out
          and "going on (onNonConvergence continue)" in out
          and row is not None and row.get("converged") == 0)
    ck.add(name + "/written_and_flagged", ok,
           note="(rc=%d, converged column %s)"
           % (rc, None if row is None else row.get("converged")))
    ck.verify()
