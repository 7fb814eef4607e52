"""rigidPunch: Sneddon's flat-ended rigid punch (a triangulated surface
with a sharp edge, no mesh) on an elastic block, quarter model, two load
steps at -refine 1: compareRigidPunch.py's checks (F against 2 a E* delta
within 3 % at every step, the pressure under the punch against Sneddon's
away from the edge). The force check is what caught the closest point on
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
