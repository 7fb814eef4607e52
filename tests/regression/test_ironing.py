"""Large sliding under finite deformation (issue 22): tutorials/
shallowIroning, the shallow-ironing benchmark (a neo-Hookean die with a
curved bottom pressed 1 mm into a neo-Hookean foundation, then ironed 10 mm
along it, Coulomb mu = 0.3) on its coarse mesh. compareIroning.py checks
that every step converged, the die's vertical force at the end of the
press inside the published spread, the global friction ratio at t = 1.5
inside 0.30 to 0.40 and the horizontal force smooth while the die slides.
The last two are not met yet (docs/tutorials.md#shallowironing): the
slave's faces wrap round the die's sharp leading corner in two ways, one
face more or less against its side, and the horizontal force jumps
between the two (+-5 %); they are a strict xfail, so the suite fails once
they pass and the mark must come off."""
import pytest

import harness

TUTORIAL = "shallowIroning"
OPEN = ("friction_ratio_t1.5", "H_smooth_while_sliding")


def _run():
    return harness.tutorial_run(TUTORIAL, TUTORIAL, [])


def _split(r, want_open):
    """The run with only its open checks (want_open) or only the others."""
    r = dict(r)
    if r.get("checks") is not None:
        r["checks"] = [c for c in r["checks"]
                       if c["name"].split("/")[-1] in OPEN] if want_open else \
            [c for c in r["checks"] if c["name"].split("/")[-1] not in OPEN]
    return r


@pytest.mark.xdist_group(TUTORIAL)
def test_shallow_ironing():
    ck = harness.Checks()
    ck.run(_split(_run(), False), TUTORIAL)
    ck.verify()


@pytest.mark.xdist_group(TUTORIAL)
@pytest.mark.xfail(strict=True, reason="the die's horizontal force jumps between two "
                   "states of the faces at its leading corner (docs/tutorials.md)")
def test_shallow_ironing_smooth_sliding():
    ck = harness.Checks()
    r = _split(_run(), True)
    if r["rc"] != 0 or r["checks"] is None:
        pytest.fail("Allrun failed, see %s" % r["case"])
    ck.add_checks(r["checks"])
    ck.verify()
