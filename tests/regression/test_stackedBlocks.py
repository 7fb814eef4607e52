"""Many pairs (issue 24): tutorials/stackedBlocks, three blocks through two
contact pairs on non-matching meshes, the middle block the master of one
pair and the slave of the other. compareStack.py checks the uniform
stress of the blocks in series and both pairs' forces to 1e-6 for every
method whose patch-test answer has a closed form here (exact: measured
3e-11 to 5e-10; the penalty family with each pair's spring in series),
and the scotch decomposition on 2 processors against it as well."""
import pytest

import harness
from c4fpost import methods
import runs

LM = runs.LM
TUTORIAL = "stackedBlocks"


@pytest.mark.parametrize("method", [m for m in methods.names()
                                    if methods.get(m).answer in ("exact", "penalty")])
def test_stacked_blocks(method):
    ck = harness.Checks()
    name = "%s_%s" % (TUTORIAL, method)
    ck.run(harness.tutorial_run(TUTORIAL, name, ["-method", method]), name)
    ck.verify()


def test_stacked_blocks_parallel():
    ck = harness.Checks()
    name = "%s_parallel" % TUTORIAL
    r = harness.tutorial_run(TUTORIAL, name, ["-method", LM, "-parallel"])
    if ck.run(r, name):
        ck.decomposed(r["case"], name + "/decomposed")
    ck.verify()
