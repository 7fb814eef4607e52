"""Dissimilar materials and slave choices, for the reference exact method
(the Lagrange multiplier) and the plain penalty: hertzCylinder with a
steel cylinder on an aluminium block, the near-rigid indenter with either
body the slave, and contactPatchTest with a 1000:1 stiffness ratio and a
coarse slave. The decomposed runs are in test_parallel.py."""
import pytest

import harness
from c4fpost import methods
import runs
from harness import methods_with_coeff

LM = runs.LM
PENALTY = runs.PENALTY
REPRESENTATIVES = (LM, PENALTY)


@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.xdist_group(
    "steelAluminium" if m == LM else "steelAluminium_" + m)) for m in REPRESENTATIVES])
def test_steelAluminium_hertz(method):
    """A steel cylinder on an aluminium block (a law per cellZone): Hertz
    with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 at the measured load, the
    tolerances of hertzCylinder (compareHertz.py)."""
    ck = harness.Checks()
    ck.run(runs.steel_aluminium(method), "hertzCylinder_steelAluminium_" + method)
    ck.verify()


@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.xdist_group(
    "nearRigid_" + m)) for m in REPRESENTATIVES])
def test_nearRigid_indenter_either_slave_agrees(method):
    """The near-rigid indenter (cylinder 1000 x stiffer than the block)
    against Hertz with the block's E* alone, with either body the slave.
    The stiff cylinder's faces (0.267 mm) are finer than the block's
    (0.35 mm): constrained per slave face its pressure oscillated (p0 2.5 x
    Hertz, the mortar inf-sup failure); it is constrained per block face
    (constraintFaces auto). Both roles give the same answer: peak pressure
    within compareHertz's tolerance (P0_TOL) of each other, the contact
    half-widths within A_TOL_FACES of the coarser slave faces (the
    one-sided resolution of each measure)."""
    ck = harness.Checks()
    blk, cyl = runs.near_rigid(method, "block"), runs.near_rigid(method, "cylinder")
    ok = ck.run(blk, "hertzCylinder_nearRigid_blockSlave_" + method)
    ok = ck.run(cyl, "hertzCylinder_nearRigid_cylinderSlave_" + method) and ok
    name = "hertzCylinder_nearRigid_roles_" + method
    if ok:
        compareHertz = harness.validation("hertzCylinder", "compareHertz")
        b = compareHertz.compare(blk["case"], estar="block")
        c = compareHertz.compare(cyl["case"], estar="block")
        pb, pc = max(b["p"]), max(c["p"])
        err = abs(pc - pb) / pb
        ck.add(name + "/peak_pressure", err <= compareHertz.P0_TOL, pc, pb, err,
               compareHertz.P0_TOL, note="(cylinder slave against block slave)")
        tolA = compareHertz.A_TOL_FACES * max(b["hA"], c["hA"])
        ck.add(name + "/contact_half_width", abs(c["aNum"] - b["aNum"]) <= tolA,
               c["aNum"], b["aNum"], abs(c["aNum"] - b["aNum"]), tolA, note="[m]")
    else:
        ck.add(name + "/compared", False, note="a run failed")
    ck.verify()


@pytest.mark.parametrize("method", methods_with_coeff("weights"))
def test_nearRigid_stiffness_weights(method):
    """Nitsche on the near-rigid indenter needs the stiffness-weighted flux
    (the compliant block's dominates; with the plain mean the stiff
    cylinder's cell stress cycles, residual 8e-7): Hertz with the block's
    E*, 53 correctors (LM 96)."""
    ck = harness.Checks()
    name = "hertzCylinder_nearRigid_blockSlave_" + method
    ck.run(harness.tutorial_run("hertzCylinder", name,
                                ["-method", method, "-materials", "nearRigidCylinder",
                                 "-slave", "block"],
                                edit=lambda case: methods.set_coeff(case, method, "weights",
                                                                           "stiffness")),
           name)
    ck.verify()


@pytest.mark.parametrize("variant,opts", [
    ("stiffUpper", ["-materials", "stiffUpper"]),
    ("stiffUpperSlave", ["-materials", "stiffUpper", "-slave", "upper"]),
    ("upperSlave", ["-slave", "upper"])], ids=["stiffUpper", "stiffUpperSlave", "upperSlave"])
@pytest.mark.parametrize("method", REPRESENTATIVES)
def test_patch_test_materials_and_slave(method, variant, opts):
    """The 1000:1 patch test with the soft block as the slave, and with the
    stiff one (7 coarse slave faces on 10 master faces): both converge to
    the same answer (the Lagrange multiplier's active-set constant from
    both half cells in series, the deferred correction solved to its fixed
    point); and the coarse slave with like materials."""
    ck = harness.Checks()
    name = "contactPatchTest_%s_%s" % (variant, method)
    ck.run(harness.tutorial_run("contactPatchTest", name, ["-method", method] + opts), name)
    ck.verify()
