"""Bad input: each case (badInput.CASES) edits a copy of a tutorial, runs
the solver, and must see it stop with a FatalIOError that names the file,
the entry and what is valid, with no crash and no time directory written."""
import os
import shutil

import pytest

import harness
from regression import badInput


@pytest.mark.parametrize("name,tutorial,edits,expected", badInput.CASES,
                         ids=[c[0] for c in badInput.CASES])
def test_bad_input_stops_with_clear_error(name, tutorial, edits, expected):
    ck = harness.Checks()
    check = "badInput/" + name
    case = os.path.join(harness.WORK, "badInput", name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(harness.ROOT, "tutorials", tutorial), case,
                    ignore=shutil.ignore_patterns("[1-9]*", "processor*", "log.*", "VTK",
                                                  "*.png"))
    try:
        for f, pat, rep in edits:
            badInput.edit(case, f, pat, rep)
    except RuntimeError as e:
        ck.add(check, False, note=str(e))
        ck.verify()
    rc, out = harness.run(["blockMesh"], cwd=case, log=os.path.join(case, "log.blockMesh"))
    if rc == 0 and os.path.exists(os.path.join(case, "system/topoSetDict")):
        rc, out = harness.run(["topoSet"], cwd=case, log=os.path.join(case, "log.topoSet"))
    if rc != 0:
        ck.add(check, False, note="blockMesh or topoSet failed")
        ck.verify()
    rc, out = harness.run([harness.SOLVER], cwd=case,
                          log=os.path.join(case, "log.solidContactFoam"))
    missing = [e for e in expected if e not in out]
    crashed = [m for m in badInput.CRASH_MARKERS if m in out]
    wrote = harness.times_written(case)
    note = "(rc=%d)" % rc
    if missing:
        note += " missing in output: %s" % missing
    if crashed:
        note += " crashed: %s" % crashed
    if wrote:
        note += " wrote time directories: %s" % wrote
    if rc == 0:
        note += " solver did not stop"
    ck.add(check, rc != 0 and not missing and not crashed and not wrote, note=note)
    ck.verify()
