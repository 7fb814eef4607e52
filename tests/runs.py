"""The tutorial runs several tests read (each made once per session by
harness.tutorial_run; the test that owns a run asserts its own checks)."""
import os
import re

import harness
from c4fpost import methods

# The reference of the exact methods: the Lagrange multiplier
LM = "lagrangeMultiplier"

# The reference of the penalty family (a regularised multiplier converges
# to its state): the plain penalty. A reference is a method by name, not a
# list of facts: any other method is checked by its traits
PENALTY = "penalty"


def is_barrier(method):
    return methods.table()[method].answer == "barrier"


def verbose_for(method):
    """The barrier's runs print every corrector's smallest gap."""
    return "verbose yes;" if is_barrier(method) else ""


def plate_hole():
    return harness.tutorial_run("plateHole", "plateHole")


def hertz(method):
    """hertzCylinder -method `method`."""
    return harness.tutorial_run("hertzCylinder", "hertzCylinder_" + method,
                                ["-method", method], controls=verbose_for(method))


def hertz_parallel(method):
    """hertzCylinder -method `method` -parallel (the lagrangeMultiplier run
    is hertzCylinderParallel)."""
    name = "hertzCylinderParallel" + ("" if method == LM else "_" + method)
    return name, harness.tutorial_run("hertzCylinder", name, ["-method", method, "-parallel"],
                                      controls=verbose_for(method))


def patch(method):
    """contactPatchTest -method `method`."""
    return harness.tutorial_run("contactPatchTest", "contactPatchTest_" + method,
                                ["-method", method], controls=verbose_for(method))


def barrier_kappa_update(method):
    """The barrier with kappaScale 0.01 (verbose): (name, run)."""
    name = "contactPatchTest_%s_kappaUpdate" % method
    return name, harness.tutorial_run(
        "contactPatchTest", name, ["-method", method], controls="verbose yes;",
        edit=lambda case: methods.set_coeff(case, method, "kappaScale", "0.01"))


def steel_aluminium(method):
    return harness.tutorial_run("hertzCylinder", "hertzCylinder_steelAluminium_" + method,
                                ["-method", method, "-materials", "steelAluminium"])


def near_rigid(method, slave):
    """hertzCylinder -materials nearRigidCylinder -slave block|cylinder."""
    return harness.tutorial_run(
        "hertzCylinder", "hertzCylinder_nearRigid_%sSlave_%s" % (slave, method),
        ["-method", method, "-materials", "nearRigidCylinder", "-slave", slave])


def sphere():
    return harness.tutorial_run("hertzSphere", "hertzSphere_" + LM, ["-method", LM])


def cattaneo(method):
    return harness.tutorial_run("cattaneoMindlin", "cattaneoMindlin_" + method,
                                ["-method", method])


def bimaterial_bar(parallel=False):
    """tests/regression/cases/bimaterialBar (serial, or decomposed in two
    meeting at the interface): dict(case, rc)."""
    import os
    import shutil
    name = "bimaterialBarParallel" if parallel else "bimaterialBar"

    def make():
        case = os.path.join(harness.WORK, name)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(harness.ROOT, "tests/regression/cases/bimaterialBar"),
                        case)
        rc, _ = harness.run(["blockMesh"], cwd=case, log=os.path.join(case, "log.blockMesh"))
        if parallel and not rc:
            rc, _ = harness.run(["decomposePar"], cwd=case,
                                log=os.path.join(case, "log.decomposePar"))
            if not rc:
                rc, _ = harness.run(["mpirun", "-np", "2", harness.SOLVER, "-parallel"],
                                    cwd=case, log=os.path.join(case, "log.solidContactFoam"))
            if not rc:
                rc, _ = harness.run(["reconstructPar", "-latestTime"], cwd=case,
                                    log=os.path.join(case, "log.reconstructPar"))
        elif not rc:
            rc, _ = harness.run([harness.SOLVER], cwd=case,
                                log=os.path.join(case, "log.solidContactFoam"))
        if not os.path.isdir(os.path.join(case, "1")):
            rc = rc or 1
        return dict(case=case, rc=rc)
    return harness.once(name, make)


