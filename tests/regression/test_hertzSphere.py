"""hertzSphere: Hertz in 3D, the quarter model on its tutorial mesh (10
slave faces across a): compareSphere.py (p0 within 4 %, the contact radius
within one face, the RMS of p(r) - Hertz inside 0.8 a within 2.5 % of p0),
the reference exact method only (the bench runs the others and two mesh
levels). Its decomposed run is in test_parallel.py."""
import pytest

import harness
import runs


@pytest.mark.xdist_group("hertzSphere")
def test_hertz_point_contact_and_vtk_fields():
    ck = harness.Checks()
    r = runs.sphere()
    name = "hertzSphere_" + runs.LM
    if ck.run(r, name):
        ck.vtk_written(r["case"], name,
                       ["D", "sigma", "contactPressure", "contactGap", "contactActive"])
    ck.verify()
