"""contactPatchTest3D: the 3D patch test with non-matching faces in both
directions, the normal along an axis and turned 30 degrees about (1, 2, 3),
nu 0 and 0.3, for every method of the selection table (comparePatchTest3D.py
checks each by the answer its traits give; about 2 s a run). The barrier
also: the gap it starts from is Allrun's lift along the (turned) normal,
and every corrector's gaps stay open."""
import pytest

import harness
from c4fpost import methods
import runs

VARIANTS = ([], ["-rotate"], ["-nu", "0.3"], ["-rotate", "-nu", "0.3"])


def variant_id(opts):
    return "".join(o.lstrip("-").replace(".", "") for o in opts) or "axis"


@pytest.mark.parametrize("opts", VARIANTS, ids=variant_id)
@pytest.mark.parametrize("method", list(methods.table()))
def test_patch_test_3D_closed_form(method, opts):
    ck = harness.Checks()
    tag = "".join(o.lstrip("-").replace(".", "") for o in opts)
    name = "contactPatchTest3D_%s%s" % (method, ("_" + tag) if tag else "")
    r = harness.tutorial_run("contactPatchTest3D", name, ["-method", method] + opts,
                             controls=runs.verbose_for(method))
    if ck.run(r, name) and runs.is_barrier(method):
        # Allrun's default lift with -method barrier (half its dhat)
        ck.barrier_initial_gap(r["case"], name, 5e-4)
        ck.barrier_gaps_open(r["case"], name)
    ck.verify()
