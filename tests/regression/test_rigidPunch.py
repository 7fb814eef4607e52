"""rigidPunch: Sneddon's flat-ended rigid punch (a triangulated surface
with a sharp edge, no mesh) on an elastic block, quarter model, two load
steps at -refine 1 (15 faces across a): compareRigidPunch.py's checks (F
against 2 a E* delta within 2 % at every step, measured -0.13 %; the
pressure under the punch against Sneddon's away from the edge). The force check is what caught the closest point on
the punch's side for faces that crossed its end near the edge (+15 %,
growing with the mesh; triSurfaceRigidSurface.H)."""
import pytest

import harness
import runs


@pytest.mark.xdist_group("rigidPunch")
def test_rigid_punch_sneddon():
    ck = harness.Checks()
    r = runs.rigid_punch(runs.LM)
    ck.run(r, "rigidPunch_" + runs.LM)
    ck.verify()


@pytest.mark.xdist_group("rigidPunch")
def test_rigid_punch_parallel_equals_serial():
    """Allrun -parallel: each processor reads the STL from the case's
    constant/triSurface (processorN/constant has none) and projects its own
    faces; F of both steps equal to the serial run's to 1e-6 (measured
    7e-11)."""
    ck = harness.Checks()
    name = "rigidPunch_%s_parallel" % runs.LM
    ref = harness.need(runs.rigid_punch(runs.LM), "rigidPunch_" + runs.LM)
    r = runs.rigid_punch(runs.LM, parallel=True)
    if ck.run(r, name):
        harness.forces_agree(ck, r["case"], ref, "blockTop", name, 1e-6, "equals_serial")
    ck.verify()
