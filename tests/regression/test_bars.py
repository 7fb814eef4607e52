"""Bars without contact: load steps from a table (uniaxialBar) and two
materials in series with a zoned law (bimaterialBar, serial; its
decomposed run is in test_parallel.py)."""
import os
import shutil

import numpy as np
import pytest

import harness
import runs
from c4fpost import foamio


def test_uniaxial_bar_stress_follows_load_table():
    """Bar of length L = 1 m, nu = 0, end displacement ramped to 1 mm at
    t = 2 by OpenFOAM's uniformFixedValue: sigma_xx = E delta(t)/L in every
    cell at every step (uniform strain is exact for this discretisation, so
    the tolerance is the outer-corrector tolerance 1e-9 with margin)."""
    ck = harness.Checks()
    case = os.path.join(harness.WORK, "uniaxialBar")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(harness.ROOT, "tests/regression/cases/uniaxialBar"), case)
    rc1, _ = harness.run(["blockMesh"], cwd=case, log=os.path.join(case, "log.blockMesh"))
    rc2, _ = harness.run([harness.SOLVER], cwd=case,
                         log=os.path.join(case, "log.solidContactFoam"))
    if rc1 or rc2:
        ck.add("uniaxialBar/run", False, note="failed, see %s" % case)
    else:
        E = 2e11
        for t, delta in (("1", 0.5e-3), ("2", 1e-3)):
            sxx = foamio.read_internal(os.path.join(case, t, "sigma"))[:, 0]
            ref = E * delta / 1.0
            err = float(np.abs(sxx - ref).max() / ref)
            ck.add("uniaxialBar/sxx_step_%s" % t, err <= 1e-6, float(sxx.mean()), ref, err,
                   1e-6)
    ck.verify()


@pytest.mark.xdist_group("bimaterialBar")
def test_bimaterial_bar_exact_in_series():
    ck = harness.Checks()
    r = runs.bimaterial_bar()
    if r["rc"]:
        ck.add("bimaterialBar/run", False, note="failed, see %s" % r["case"])
    else:
        ck.steps_converged(r["case"], "bimaterialBar")
        runs.bimaterial_checks(ck, r["case"], "bimaterialBar")
    ck.verify()
