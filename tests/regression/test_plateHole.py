"""plateHole: the plate with a hole against Kirsch (compareKirsch.py), its
VTK output, and the plain iteration (acceleration none) against the
accelerated one. Its decomposed run is in test_parallel.py."""
import pytest

import harness
import runs

pytestmark = pytest.mark.xdist_group("plateHole")


plate_hole = runs.plate_hole


def test_kirsch_stress_and_vtk_fields():
    ck = harness.Checks()
    r = plate_hole()
    if ck.run(r, "plateHole"):
        ck.vtk_written(r["case"], "plateHole", ["D", "sigma", "sigmaEq", "pointD"])
    ck.verify()


def test_acceleration_none_equals_accelerated():
    """The plain iteration (acceleration none): the same answer as the
    default accelerated one within what a 1e-9 residual leaves (measured
    4e-8 of D), and Kirsch's checks."""
    ck = harness.Checks()
    plain = harness.tutorial_run("plateHole", "plateHolePlain", controls="acceleration none;")
    if ck.run(plain, "plateHolePlain"):
        ck.displacements_agree(harness.need(plate_hole()), plain["case"],
                               "plateHolePlain/D_equals_accelerated", 1e-6)
    ck.verify()
