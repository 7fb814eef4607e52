"""Decomposed runs on 2 processors against their serial runs: each is
checked like the serial run (its tutorial's closed form), ran on 2
processors, and agrees with the serial answer to 1e-6 (both stop at the
outer correctors' residual 1e-9). Each test shares its xdist group with
the serial run it compares with."""
import os
import re
import shutil

import pytest

import harness
from c4fpost import methods
import runs
from harness import methods_where, methods_with_coeff
from regression import badInput

LM = runs.LM


@pytest.mark.xdist_group("plateHole")
def test_plateHole_parallel_equals_serial():
    """The outer correctors stop at residual 1e-9; both runs carry an error
    of that order, so they agree to about 1e-7 of D."""
    ck = harness.Checks()
    name = "plateHoleParallel"
    par = harness.tutorial_run("plateHole", name, ["-parallel"])
    if ck.run(par, name):
        ck.decomposed(par["case"], name + "/decomposed")
        ck.displacements_agree(harness.need(runs.plate_hole()), par["case"],
                               name + "/D_equals_serial", 1e-6)
    ck.verify()


def held_master_faces(case):
    """(fewest, most, total) master faces a processor held at each
    selection (contactPatchPair's log line), over the run."""
    text = open(os.path.join(case, "log.solidContactFoam")).read()
    rows = re.findall(r"master faces held per processor (\d+) \.\. (\d+) of (\d+)", text)
    return [tuple(int(x) for x in r) for r in rows]


def hertz_parallel_checks(method):
    """hertzCylinder -parallel against the serial run: force and peak to
    1e-6 (the barrier also: every corrector's gaps open). No processor
    holds the whole master: each only the faces its slave faces can reach
    (measured 60 and 74 of 77: the processor whose slave faces lie on one
    side of the cut does not hold the master's far end)."""
    ck = harness.Checks()
    name, par = runs.hertz_parallel(method)
    if ck.run(par, name):
        ck.decomposed(par["case"], name + "/decomposed")
        held = held_master_faces(par["case"])
        ck.add(name + "/master_not_gathered_whole",
               bool(held) and all(lo < total for lo, _, total in held),
               note="(master faces held per processor at each selection: %s)" % held)
        if runs.is_barrier(method):
            ck.barrier_gaps_open(par["case"], name)
        ck.contact_agrees(harness.need(runs.hertz(method)), par["case"], name, 1e-6)
    ck.verify()


# The methods whose decomposed run tests a parallel path of its own: the
# reference (the contact zone cut at x = 3 mm); the consistent method
# with a gamma0 (Nitsche: the master's cell stress reaches the slave by the
# gathered master-to-slave transfer); augmentedLagrange (the multiplier
# decisions are reduced, so both take the same updates; its reconstructed
# case is restarted in test_restart.py); the barrier (its per-face kappa
# and the default dhat, reduced over processors, are the serial run's:
# measured 2e-9, 61 correctors against 63)
PARALLEL = [LM] + methods_with_coeff("gamma0") + ["augmentedLagrange"] \
    + methods_where(answer="barrier")


@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.xdist_group(
    "hertzCylinder_" + m)) for m in PARALLEL if m in methods.table()])
def test_hertzCylinder_parallel_equals_serial(method):
    hertz_parallel_checks(method)


@pytest.mark.xdist_group("steelAluminium")
def test_steelAluminium_parallel_equals_serial():
    """A steel cylinder on an aluminium block on 2 processors: as for like
    materials, both stop at residual 1e-9."""
    ck = harness.Checks()
    name = "hertzCylinderParallel_steelAluminium"
    par = harness.tutorial_run("hertzCylinder", name,
                               ["-method", LM, "-materials", "steelAluminium", "-parallel"])
    if ck.run(par, name):
        ck.decomposed(par["case"], name + "/decomposed")
        ck.contact_agrees(harness.need(runs.steel_aluminium(LM)), par["case"], name, 1e-6)
    ck.verify()


@pytest.mark.xdist_group("nearRigid_" + LM)
def test_nearRigid_cylinderSlave_parallel_equals_serial():
    """The block faces' constraints on 2 processors, the cut at x = 3 mm:
    block faces whose sub-faces lie on both processors (the group sums
    reduced over processors); both stop at residual 1e-9."""
    ck = harness.Checks()
    name = "hertzCylinderParallel_nearRigid_cylinderSlave"
    par = harness.tutorial_run("hertzCylinder", name,
                               ["-method", LM, "-materials", "nearRigidCylinder",
                                "-slave", "cylinder", "-parallel"])
    if ck.run(par, name):
        ck.decomposed(par["case"], name + "/decomposed")
        ck.contact_agrees(harness.need(runs.near_rigid(LM, "cylinder")), par["case"], name,
                          1e-6)
    ck.verify()


@pytest.mark.xdist_group("hertzSphere")
def test_hertzSphere_parallel_equals_serial():
    """3D contact on 2 processors, the cut at x = 0.05 m through the
    contact zone of both patches (measured: force and peak to 2e-9, D to
    5e-10)."""
    ck = harness.Checks()
    name = "hertzSphereParallel"
    par = harness.tutorial_run("hertzSphere", name, ["-method", LM, "-parallel"])
    if ck.run(par, name):
        ck.decomposed(par["case"], name + "/decomposed")
        sphere = harness.need(runs.sphere())
        ck.contact_agrees(sphere, par["case"], name, 1e-6, patch="sphereContact")
        ck.displacements_agree(sphere, par["case"], name + "/D_equals_serial", 1e-6)
    ck.verify()


