"""Every decomposition works (issue 24): each case run serially, then
decomposed in every layout of tests/decompositions.py (scotch on 2, 3 and
4 processors, simple cuts through the contact on 2 and 4, every slave
face on one processor, every master face on one processor, a third
processor without any contact face, a processor holding one face of
each patch), and each decomposed run's D equal to the serial run's to
1e-8 of max |D|. Both stop at the outer correctors' residual, 1e-9 in
the tutorials, which left hertzCylinder's runs up to 1.04e-8 apart (scotch
on 3 processors; 8.8e-9 with a third processor without contact faces):
that is the tolerance's reach, not the decomposition's, so hertzCylinder
runs here to 1e-11. The others stop at 1e-9 (1.2e-10 apart). With
friction (slidingBlock with coulomb, the stick patch test with stick:
3.5e-11) the slave's stick flags are the serial run's too. Before, 3 or 4 processors of hertzCylinder crashed
(MPI_ERR_TRUNCATE) or hung: the mesh-quality check reduced once per
patch over each processor's own patches, processor patches included."""
import os

import numpy as np
import pytest

import decompositions
import harness
from c4fpost import foamio
import runs

LM = runs.LM
TOL = 1e-8
LAYOUTS = ("scotch2", "scotch3", "scotch4", "simpleCut2", "simpleCut4", "slaveOnOne",
           "masterOnOne", "noContactFace3", "oneFaceEach")
# (tutorial, Allrun arguments, outer tolerance or None for the tutorial's)
CASES = (("hertzCylinder", ["-method", LM], "1e-11"),
         ("contactPatchTest3D", ["-method", LM, "-rotate"], None),
         ("slidingBlock", ["-method", LM, "-friction", "coulomb"], None),
         ("contactPatchTest", ["-method", LM, "-friction", "stick", "-shear", "one"], None))


# One xdist group: the sweeps take turns, so that at most one run of up to
# 4 processes shares the 2 cores with the other worker's run
@pytest.mark.parametrize("tutorial,args,tolerance", [pytest.param(
    t, a, tol, marks=pytest.mark.xdist_group("decompositions"), id=t) for t, a, tol in CASES])
def test_every_decomposition_equals_serial(tutorial, args, tolerance):
    ck = harness.Checks()
    name = "%s_decompositions" % tutorial
    serial = harness.tutorial_run(
        tutorial, name, args,
        edit=(lambda case: harness.set_solid_tolerance(case, tolerance)) if tolerance else None)
    if not ck.run(serial, name):
        ck.verify()
    ref = serial["case"]
    slave, _ = decompositions.slave_master(ref)
    layouts = decompositions.layouts(ref)
    ck.add(name + "/layouts", sorted(layouts) == sorted(LAYOUTS),
           note="(%s)" % ", ".join(sorted(layouts)))
    for layout in LAYOUTS:
        if layout not in layouts:
            continue
        case, rc = decompositions.run_decomposed(ref, layout, layouts[layout])
        label = "%s/%s_%dprocs" % (name, layout, layouts[layout][0])
        ck.add(label + "/run", rc == 0, note="(rc %d; see %s/log.*)" % (rc, case))
        if rc != 0:
            continue
        ck.steps_converged(case, label)
        ck.displacements_agree(ref, case, label + "/D_equals_serial", TOL)
        stick = os.path.join(ref, foamio.latest_time(ref), "contactStick")
        if os.path.exists(stick):
            s = foamio.read_patch(stick, slave)
            p = foamio.read_patch(os.path.join(case, foamio.latest_time(case), "contactStick"),
                                  slave)
            ck.add(label + "/stick_flags_equal", np.array_equal(np.rint(s), np.rint(p)),
                   note="(%d faces)" % len(s))
    ck.verify()