def bimaterial_checks(ck, case, name):
    """Steel (x < 0.4 m, 10 x 3 cells of 0.04 m) and an aluminium-like part
    (x > 0.4 m, 10 x 3 cells of 0.06 m) in series, plane stress, end
    traction T = 1e7 Pa, one mesh with a zoned law. nu/E is the same in both
    parts, so the exact state is uniaxial stress with both parts' lateral
    strains equal: sigma_xx = T everywhere (sigma_yy = sigma_xy = 0) and
    eps_xx = T/E_i, a displacement linear in each part, which the bonded
    interface treatment reproduces exactly. The tolerance 1e-6 is the
    issue's; what is left is the outer correctors' 1e-9 residual (measured
    2e-8). Without the interface treatment (linear interpolation across the
    interface) sigma_xx is 64 % off next to it and eps_xx 2.8 %.
    eps_xx is measured from D of neighbouring cell centres of one part,
    eps_yy from D_y over the rows."""
    import os
    import numpy as np
    from c4fpost import foamio
    T, tol = 1e7, 1e-6
    sig = foamio.read_internal(os.path.join(case, "1", "sigma"))
    D = foamio.read_internal(os.path.join(case, "1", "D"))
    err = float(np.abs(sig[:, 0] - T).max() / T)
    ck.add(name + "/sigma_xx_uniform", err <= tol, float(sig[:, 0].mean()), T, err, tol)
    err = float(np.abs(sig[:, [1, 2, 3]]).max() / T)
    ck.add(name + "/sigma_xy_yy_zero", err <= tol, err, 0.0, err, tol)
    # Cell order of blockMesh: block by block, x fastest
    for b, (part, E, nu, h) in enumerate((("steel", 210e9, 0.3, 0.04),
                                          ("aluminium", 70e9, 0.1, 0.06))):
        Db = D[30 * b:30 * (b + 1)].reshape(3, 10, 3)
        exx = np.diff(Db[:, :, 0], axis=1) / h
        ref = T / E
        err = float(np.abs(exx - ref).max() / ref)
        ck.add("%s/eps_xx_%s" % (name, part), err <= tol, float(exx.mean()), ref, err, tol)
        eyy = np.diff(Db[:, :, 1], axis=0) / (0.1 / 3)
        ref = -nu * T / E
        err = float(np.abs(eyy - ref).max() / abs(ref))
        ck.add("%s/eps_yy_%s" % (name, part), err <= tol, float(eyy.mean()), ref, err, tol)


def rigid_sphere(method, surface="sphere", parallel=False):
    """rigidSphere -method `method` [-surface triSurface] [-parallel]: a
    rigid sphere (no mesh) on the block."""
    name = "rigidSphere_" + method + ("" if surface == "sphere" else "_" + surface) \
        + ("_parallel" if parallel else "")
    args = ["-method", method] + ([] if surface == "sphere" else ["-surface", surface]) \
        + (["-parallel"] if parallel else [])
    return harness.tutorial_run("rigidSphere", name, args)


def rigid_punch(method, parallel=False):
    """rigidPunch -method `method` [-parallel]: Sneddon's rigid flat punch
    (an STL, no mesh) on the block."""
    return harness.tutorial_run("rigidPunch",
                                "rigidPunch_" + method + ("_parallel" if parallel else ""),
                                ["-method", method] + (["-parallel"] if parallel else []))


def hertz_sphere_variant(sphere):
    """hertzSphere -sphere stiff|rigid (LM): the sphere 1000 times stiffer
    than the block, or a rigid sphere (a rigidSurface) in its place."""
    return harness.tutorial_run("hertzSphere", "hertzSphere_%s_%s" % (LM, sphere),
                                ["-method", LM, "-sphere", sphere])


def self_contact_strip(method, parallel=False, friction=None, finite=False,
                       two_patches=False):
    """selfContactStrip -method `method` [-parallel] [-friction f]
    [-finiteStrain]: the C-shaped strip closing its slot, one patch its
    own master; two_patches: the same strip with the slot's roof (slave)
    and floor (master) as a two-patch pair, every other face of the strip
    traction-free (the self-contact's reference)."""
    name = "selfContactStrip_" + method
    args = ["-method", method]
    if friction:
        name += "_" + friction
        args += ["-friction", friction]
    if finite:
        name += "_finiteStrain"
        args += ["-finiteStrain"]
    if parallel:
        name += "_parallel"
        args += ["-parallel"]
    edit = None
    if two_patches:
        name += "_twoPatches"
        edit = lambda case: strip_as_two_patches(case, method, friction or "frictionless")
    return harness.tutorial_run("selfContactStrip", name, args, edit=edit)


def strip_as_two_patches(case, method, friction):
    """selfContactStrip's copy `case` with the slot's roof and floor taken
    out of the patch strip as the pair roof (slave) / floor (master)."""
    bm = os.path.join(case, "system", "blockMeshDict")
    s = open(bm).read()
    for face in ("(4 18 19 5)", "(7 21 22 8)", "(8 22 23 9)"):
        s = re.sub(r"\n\s*%s[^\n]*" % re.escape(face), "", s, count=1)
    s = s.replace("    frontAndBack\n", "    floor { type wall; faces ((4 18 19 5)); }\n"
                  "    roof { type wall; faces ((7 21 22 8) (8 22 23 9)); }\n"
                  "    frontAndBack\n", 1)
    open(bm, "w").write(s)
    d = os.path.join(case, "0", "D")
    s = open(d).read()
    roof = ("    roof\n    {\n        type solidContact;\n        shadowPatch floor;\n"
            "        master no;\n        method %s;\n        friction %s;\n"
            "        coulombCoeffs { mu 0.3; }\n"
            "        constitutiveLawCoeffs { cN 1e21; n 2; }\n"
            "        searchDistance 0.005;\n        value uniform (0 0 0);\n    }\n"
            "    floor\n    {\n        type solidContact;\n        shadowPatch roof;\n"
            "        master yes;\n        value uniform (0 0 0);\n    }\n"
            % (method, friction))
    s = re.sub(r"    strip\n    \{.*?\n    \}\n",
               "    strip\n    {\n        type solidTraction;\n        traction constant (0 0 0);\n"
               "        pressure constant 0;\n        value uniform (0 0 0);\n    }\n" + roof,
               s, count=1, flags=re.S)
    open(d, "w").write(s)