@pytest.mark.xdist_group("bimaterialBar")
def test_bimaterialBar_parallel_equals_serial():
    """The two processors meet at the interface (simple decomposition, 10
    of the 20 columns each): the exact state as in serial, and D to 1e-6 of
    the serial run's (both stop at residual 1e-9: about 1e-8 of D)."""
    ck = harness.Checks()
    name = "bimaterialBarParallel"
    par = runs.bimaterial_bar(parallel=True)
    if par["rc"]:
        ck.add(name + "/run", False, note="failed, see %s" % par["case"])
    else:
        ck.steps_converged(par["case"], name)
        ck.decomposed(par["case"], name + "/decomposed")
        runs.bimaterial_checks(ck, par["case"], name)
        serial = runs.bimaterial_bar()
        if serial["rc"]:
            ck.add(name + "/D_equals_serial", False, note="the serial run failed")
        else:
            ck.displacements_agree(serial["case"], par["case"], name + "/D_equals_serial", 1e-6)
    ck.verify()


@pytest.mark.xdist_group("cattaneoMindlin_" + LM)
def test_cattaneoMindlin_parallel_equals_serial():
    """cattaneoMindlin on 2 processors, the cut through the stick zone:
    forces, D and the friction state equal the serial run's to 1e-6."""
    ck = harness.Checks()
    name = "cattaneoMindlinParallel"
    par = harness.tutorial_run("cattaneoMindlin", name, ["-method", LM, "-parallel"])
    if ck.run(par, name):
        ref = harness.need(runs.cattaneo(LM))
        ck.decomposed(par["case"], name + "/decomposed")
        ck.contact_agrees(ref, par["case"], name, 1e-6)
        ck.displacements_agree(ref, par["case"], name + "/D_equals_serial", 1e-6)
        ck.friction_fields_agree(ref, par["case"], name, "cylinderContact", 1e-6)
    ck.verify()


DECOMPOSE_ABOVE_INTERFACE = """FoamFile { version 2.0; format ascii; class dictionary;
           object decomposeParDict; }
numberOfSubdomains 2;
method simple;
coeffs { n (1 1 2); }
"""


@pytest.mark.xdist_group("contactPatchTest3D_noContactFace")
def test_processor_without_contact_faces_equals_serial():
    """contactPatchTest3D cut in z at the middle of the cell count: one
    processor holds both contact patches, the other no contact face at
    all (issue 24's crash: the slave point weights were made only where a
    processor had slave points, and the collective exchange in them
    mismatched, MPI_ERR_TRUNCATE). Serial = parallel to 1e-8 (measured
    1.8e-11)."""
    ck = harness.Checks()
    name = "contactPatchTest3D_noContactFace"
    serial = harness.tutorial_run("contactPatchTest3D", name, ["-method", LM])
    if not ck.run(serial, name):
        ck.verify()
    case = serial["case"] + "_parallel"

    def make():
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(serial["case"], case, ignore=shutil.ignore_patterns(
            "[1-9]*", "processor*", "log.*", "VTK", "postProcessing", "*.png",
            "checks.json"))
        with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
            f.write(DECOMPOSE_ABOVE_INTERFACE)
        rc, out = harness.run(["decomposePar", "-force"], cwd=case,
                              log=os.path.join(case, "log.decomposePar"))
        if rc == 0:
            rc, out = harness.run(["mpirun", "-np", "2", harness.SOLVER, "-parallel"],
                                  cwd=case, log=os.path.join(case, "log.solidContactFoam"))
        if rc == 0:
            rc, out = harness.run(["reconstructPar", "-latestTime"], cwd=case,
                                  log=os.path.join(case, "log.reconstructPar"))
        return rc

    rc = make()
    counts = re.findall(r"Number of cells = (\d+)",
                        open(os.path.join(case, "log.decomposePar")).read())
    ck.add(name + "/parallel_run", rc == 0,
           note="(cells per processor %s; see %s)" % (", ".join(counts), case))
    if rc == 0:
        ck.displacements_agree(serial["case"], case, name + "/D_equals_serial", 1e-8)
    ck.verify()


@pytest.mark.xdist_group("hertzCylinderParallel")
def test_processor_agglomeration_refused_with_contact():
    """GAMG's processorAgglomerator on 2 processors: it moves the coarse
    levels' interfaces between processors through the GAMGInterface type
    table, which has no contact interface ("Unknown GAMGInterface type
    contactInterface" before): a FatalIOError naming the entry and the
    contact patch, and no time directory on any processor."""
    ck = harness.Checks()
    name = "hertzCylinderProcessorAgglomerator"
    case = harness.fresh_copy("hertzCylinder", name)
    badInput.edit(case, "system/fvSolution", r"^(\s*)solver\s+GAMG;",
                  r"\1solver GAMG; processorAgglomerator masterCoarsest;")
    ok, note = harness.refused(case, ["-parallel"],
                               ["'processorAgglomerator' = masterCoarsest", "cylinderContact",
                                "Valid"])
    wrote = [d for p in os.listdir(case) if p.startswith("processor")
             for d in harness.times_written(os.path.join(case, p))]
    ck.add(name + "/refused", ok and not wrote, note=note + " processor times %s" % wrote)
    ck.verify()
