"""Near-incompressible bodies and stabilisationScale (docs/solver.md,
"Near-incompressible bodies"): the discrete equations' smoothing term
s K [laplacian(D) - div((grad D)_f)] with K = 2 mu + lambda over-smooths a
body whose K is many times its shear modulus. Against closed forms no one
here wrote: Hertz (hertzCylinder, plane strain, nu = 0.49 in both bodies)
and Kirsch (plateHole in plane strain, nu = 0.45; its stress does not
depend on the elastic constants). Each with the default s = 1 and with
s = 0.1: the closed form's own tolerances (the tutorials' validation
scripts) must hold with 0.1, and the default's error must be at least twice
as large, or the option no longer does what its documentation says.

In 3D the segregated corrector itself grew the volumetric mode of a body
loaded by tractions above nu = 1/3 (outerCorrectorRelaxation, docs/
solver.md): the 3D contact patch test (exact to 1e-6) and hertzSphere
(Hertz, with the default s and with 0.1) at nu = 0.45 must converge, and
without the relaxation the patch test must diverge, or the relaxation is
no longer what holds it."""
import os
import re

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


SPHERE_NU = 0.45
PATCH_NU = 0.45


@pytest.mark.xdist_group("nearIncompressibleSphere")
def test_hertz_sphere_nu045():
    """3D: diverged at corrector 95 with s = 1 before the relaxation
    (2026-12-07). Measured after: 103 correctors, p_max 8.7 % off Hertz, RMS
    6.2 % of p0 with s = 1; 233 correctors, 0.87 % and 1.27 % with 0.1."""
    ck = harness.Checks()
    base, default, scaled = runs("hertzSphere", SPHERE_NU)
    check_pair(ck, base, default, scaled, ("peak_pressure", "pressure_rms"))
    log = open(os.path.join(default["case"], "log.solidContactFoam")).read()
    m = re.search(r"^Outer correctors relaxed by (\S+):", log, flags=re.M)
    # omega = (5/3)(1 - nu)/(1 + nu) for isotropic elasticity in 3D
    omega = 5.0 / 3.0 * (1 - SPHERE_NU) / (1 + SPHERE_NU)
    value = float(m.group(1)) if m else float("nan")
    ck.add("%s/relaxation" % base, m is not None and abs(value - omega) < 1e-9,
           value, omega, abs(value - omega), 1e-9)
    ck.verify()


def unrelaxed_plain(case):
    """relaxationFactors for D of 1 (the case's own factor: the corrector
    as it was before outerCorrectorRelaxation); the caller also turns the
    acceleration off."""
    with open(os.path.join(case, "system", "fvSolution"), "a") as f:
        f.write("\nrelaxationFactors\n{\n    fields\n    {\n        D 1;\n    }\n}\n")


@pytest.mark.xdist_group("nearIncompressiblePatch3D")
def test_patch_test_3d_nu045():
    """The 3D contact patch test with nu = 0.45, straight and rotated: every
    check of the tutorial (the uniform stress to 1e-6) after 104 and 143
    correctors (2026-12-07; it diverged at corrector 2971 before). The
    control, the plain unrelaxed corrector, diverged at corrector 27 with
    the divergence check's FatalError: it must still fail, in fewer than
    200 correctors."""
    ck = harness.Checks()
    nu = ("-nu", "%g" % PATCH_NU)
    for name, args in (("contactPatchTest3D_nu045", nu),
                       ("contactPatchTest3D_rotated_nu045", nu + ("-rotate",))):
        ck.run(harness.tutorial_run("contactPatchTest3D", name, args=args), name)

    name = "contactPatchTest3D_nu045_unrelaxed"
    r = harness.tutorial_run("contactPatchTest3D", name, args=nu, edit=unrelaxed_plain,
                             controls="acceleration none;")
    log = os.path.join(r["case"], "log.solidContactFoam")
    text = open(log).read() if os.path.exists(log) else ""
    m = re.search(r"corrector (\d+): the outer correctors diverged", text)
    ck.add("%s/diverges" % name, r["rc"] != 0 and m is not None and int(m.group(1)) < 200,
           note="(rc=%d, %s)" % (r["rc"], "corrector " + m.group(1) if m else
                                 "no divergence in " + log))
    ck.verify()
