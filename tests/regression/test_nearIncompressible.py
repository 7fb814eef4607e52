"""Near-incompressible bodies and stabilisationScale (docs/solver.md,
"Near-incompressible bodies"): the discrete equations' smoothing term
s K [laplacian(D) - div((grad D)_f)] with K = 2 mu + lambda over-smooths a
body whose K is many times its shear modulus. Against closed forms no one
here wrote: Hertz (hertzCylinder, plane strain, nu = 0.49 in both bodies)
and Kirsch (plateHole in plane strain, nu = 0.45; its stress does not
depend on the elastic constants). Each with the default s = 1 and with
s = 0.1: the closed form's own tolerances (the tutorials' validation
scripts) must hold with 0.1, and the default's error must be at least twice
as large, or the option no longer does what its documentation says."""
import pytest

import harness
from c4fpost import foamio

HERTZ_NU = 0.49
KIRSCH_NU = 0.45
SCALE = 0.1
# Measured (2026-12-07): hertzCylinder nu = 0.49 p0 10.6 % off Hertz with
# s = 1, 1.9 % with 0.1 (5.5x), a 0.62 and 0.21 mm off (2.9x); plateHole
# nu = 0.45 in plane strain sigma_xx 15.1 % off Kirsch along the symmetry
# line with s = 1, 5.3 % with 0.1 (2.8x; 4.1 % at nu = 0.3 with s = 1, the
# mesh's own error). At least this factor between the two errors
IMPROVEMENT = 2.0


def set_nu(nu, plane_strain=False):
    """A case edit: nu in every law (c4fpost.foamio.set_poisson_ratio),
    plane strain where asked."""
    def edit(case):
        foamio.set_poisson_ratio(case, nu, plane_strain)
    return edit


def runs(tutorial, nu, plane_strain=False):
    base = "%s_nu%g" % (tutorial, nu)
    default = harness.tutorial_run(tutorial, base, edit=set_nu(nu, plane_strain))
    scaled = harness.tutorial_run(tutorial, base + "_stabilisation%g" % SCALE,
                                  edit=set_nu(nu, plane_strain),
                                  controls="stabilisationScale %g;" % SCALE)
    return base, default, scaled


def check_pair(ck, base, default, scaled, names):
    """The scaled run's closed-form checks `names` pass; each default
    error is at least IMPROVEMENT times the scaled one."""
    for r in (default, scaled):
        harness.need(r)
    ck.steps_converged(default["case"], base)
    ck.steps_converged(scaled["case"], base + "_stabilisation")
    by = [{c["name"].split("/")[-1]: c for c in r["checks"]} for r in (default, scaled)]
    for name in names:
        d, s = by[0][name], by[1][name]
        ck.add("%s_stabilisation%g/%s" % (base, SCALE, name), s["passed"], s["value"],
               s["reference"], s["error"], s["tolerance"])
        ratio = d["error"] / max(s["error"], 1e-300)
        ck.add("%s/%s_default_over_scaled" % (base, name), ratio >= IMPROVEMENT, ratio,
               IMPROVEMENT, ratio, IMPROVEMENT,
               note="(error with s = 1: %.4g, with s = %g: %.4g)" % (d["error"], SCALE,
                                                                    s["error"]))


@pytest.mark.xdist_group("nearIncompressibleHertz")
def test_hertz_cylinder_nu049():
    ck = harness.Checks()
    base, default, scaled = runs("hertzCylinder", HERTZ_NU)
    check_pair(ck, base, default, scaled, ("peak_pressure", "contact_half_width"))
    ck.verify()


@pytest.mark.xdist_group("nearIncompressibleKirsch")
def test_plate_hole_plane_strain_nu045():
    ck = harness.Checks()
    base, default, scaled = runs("plateHole", KIRSCH_NU, plane_strain=True)
    check_pair(ck, base, default, scaled,
               ("sxx_symmetry_line_max_error", "peak_sxx_first_cell"))
    ck.verify()
