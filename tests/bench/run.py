#!/usr/bin/python3
"""contact4foam benchmarks (`make bench`). Prints ratios measured side by
side in this one run; nothing here is asserted.

Convergence: one table of the outer correctors, the wall time per load step
and whether the step converged, for each case and problem with the plain
iteration (acceleration none) and the accelerated default (Anderson,
andersonDepth 15). The cases: plateHole (no contact), hertzCylinder on the
default mesh and at 4x the cells (every cell count of blockMeshDict times
2, what its Allrun's -refine 2 does) and the four contactPatchTest3D
variants (axis-aligned, -rotate, -nu 0.3, both), and hertzCylinder with a
near-rigid cylinder (1000 x the block's E) with each body as the slave,
whose correctors are also given over the equal-material case's. The
problems: the contact-
free equivalent, the Lagrange multiplier and the penalty method; each
contact row gives its correctors over those of its contact-free equivalent
with the same iteration, the segregated solver's floor for that mesh.
hertzCylinder's contact-free equivalent is built from the converged
Lagrange multiplier run (c4fpost.contactfree: the slave's displacement and
the master's traction prescribed), contactPatchTest3D's is its Allrun's
-noContact (the exact state prescribed). Every run is capped at 5000
correctors with onNonConvergence continue, so a stall is reported. The
table is also written as markdown to $C4F_PREFIX/run/bench/convergence.md.

hertzCylinder accuracy: the peak-pressure and half-width errors against
Hertz on the coarse (half the cell counts), the default and the refined
mesh; and the contact update time (search, method, transfer), per
corrector and as a share of the solver's wall time, with the search tree
rebuilt every corrector against reused until the master has moved 0.1 mm.

plateHole refinement: the Kirsch error at the hole and the whole-field L2
error for four meshes (each level halves the cell size), the observed
order between levels, the correctors and the wall time per level, and the
serial/parallel wall-time ratio on the finest mesh.

Uzawa (augmentedLagrange on hertzCylinder, multiplierUpdate converged):
the max penetration over h and the relative multiplier change per
multiplier update, falling geometrically, and the updates and correctors
for three penalty scales; then the multiplier family's correctors against
the Lagrange multiplier's on hertzCylinder, hertzSphere and the rotated 3D
patch test, each method with its default multiplierUpdate and with
`converged` (`run.py --only uzawa` runs this part alone).

Roles (`run.py --only roles`, issue 25): hertzCylinder with the near-rigid
cylinder, the block or the cylinder the slave, for the Lagrange
multiplier, the penalty and the methods with stored multipliers at two
mesh levels: each body's p_max and a with either role, the penetration
the constraint leaves, the correctors; markdown in roles.md.

perturbedLagrange on contactPatchTest for penaltyScale 10, 100 and 1000:
the stress error against the Lagrange multiplier answer, falling like
1/eps, the difference to the penalty run with the same eps, and the
multiplier updates and correctors (`run.py --only perturbedLagrange`).

Every method side by side (`run.py --only methods`): each method of
`solidContactFoam -listMethods` on hertzCylinder (correctors, wall time,
p0 and a errors, max penetration or min gap, multiplier updates) and
contactPatchTest (correctors, wall time, stress error against the exact
stress), and the exact methods on hertzSphere at two mesh levels (10 and
15 faces across a); markdown in methods.md, a bar chart in methods.png.

Friction side by side (`run.py --only friction`, issue 10): cattaneoMindlin
at -refine 1 and 2 for lagrangeMultiplier, augmentedLagrange and penalty
(correctors per step, wall time, Q'/(mu P'), the stick-zone half-width and
the RMS of q against Cattaneo-Mindlin, also at t = 1 where it should be
0), slidingBlock with coulomb for every method (F_T/(mu F_N) - 1 in full
slip; a method without a slip law is listed as refused) and the stick
patch test for every method (correctors, stress error); markdown in
friction.md, q's RMS against the faces across a in friction.png.

Finite deformation (`run.py --only finiteStrain`, issue 22):
finiteStrainCylinder's force on its mesh (the Lagrange multiplier and the
barrier) and at -refine 2 against a CalculiX curve made in this run
(validation/calculix.py; the stored one without ccx), and
finiteStrainPatchTest's correctors for nu 0.3, 0.4 and 0.45 (and the
barrier at 0.3).

Large sliding (`run.py --only ironing`, issue 22): shallowIroning at
-refine 1 and 1.5: the die's forces at t = 1 and 1.5, the friction ratio at
1.5, the peak-to-peak of H over the steady part, correctors per step and
wall time (compareIroning.py's numbers).

GAMG (`run.py --only gamg`, issue 24): hertzCylinder at -refine 1, 2 and
4 and hertzSphere, the Lagrange multiplier with the contact coupling on
GAMG's coarse levels (the default) and on the finest only, against two
contact-free equivalents of the converged run: correctors, linear
iterations per corrector, wall time and their ratios, and the wall ratios
again as the median of GAMG_ROUNDS paired re-runs; markdown in gamg.md.

Rigid tools and self-contact (`run.py --only rigid`, issue 23):
rigidPunch at -refine 0.67, 1 and 1.33 (10, 15 and 20 faces across a:
the force against Sneddon's at each step, correctors, wall time) and selfContactStrip at -refine 1, 2 and 4 (the
force across the slot against CalculiX's at each contact step, its
error in % of the force; correctors and wall time side by side with the
same strip as a two-patch pair, roof and floor, on the same mesh).

The big case (`run.py --only big`, issue 24): hertzSphere at about 1e6
cells, serial and on 2 processors: wall time per corrector, linear
iterations, the contact update's share, memory per process, the master
faces each processor holds, the strong-scaling efficiency; big.md.

Newton-Krylov against the segregated loop (`run.py --only newton`, issue
26): each case run with the segregated loop as the tutorial sets it
(Anderson, or the plain iteration on shallowIroning) and with
`-algorithm newtonKrylov`, one after the other:
correctors (for Newton, every product is one), Newton steps per load
step (mean and largest), linear iterations, wall time per load step and
its ratio, and the normal force's relative difference between the two;
hertzCylinder at -refine 1 and 2, the same with nu = 0.49 in both bodies,
hertzSphere, hertzSphereTets, contactPatchTest, finiteStrainPatchTest
(frictionless and with Coulomb), shallowIroning (Coulomb under finite
deformation, 100 steps; dF_N at its last), rigidSphere and rigidPunch
(rigid tools; Newton solves with GAMG where the tutorial has PCG);
markdown in newton.md.

Near-incompressible bodies (`run.py --only stabilisation`): hertzCylinder
(LM, nu in both bodies), plateHole in plane strain (Kirsch) and hertzSphere
(3D, where above nu = 1/3 the solver relaxes its correctors) at three
Poisson's ratios, each with stabilisationScale 1 (the default), 0.3 and
0.1: the errors against the closed form and the correctors; markdown in
stabilisation.md.

The proximity search (CGAL AABB tree, brute force, OpenFOAM's
indexedOctree) has its own benchmark, tests/bench/searchBench.py.
"""
import importlib
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "src/postProcessing/python"))
sys.path.insert(0, os.path.join(ROOT, "tutorials/plateHole/validation"))
sys.path.insert(0, os.path.join(ROOT, "tutorials/hertzCylinder/validation"))
sys.path.insert(0, os.path.join(ROOT, "tutorials/contactPatchTest/validation"))
sys.path.insert(0, os.path.join(ROOT, "tutorials/hertzSphere/validation"))

import numpy as np  # noqa: E402
from c4fpost import blockmesh, contactfree, contactreport, foamio, kirsch, methods  # noqa: E402
import compareHertz  # noqa: E402
import compareKirsch  # noqa: E402
import compareSphere  # noqa: E402

PREFIX = os.environ.get("C4F_PREFIX", os.path.expanduser("~/.contact4foam"))
WORK = os.path.join(PREFIX, "run", "bench")
SOLVER = "solidContactFoam"

# The outer-corrector settings of the convergence runs: a stall is a row
# with converged = no, not a stopped bench
CAPPED = {"nCorrectors": "5000", "onNonConvergence": "continue"}
ITERATIONS = (("plain", dict(CAPPED, acceleration="none")),
              ("accelerated", CAPPED))            # the default: anderson, depth 15
# The methods come from the solver's selection table (c4fpost.methods):
# the references: the exact methods' (the Lagrange multiplier) and the
# penalty family's (the plain penalty)
LM = "lagrangeMultiplier"
PENALTY = "penalty"
PROBLEMS = ("contact-free", LM, PENALTY)
# The near-rigid indenter's cases: (label, Allrun arguments)
NEAR_RIGID = tuple(("hertzCylinder nearRigidCylinder -slave " + slave,
                    ("-materials", "nearRigidCylinder", "-slave", slave))
                   for slave in ("block", "cylinder"))


def sh(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, shell=True, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, stdin=subprocess.DEVNULL)
    if p.returncode:
        sys.exit("bench: '%s' failed in %s\n%s" % (cmd, cwd, p.stdout[-2000:]))
    return p.stdout


def set_solid_mechanics(case, entries):
    """Set `entries` (keyword: value) in the solidMechanics dictionary of
    system/fvSolution: an entry already there is replaced, others added."""
    fvs = os.path.join(case, "system/fvSolution")
    text = open(fvs).read()
    m = re.search(r"^solidMechanics\s*\{(.*?)^\}", text, flags=re.M | re.S)
    if m is None:
        sys.exit("bench: no solidMechanics dictionary in " + fvs)
    body = m.group(1)
    for key, value in entries.items():
        body, n = re.subn(r"^(\s*)%s\s+[^;]*;" % key, r"\g<1>%s %s;" % (key, value), body,
                          flags=re.M)
        if n == 0:
            body += "    %s %s;\n" % (key, value)
    open(fvs, "w").write(text[:m.start(1)] + body + text[m.end(1):])


def timed_solver_dir():
    """A directory with a `solidContactFoam` that runs the real one and
    writes its wall time (time.time() around it) and exit code to
    wall.solidContactFoam in the case: put first on PATH, it times the
    solver run that a tutorial's Allrun starts, and nothing else (the
    Allruns also ask the solver for its tables, -listMethods and
    -listFrictionModels, which are not timed)."""
    d = os.path.join(WORK, "timedSolver")
    os.makedirs(d, exist_ok=True)
    real = shutil.which(SOLVER)
    if real is None:
        sys.exit("bench: %s not found; source etc/bashrc and build first" % SOLVER)
    exe = os.path.join(d, SOLVER)
    with open(exe, "w") as f:
        f.write("#!/usr/bin/python3\n"
                "import os, subprocess, sys, time\n"
                "if any(a.startswith('-list') for a in sys.argv[1:]):\n"
                "    os.execv(%r, [%r] + sys.argv[1:])\n"
                "import resource\n"
                "t0 = time.time()\n"
                "rc = subprocess.call([%r] + sys.argv[1:])\n"
                "with open('wall.%s', 'w') as f:\n"
                "    f.write('%%.6f %%d\\n' %% (time.time() - t0, rc))\n"
                "with open('mem.%s', 'a') as f:\n"
                "    f.write('%%s %%d\\n' %% (os.environ.get('OMPI_COMM_WORLD_RANK', '0'),\n"
                "            resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss))\n"
                "sys.exit(rc)\n" % (real, real, real, SOLVER, SOLVER))
    os.chmod(exe, 0o755)
    return d


def bench_case(name, src, entries=None, prepare=None, allrun=None, parallel=False,
               require=False, edit=None):
    """One solver run on a fresh copy of `src` (a tutorial, or a case run
    before) in WORK/name: `entries` set in solidMechanics, then either
    prepare(case) sets it up (mesh included) and the solver runs here, or
    its Allrun runs with the arguments `allrun` (the solver through the
    timing wrapper). The wall time is the solver's alone. Returns the case,
    the wall time per load step, the correctors (summed over the steps),
    whether every step converged, and the last step's residual and contact
    update time (None without contact). With `require` a failed or
    unconverged run stops the bench."""
    case = os.path.join(WORK, name)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(src, case, ignore=shutil.ignore_patterns(
        "[1-9]*", "processor*", "log.*", "VTK", "postProcessing", "*.png", "checks.json",
        "wall." + SOLVER, "mem." + SOLVER))
    if entries:
        set_solid_mechanics(case, entries)
    if edit is not None:
        edit(case)
    logfile = os.path.join(case, "log." + SOLVER)
    if allrun is not None:
        env = dict(os.environ, PATH=timed_solver_dir() + os.pathsep + os.environ["PATH"])
        with open(os.path.join(case, "log.Allrun"), "w") as f:
            subprocess.run(["./Allrun"] + list(allrun), cwd=case, env=env, stdout=f,
                           stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        try:
            wall, rc = open(os.path.join(case, "wall." + SOLVER)).read().split()
            wall, rc = float(wall), int(rc)
        except (OSError, ValueError):
            wall, rc = float("nan"), -1          # Allrun stopped before the solver
    else:
        if prepare is not None:
            prepare(case)
        cmd = [SOLVER]
        if parallel:
            sh("decomposePar", case)
            cmd = ["mpirun", "-np", "2", SOLVER, "-parallel"]
        with open(logfile, "w") as f:
            t0 = time.time()
            rc = subprocess.run(cmd, cwd=case, stdout=f, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL).returncode
            wall = time.time() - t0
        if parallel and rc == 0:
            sh("reconstructPar -latestTime", case)
    log = open(logfile).read() if os.path.exists(logfile) else ""
    steps = re.findall(r"^Time = \S+\s+correctors = (\d+)\s+residual = (\S+)(.*)$", log, flags=re.M)
    converged = (rc == 0 and bool(steps) and not any("NOT CONVERGED" in s[2] for s in steps)
                 and re.search(r"^End\s*$", log, flags=re.M) is not None)
    if require and not converged:
        sys.exit("bench: %s did not converge (rc=%d), see %s" % (name, rc, logfile))
    contact = re.search(r"contactTime = (\S+)", steps[-1][2]) if steps else None
    search = re.search(r"searchTime = (\S+)", steps[-1][2]) if steps else None
    linear = re.findall(r"^\s+linear solver: (\d+) iterations", log, flags=re.M)
    return dict(name=name, case=case, rc=rc, converged=converged, steps=len(steps),
                linear=sum(int(n) for n in linear) if linear else None,
                ncorr=sum(int(s[0]) for s in steps) if steps else None,
                residual=float(steps[-1][1]) if steps else None,
                wall=wall, wall_step=wall / max(1, len(steps)),
                contact=float(contact.group(1)) if contact else None,
                search=float(search.group(1)) if search else None)


# --------------------------------------------------------------------------
def hertz_prepare(level=1.0, method="lagrangeMultiplier", rebuild=None):
    """Set up the hertzCylinder tutorial: every cell count of blockMeshDict
    scaled by `level` (2: what its Allrun's -refine 2 does), the contact
    method (and the search tree's rebuild tolerance), blockMesh."""
    def prepare(case):
        blockmesh.scale_block_mesh(os.path.join(case, "system/blockMeshDict"), level)
        d = os.path.join(case, "0/D")
        text = open(d).read()
        text = re.sub(r"^(\s*method\s+)\w+;", r"\g<1>%s;" % method, text, flags=re.M)
        if rebuild is not None:
            text = re.sub(r"^(\s*method\s+\w+;)", r"\1 rebuildTolerance %g;" % rebuild, text,
                          flags=re.M)
        open(d, "w").write(text)
        sh("blockMesh", case)
    return prepare


def contact_free_prepare(contact, slave="cylinderContact", master="blockContact",
                         slave_traction=False):
    """The contact-free equivalent of the converged contact run `contact`
    (hertzCylinder's patches by default; copied with its mesh): its
    converged time brought in and turned into 0/D by c4fpost.contactfree,
    the slave held by its displacement or (slave_traction) its traction."""
    def prepare(case):
        t = foamio.latest_time(contact)
        shutil.copytree(os.path.join(contact, t), os.path.join(case, t))
        contactfree.make_contact_free(case, t, slave, master, slave_traction=slave_traction)
    return prepare


def hertz_accuracy(r):
    res = compareHertz.compare(r["case"])
    checks = {c["name"].split("/")[-1]: c for c in res["checks"]}
    cells = re.search(r"^\s*cells:\s+(\d+)", sh("checkMesh -constant", r["case"]), flags=re.M)
    return dict(r, cells=int(cells.group(1)), p0=checks["peak_pressure"]["error"],
                a=checks["contact_half_width"]["error"])


def convergence_rows():
    """Run every case x problem x iteration of the convergence table;
    returns the rows in table order and the runs by key."""
    runs = {}
    tut = os.path.join(ROOT, "tutorials")
    cases = []

    print("convergence runs:", flush=True)

    def note(key, r):
        runs[key] = r
        if r is None:
            state = "not run"
        else:
            state = "%s correctors, %.2f s" % (r["ncorr"], r["wall"])
            if not r["converged"]:
                state += ", NOT CONVERGED (rc=%d)" % r["rc"]
        print("  %-30s %-18s %-11s %s" % (key + (state,)), flush=True)

    # plateHole: no contact
    label = "plateHole"
    cases.append((label, ("contact-free",)))
    for it, entries in ITERATIONS:
        note((label, "contact-free", it),
             bench_case("conv_plateHole_" + it, os.path.join(tut, "plateHole"), entries,
                        prepare=lambda case: sh("blockMesh", case)))

    # hertzCylinder: the contact-free equivalent from the converged LM run
    for level, label in ((1, "hertzCylinder"), (2, "hertzCylinder -refine 2")):
        cases.append((label, PROBLEMS))
        tag = "hertz" if level == 1 else "hertz_refine%d" % level
        for it, entries in ITERATIONS:
            for method in PROBLEMS[1:]:
                note((label, method, it),
                     bench_case("conv_%s_%s_%s" % (tag, method, it),
                                os.path.join(tut, "hertzCylinder"), entries,
                                prepare=hertz_prepare(level, method)))
            lm = runs[(label, "lagrangeMultiplier", it)]
            note((label, "contact-free", it),
                 bench_case("conv_%s_contactFree_%s" % (tag, it), lm["case"], entries,
                            prepare=contact_free_prepare(lm["case"]))
                 if lm["converged"] else None)

    # hertzCylinder with a near-rigid cylinder (1000 x the aluminium
    # block's E), each body as the slave: correctors against the equal-
    # material (steel) rows above
    for label, args in NEAR_RIGID:
        cases.append((label, PROBLEMS[1:]))
        tag = label.split()[-1]
        for it, entries in ITERATIONS:
            for method in PROBLEMS[1:]:
                note((label, method, it),
                     bench_case("conv_hertz_nearRigid_%s_%s_%s" % (tag, method, it),
                                os.path.join(tut, "hertzCylinder"), entries,
                                allrun=list(args) + ["-method", method]))

    # contactPatchTest3D: -noContact prescribes the exact state
    for variant in ((), ("-rotate",), ("-nu", "0.3"), ("-rotate", "-nu", "0.3")):
        label = " ".join(("contactPatchTest3D",) + variant)
        cases.append((label, PROBLEMS))
        tag = "".join("_" + o.lstrip("-").replace(".", "") for o in variant)
        for problem in PROBLEMS:
            args = ["-noContact"] if problem == "contact-free" else ["-method", problem]
            for it, entries in ITERATIONS:
                note((label, problem, it),
                     bench_case("conv_patch3d%s_%s_%s" % (tag, problem, it),
                                os.path.join(tut, "contactPatchTest3D"), entries,
                                allrun=args + list(variant)))

    rows = []
    for label, problems in cases:
        for problem in problems:
            for it, _ in ITERATIONS:
                r = runs.get((label, problem, it))
                free = runs.get((label, "contact-free", it))
                ratio = ""
                if problem != "contact-free":
                    ratio = ("%.2f" % (r["ncorr"] / free["ncorr"])
                             if r and free and r["ncorr"] and free["ncorr"] else "n/a")
                # The near-rigid indenter against the same problem with
                # like materials
                equal = ""
                if label in dict(NEAR_RIGID):
                    ratio = ""
                    same = runs.get(("hertzCylinder", problem, it))
                    equal = ("%.2f" % (r["ncorr"] / same["ncorr"])
                             if r and same and r["ncorr"] and same["ncorr"] else "n/a")
                if r is None:
                    rows.append((label, problem, it, "-", "-", "not run", ratio, equal))
                else:
                    rows.append((label, problem, it,
                                 "-" if r["ncorr"] is None else "%d" % r["ncorr"],
                                 "%.3f" % r["wall_step"],
                                 "yes" if r["converged"] else "no", ratio, equal))
    return rows, runs


def convergence_table(rows, runs):
    head = ("case", "problem", "iteration", "correctors", "wall time per step [s]",
            "converged", "correctors / contact-free", "correctors / equal materials")
    widths = [max(len(x[i]) for x in (head,) + tuple(rows)) for i in range(len(head))]

    def line(cells):
        return "| " + " | ".join(c.ljust(w) for c, w in zip(cells, widths)) + " |"
    lines = [line(head), "|" + "|".join("-" * (w + 2) for w in widths) + "|"]
    lines += [line(r) for r in rows]
    notfree = [k[0] for k, r in runs.items() if k[1] == "contact-free" and r is None]
    notes = [
        "",
        "plain: `acceleration none;` in solidMechanics of system/fvSolution; accelerated: the"
        " default (`acceleration anderson; andersonDepth 15;`). Every run: `nCorrectors 5000;"
        " onNonConvergence continue;`, so converged = no is a step that stopped at the cap"
        " (or a failed solver run). All cases are one load step; the wall time is the"
        " solver's alone (start-up included, meshing not).",
        "",
        "Contact-free equivalent: hertzCylinder's is the Lagrange multiplier run with the same"
        " iteration, converged, with its slave face displacement prescribed as fixedValue and"
        " its master contact traction as solidTraction (c4fpost.contactfree);"
        " contactPatchTest3D's is its `Allrun -noContact` (the exact displacement and pressure"
        " prescribed); plateHole has no contact.",
        "",
        "The penalty rows' ratio is taken against the same contact-free equivalent as the"
        " Lagrange multiplier rows (hertzCylinder: the one built from the Lagrange multiplier"
        " run; contactPatchTest3D: the exact state), not one built from the penalty solution,"
        " which differs from it by the penalty's penetration.",
        "",
        "hertzCylinder nearRigidCylinder: `Allrun -materials nearRigidCylinder -slave <body>`,"
        " the cylinder 1000 times stiffer than the aluminium block (a law per cellZone); its"
        " last column is its correctors over those of the same problem and iteration on"
        " hertzCylinder (both bodies steel).",
    ]
    if notfree:
        notes += ["", "Not built (its Lagrange multiplier run did not converge): the contact-free"
                  " equivalent of " + ", ".join(sorted(set(notfree))) + "."]
    notes += ["", "Measured on a machine with %d cpus (os.cpu_count()), one solver process at a"
              " time." % os.cpu_count()]
    text = "\n".join(lines + notes) + "\n"
    print("\nConvergence: outer correctors per load step, contact against contact-free\n")
    print(text, flush=True)
    md = os.path.join(WORK, "convergence.md")
    with open(md, "w") as f:
        f.write("# contact4foam convergence (make bench)\n\n" + text)
    print("(written to %s)" % md, flush=True)


def hertz_bench(runs):
    """Accuracy against Hertz and the search tree rebuilt or reused, from
    the accelerated runs of the convergence table and two more."""
    accel = dict(ITERATIONS)["accelerated"]
    default = runs[("hertzCylinder", "lagrangeMultiplier", "accelerated")]
    print("\nhertzCylinder refinement against Hertz (accelerated; * not converged)")
    print("%-20s %8s %8s %14s %14s %10s %10s" % ("method", "level", "cells", "p0 error", "a error [m]",
                                                 "correctors", "wall [s]"))
    coarse = bench_case("hertz_coarse", os.path.join(ROOT, "tutorials/hertzCylinder"), accel,
                        prepare=hertz_prepare(0.5))
    for method, level, r in (
            ("lagrangeMultiplier", 0.5, coarse),
            ("lagrangeMultiplier", 1.0, default),
            ("lagrangeMultiplier", 2.0, runs[("hertzCylinder -refine 2", "lagrangeMultiplier", "accelerated")]),
            ("penalty", 2.0, runs[("hertzCylinder -refine 2", "penalty", "accelerated")])):
        if r["ncorr"] is None:
            print("%-20s %8.2f  run failed, see %s" % (method, level, r["case"]))
            continue
        a = hertz_accuracy(r)
        print("%-20s %8.2f %8d %14.4g %14.4g %9d%s %10.2f" % (method, level, a["cells"], a["p0"], a["a"],
                                                              a["ncorr"], "" if a["converged"] else "*",
                                                              a["wall"]))

    print("\nhertzCylinder, default mesh, Lagrange multiplier (accelerated): search tree rebuilt"
          " every corrector or reused")
    print("%-34s %10s %16s %18s %14s" % ("search", "correctors", "contact time [s]", "per corrector [ms]",
                                         "share of wall"))
    reuse = bench_case("hertz_treeReuse", os.path.join(ROOT, "tutorials/hertzCylinder"), accel,
                       prepare=hertz_prepare(rebuild=1e-4))
    for label, r in (("rebuild every corrector", default), ("reuse until 0.1 mm of motion", reuse)):
        if r["contact"] is None:
            print("%-34s  run failed, see %s" % (label, r["case"]))
            continue
        print("%-34s %9d%s %16.3f %18.3f %13.1f%%" % (label, r["ncorr"], "" if r["converged"] else "*",
                                                     r["contact"], 1e3 * r["contact"] / r["ncorr"],
                                                     100 * r["contact"] / r["wall"]))


def plate_case(n, parallel=False):
    def prepare(case):
        bmd = os.path.join(case, "system/blockMeshDict")
        text = open(bmd).read()
        text = re.sub(r"^nRadial\s+\d+;", "nRadial %d;" % n, text, flags=re.M)
        text = re.sub(r"^nArc\s+\d+;", "nArc %d;" % (2 * n // 3), text, flags=re.M)
        open(bmd, "w").write(text)
        sh("blockMesh", case)
    r = bench_case("plateHole_%d%s" % (n, "_par" if parallel else ""),
                   os.path.join(ROOT, "tutorials/plateHole"), prepare=prepare, parallel=parallel,
                   require=True)
    case = r["case"]
    # The hole error is the tutorial's own check; only the field L2 is extra
    res = compareKirsch.compare(case)
    e_hole = res["checks"][0]["value"]
    t = res["time"]
    C = foamio.read_internal(os.path.join(case, t, "C"))
    s = foamio.read_internal(os.path.join(case, t, "sigma"))
    ref, _, _ = kirsch.stress_xy(C[:, 0], C[:, 1], compareKirsch.T, compareKirsch.R)
    e_l2 = np.sqrt(np.mean((s[:, 0] - ref) ** 2)) / compareKirsch.T
    return dict(r, n=n, cells=len(C), e_hole=e_hole, e_l2=e_l2)


def plate_bench():
    print("\nplateHole refinement (Kirsch), serial")
    print("%8s %8s %12s %12s %8s %10s %10s" % ("nRadial", "cells", "err@hole/3T", "L2/T", "order",
                                               "correctors", "wall [s]"))
    rows = [plate_case(n) for n in (15, 30, 60, 120)]
    prev = None
    for r in rows:
        order = "" if prev is None else "%.2f" % (np.log(prev["e_hole"] / r["e_hole"]) / np.log(2))
        print("%8d %8d %12.4g %12.4g %8s %10d %10.2f" % (r["n"], r["cells"], r["e_hole"], r["e_l2"], order,
                                                         r["ncorr"], r["wall"]))
        prev = r
    par = plate_case(rows[-1]["n"], parallel=True)
    print("\nfinest mesh, 2 MPI ranks: wall %.2f s, correctors %d; serial/parallel wall ratio %.2f"
          % (par["wall"], par["ncorr"], rows[-1]["wall"] / par["wall"]))
    print("(times include solver start-up; %d cores on this machine)" % os.cpu_count())


UZAWA_LINE = re.compile(r"multiplier update (\d+)\s+max <-g>/h = (\S+)\s+"
                        r"max\|dlambda\|/max\|lambda\| = (\S+)")


def uzawa_bench():
    """augmentedLagrange on hertzCylinder: per Uzawa update j the max
    penetration over h and the relative multiplier change of the converged
    inner solve (the solver's log lines), with the ratio of successive
    penetrations (the contraction, K_c/(K_c + eps) in the model problem);
    for penaltyScale 0.3, 1 (default) and 3 the updates, correctors and
    wall time per step. Also written as markdown to WORK/uzawa.md."""
    print("\n== Uzawa updates: augmentedLagrange on hertzCylinder")
    runs = []
    for s in ("0.3", "1", "3"):
        def prepare(case, s=s):
            # The update after convergence: one Uzawa update per converged
            # inner solve, so that its rate shows
            methods.set_coeff(case, "augmentedLagrange", "penaltyScale", s)
            methods.set_coeff(case, "augmentedLagrange", "multiplierUpdate", "converged")
        case = os.path.join(WORK, "uzawaSrc_s" + s)
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tutorials/hertzCylinder"), case,
                        ignore=shutil.ignore_patterns("[1-9]*", "processor*", "log.*", "VTK",
                                                      "postProcessing", "*.png"))
        prepare(case)
        r = bench_case("hertzUzawa_s" + s, case, allrun=("-method", "augmentedLagrange"))
        log = open(os.path.join(r["case"], "log." + SOLVER)).read()
        r["updates"] = [(int(j), float(g), float(dl)) for j, g, dl in UZAWA_LINE.findall(log)]
        r["scale"] = s
        runs.append(r)
    lines = ["| penaltyScale s | converged | multiplier updates | correctors | wall per step [s] |",
             "| --- | --- | --- | --- | --- |"]
    for r in runs:
        lines.append("| %s | %s | %d | %s | %.2f |" % (r["scale"], "yes" if r["converged"] else "no",
                                                     max([u[0] for u in r["updates"]] or [0]),
                                                     r["ncorr"], r["wall_step"]))
    default = [r for r in runs if r["scale"] == "1"][0]
    lines += ["", "penaltyScale 1 (default), per update j (the test after the inner correctors"
              " converged with the multipliers of update j):", "",
              "| j | max <-g_N>/h | ratio to j-1 | max abs(d lambda)/max lambda |",
              "| --- | --- | --- | --- |"]
    prev = None
    for j, g, dl in default["updates"]:
        lines.append("| %d | %.3e | %s | %.3e |" % (j, g, "%.3f" % (g / prev) if prev else "",
                                                     dl))
        prev = g
    lines += ["", multiplier_family_table()]
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(WORK, "uzawa.md"), "w") as f:
        f.write(text + "\n")


# The multiplier family against the Lagrange multiplier (issue 25): the
# cases of its target, each method with its default multiplierUpdate and,
# for those that update in every corrector, with `converged` too
FAMILY_CASES = (("hertzCylinder", ()), ("hertzSphere", ()),
                ("contactPatchTest3D", ("-rotate", "-nu", "0.3")),
                ("hertzCylinder", ("-materials", "nearRigidCylinder", "-slave", "cylinder")))


def multiplier_family_table():
    """Correctors of each method with stored multipliers on the cases of
    FAMILY_CASES, side by side with lagrangeMultiplier's in the same run."""
    family = [m for m in methods.table().values() if "multiplierUpdate" in m.coeffs]
    head = ["case", LM] + ["%s (%s)" % (m.name, m.coeffs["multiplierUpdate"])
                                  for m in family]
    others = [m for m in family if m.coeffs["multiplierUpdate"] == "corrector"]
    head += ["%s (converged)" % m.name for m in others]
    lines = ["Multiplier family: correctors (ratio to %s)" % LM, "",
             "| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for tut, args in FAMILY_CASES:
        src = os.path.join(ROOT, "tutorials", tut)
        tag = "family_" + tut + "".join("_" + a.lstrip("-") for a in args)

        def cell(name, method, prepare=None):
            case = os.path.join(WORK, name + "_src")
            shutil.rmtree(case, ignore_errors=True)
            shutil.copytree(src, case, ignore=shutil.ignore_patterns(
                "[1-9]*", "processor*", "log.*", "VTK", "postProcessing", "*.png"))
            if prepare:
                prepare(case)
            return bench_case(name, case, allrun=("-method", method) + tuple(args))

        lm = cell(tag + "_" + LM, LM)

        def fmt(r):
            if not r["converged"]:
                return "not converged"
            return "%d (%.2f)" % (r["ncorr"], r["ncorr"] / float(lm["ncorr"]))

        row = [tut + (" " + " ".join(args) if args else ""), "%d" % lm["ncorr"]]
        row += [fmt(cell("%s_%s" % (tag, m.name), m.name)) for m in family]
        row += [fmt(cell("%s_%s_converged" % (tag, m.name), m.name,
                         lambda case, m=m: methods.set_coeff(case, m.name, "multiplierUpdate",
                                                             "converged")))
                for m in others]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


# --------------------------------------------------------------------------
# Roles (issue 25): the near-rigid indenter with either body the slave
ROLES_LEVELS = (1, 2)


def surface_strain(case, patch="blockContact"):
    """e_xx of `patch`'s surface at its face nearest x = 0 (the symmetry
    plane), from the face values of D written at the latest time."""
    Cf, _ = foamio.patch_geometry(case, patch)
    D = foamio.read_patch(os.path.join(case, foamio.latest_time(case), "D"), patch, len(Cf))
    o = np.argsort(Cf[:, 0])
    return float(np.gradient(D[o, 0], Cf[o, 0])[0])


def roles_bench():
    """hertzCylinder -materials nearRigidCylinder with the block and with
    the cylinder as the slave, for the Lagrange multiplier, the penalty
    and the methods with stored multipliers, at two mesh levels: each
    body's pressure (p_max and the ellipse fit's a, compareHertz.compare
    on that patch) with the cylinder the slave against the block the
    slave; the cylinder-slave run's maxPenetration (the gap its constraint
    closes, contactReport) and minGap (the slave faces' own search gap);
    the correctors of both; and the slave-to-slave ratio of the peaks
    (cylinder slave's over block slave's) against 1/(1 + e_xx), e_xx the
    block surface's strain at the centre. Markdown in WORK/roles.md."""
    print("\n== Roles: hertzCylinder nearRigidCylinder, the block or the cylinder the slave")
    table = methods.table()
    chosen = [LM, PENALTY] + [m for m in table if table[m].multipliers != "none"]
    head = ("method", "faces across a (block)", "correctors block / cylinder slave",
            "block: p_max, a_fit", "cylinder: p_max, a_fit",
            "maxPenetration / minGap [m] (cylinder slave)",
            "peaks cylinder / block (each run)", "1/(1 + e_xx)")
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for level in ROLES_LEVELS:
        for method in chosen:
            r = {}
            for slave in ("block", "cylinder"):
                args = ["-method", method, "-materials", "nearRigidCylinder", "-slave", slave]
                if level > 1:
                    args += ["-refine", str(level)]
                r[slave] = bench_case("roles_%s_%sSlave_r%d" % (method, slave, level),
                                      os.path.join(ROOT, "tutorials/hertzCylinder"),
                                      allrun=args)
            if not all(x["converged"] for x in r.values()):
                lines.append("| %s | level %d | %s | not converged | | | | |" % (
                    method, level, " / ".join(str(x["ncorr"]) for x in r.values())))
                continue
            cells = []
            for patch in compareHertz.PATCHES[::-1]:
                b = compareHertz.compare(r["block"]["case"], estar="block", patch=patch)
                c = compareHertz.compare(r["cylinder"]["case"], estar="block", patch=patch)
                cells.append("%+.2f %%, %+.2f %%" % (100 * (max(c["p"]) / max(b["p"]) - 1),
                                                    100 * (c["aFit"] / b["aFit"] - 1)))
            sb = compareHertz.compare(r["block"]["case"], estar="block")
            ratios = []
            for x in r.values():
                pk = [max(compareHertz.compare(x["case"], estar="block", patch=p)["p"])
                      for p in ("cylinderContact", "blockContact")]
                ratios.append("%.4f" % (pk[0] / pk[1]))
            row = contactreport.last_row(r["cylinder"]["case"], "cylinderContact") or {}
            exx = surface_strain(r["block"]["case"])
            lines.append("| %s | %.1f | %d / %d | %s | %s | %.2g / %.2g | %s | %.4f |" % (
                method, sb["aH"] / sb["hA"], r["block"]["ncorr"], r["cylinder"]["ncorr"],
                cells[0], cells[1], row.get("maxPenetration", float("nan")),
                row.get("minGap", float("nan")), " / ".join(ratios), 1 / (1 + exx)))
    notes = [
        "",
        "Each body's pressure with the cylinder the slave against the same body's with the"
        " block the slave (relative differences). The issue's target: within 0.5 % of p_max"
        " and a, penetration at most 1e-9 m. maxPenetration is the gap the constraint closes"
        " (per block face: constraintFaces auto), minGap the cylinder faces' own search gap,"
        " which differs from it by the block surface's chord between its points. The penalty"
        " and perturbedLagrange regularise with eps = s K/h of the slave (1000 times stiffer"
        " with the cylinder the slave): their answers depend on the roles by design. The"
        " cylinder's peak over the block's in each run (block slave / cylinder slave): each"
        " body's pressure is per its own area, and the block's surface contracts by e_xx"
        " under the indenter (from D at the centre face of the block-slave run).",
    ]
    text = "\n".join(lines + notes)
    print(text, flush=True)
    with open(os.path.join(WORK, "roles.md"), "w") as f:
        f.write("# contact4foam roles (make bench)\n\n" + text + "\n")


PL_SCALES = ("10", "100", "1000")


def perturbed_bench():
    """perturbedLagrange on contactPatchTest for penaltyScale 10, 100 and
    1000: the stress error against the Lagrange multiplier run (the exact
    answer) falls like 1/eps, as the series-spring offset 1 - L/(L + E/eps)
    predicts, and equals the penalty run's with the same eps; with the
    multiplier updates and correctors of each, and the penalty's
    correctors. Also written as markdown to WORK/perturbedLagrange.md."""
    print("\n== perturbedLagrange on contactPatchTest: error against LM for three eps")
    tut = os.path.join(ROOT, "tutorials/contactPatchTest")

    def run(method, scale=None):
        name = "patchPL_%s%s" % (method, "" if scale is None else "_s" + scale)
        src = os.path.join(WORK, name + "Src")
        shutil.rmtree(src, ignore_errors=True)
        shutil.copytree(tut, src, ignore=shutil.ignore_patterns(
            "[1-9]*", "processor*", "log.*", "VTK", "postProcessing", "*.png"))
        if scale is not None:
            methods.set_coeff(src, method, "penaltyScale", scale)
        r = bench_case(name, src, allrun=("-method", method))
        if not r["converged"]:
            print("  %s did not converge, see %s" % (name, r["case"]))
            return r
        log = open(os.path.join(r["case"], "log." + SOLVER)).read()
        m = re.findall(r"multiplierUpdates = (\d+)", log)
        r["updates"] = int(m[-1]) if m else None
        sig = foamio.read_internal(os.path.join(r["case"], foamio.latest_time(r["case"]),
                                                "sigma"))
        r["syy"] = sig[:, 3]
        return r

    lm = run("lagrangeMultiplier")
    if not lm["converged"]:
        return
    ref = lm["syy"]
    # E/eps = h/s for the tutorial (nu = 0, K = E, slave h = V/A = 0.1 m)
    import comparePatchTest
    res = comparePatchTest.compare(lm["case"])
    h, L = float(np.mean(res["h"])), comparePatchTest.L
    lines = ["| penaltyScale s | eps = s K/h [Pa/m] | error against LM | error x s |"
             " offset 1 - L/(L + E/eps) | difference to penalty (same eps) |"
             " multiplier updates | correctors | penalty correctors |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for scale in PL_SCALES:
        pl, pen = run("perturbedLagrange", scale), run("penalty", scale)
        if not (pl["converged"] and pen["converged"]):
            lines.append("| %s | not converged | | | | | | | |" % scale)
            continue
        s = float(scale)
        err = float(np.abs(pl["syy"] - ref).max() / np.abs(ref).max())
        diff = float(np.abs(pl["syy"] - pen["syy"]).max() / np.abs(pen["syy"]).max())
        offset = 1.0 - L / (L + h / s)
        lines.append("| %s | %.3g | %.4e | %.4f | %.4e | %.1e | %s | %d | %d |"
                     % (scale, s * res["K"] / h, err, err * s, offset, diff, pl["updates"],
                        pl["ncorr"], pen["ncorr"]))
    lines += ["", "Error: max over the cells of abs(sigma_yy - sigma_yy,LM)/abs(sigma_yy,LM), the"
              " Lagrange multiplier run (%d correctors) being exact to 1e-6; error x s constant"
              " is the 1/eps fall (h/L = %g for this mesh). Difference to penalty: the same"
              " measure against the penalty run with the same penaltyScale." % (lm["ncorr"], h / L)]
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(WORK, "perturbedLagrange.md"), "w") as f:
        f.write(text + "\n")


# --------------------------------------------------------------------------
SPHERE_LEVELS = (1.0, 1.5)


def exact_methods():
    """The methods whose answer is the exact constraint (g_N = 0 at the
    converged state; their trait answer=exact), the reference first:
    hertzSphere's two mesh levels are run for these."""
    exact = [m.name for m in methods.table().values() if m.answer == "exact"]
    return sorted(exact, key=lambda m: m != LM)


def method_runs(method, tutorial, level=None):
    """One run of `tutorial`'s Allrun with `method` (and -refine level),
    with its solver wall time, correctors, multiplier updates and the
    contact report's last row."""
    tag = "" if level in (None, 1.0) else "_refine%g" % level
    allrun = ["-method", method] + ([] if tag == "" else ["-refine", "%g" % level])
    r = bench_case("methods_%s_%s%s" % (tutorial, method, tag),
                   os.path.join(ROOT, "tutorials", tutorial), allrun=allrun)
    log = open(os.path.join(r["case"], "log." + SOLVER)).read() \
        if os.path.exists(os.path.join(r["case"], "log." + SOLVER)) else ""
    m = re.findall(r"multiplierUpdates = (\d+)", log)
    r["updates"] = int(m[-1]) if m else 0
    return r


def methods_bench():
    """Every method of the run-time selection table side by side: on
    hertzCylinder (default mesh) the correctors, the solver's wall time,
    the p0 and a errors against Hertz, the max penetration (or, where the
    report has it, the min gap) and the multiplier updates; on
    contactPatchTest the correctors, wall time and the stress error
    against the exact uniform stress; on hertzSphere the exact methods at
    two mesh levels. Markdown in WORK/methods.md, a bar chart in
    WORK/methods.png."""
    import compareHertz
    import comparePatchTest
    names = methods.names()
    print("\n== every method side by side: %s" % ", ".join(names), flush=True)
    rows = []
    for m in names:
        row = dict(method=m)
        h = method_runs(m, "hertzCylinder")
        row["hertz"] = h
        if h["ncorr"] is not None and h["rc"] == 0:
            res = compareHertz.compare(h["case"])
            c = {x["name"].split("/")[-1]: x for x in res["checks"]}
            rep = contactreport.last_row(h["case"], res.get("slave", "cylinderContact")) or {}
            row.update(p0=c["peak_pressure"]["error"], a=c["contact_half_width"]["error"],
                       pen=rep.get("maxPenetration"), minGap=rep.get("minGap"))
        pt = method_runs(m, "contactPatchTest")
        row["patch"] = pt
        if pt["ncorr"] is not None and pt["rc"] == 0:
            row["stress"] = comparePatchTest.compare(pt["case"])["maxRel"]
        rows.append(row)
        print("  %-20s hertzCylinder %s correctors, contactPatchTest %s" % (
            m, h["ncorr"], pt["ncorr"]), flush=True)

    def fmt(v, f="%.3g"):
        return "-" if v is None else f % v

    def corr(r):
        return "-" if r["ncorr"] is None else "%d%s" % (r["ncorr"], "" if r["converged"] else "*")

    lines = ["| method | Hertz correctors | Hertz wall [s] | p0 error | a error [mm] |"
             " max penetration [m] | min gap [m] | multiplier updates | patch correctors |"
             " patch wall [s] | patch stress error |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for row in rows:
        h, pt = row["hertz"], row["patch"]
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %d / %d | %s | %s | %s |" % (
            row["method"], corr(h), fmt(h["wall"], "%.1f"),
            fmt(None if row.get("p0") is None else 100 * row["p0"], "%.2f %%"),
            fmt(None if row.get("a") is None else 1e3 * row["a"], "%.3f"),
            fmt(row.get("pen")), fmt(row.get("minGap")), h["updates"], pt["updates"],
            corr(pt), fmt(pt["wall"], "%.2f"), fmt(row.get("stress"))))
    lines += ["", "hertzCylinder: default mesh (23 slave faces across a); p0 error as a"
              " fraction of Hertz at the measured load, a error in mm (tolerance of the tests:"
              " 3 % and 1.5 faces = 0.4 mm); multiplier updates hertzCylinder / patch test."
              " contactPatchTest: max over the cells of abs(sigma_yy/sigma_exact - 1), the"
              " exact stress of the blocks in series (the penalty-like methods carry their"
              " offset h/(s L) by design). * not converged. Wall: the solver alone, this"
              " machine, this run."]

    # hertzSphere at two levels, the exact methods
    sph = ["", "| method | level (faces across a) | cells | correctors | wall [s] | p0 error |"
           " a error [face widths] | RMS p - Hertz (r < 0.8 a) |",
           "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for m in exact_methods():
        for level in SPHERE_LEVELS:
            r = method_runs(m, "hertzSphere", level)
            if r["ncorr"] is None or r["rc"] != 0:
                sph.append("| %s | %g | - | failed | | | | |" % (m, level))
                continue
            res = compareSphere.compare(r["case"])
            c = {x["name"].split("/")[-1]: x for x in res["checks"]}
            cells = re.search(r"^\s*cells:\s+(\d+)", sh("checkMesh -constant", r["case"]),
                              flags=re.M)
            sph.append("| %s | %g (%.0f) | %s | %s | %.1f | %.4f | %.2f | %.4f |" % (
                m, level, res["aH"] / res["hA"], cells.group(1) if cells else "-", corr(r),
                r["wall"], c["peak_pressure"]["error"],
                c["contact_radius"]["error"] / res["hA"], c["pressure_rms"]["error"]))
            print("  hertzSphere %-20s level %g: %s correctors" % (m, level, r["ncorr"]),
                  flush=True)
    text = "\n".join(lines + sph)
    print(text)
    with open(os.path.join(WORK, "methods.md"), "w") as f:
        f.write(text + "\n")
    methods_chart(rows, os.path.join(WORK, "methods.png"))


def methods_chart(rows, png):
    """Bar chart of the methods table: correctors (hertzCylinder and
    contactPatchTest) and the hertzCylinder p0 error."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [r["method"] for r in rows]
    x = np.arange(len(names))
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    hc = [r["hertz"]["ncorr"] or 0 for r in rows]
    pc = [r["patch"]["ncorr"] or 0 for r in rows]
    a1.bar(x - 0.2, hc, 0.4, label="hertzCylinder")
    a1.bar(x + 0.2, pc, 0.4, label="contactPatchTest")
    a1.set_ylabel("outer correctors")
    a2.bar(x, [100 * (r.get("p0") or 0) for r in rows], 0.6, color="C2")
    a2.axhline(3, color="k", ls=":", lw=1, label="test tolerance 3 %")
    a2.set_ylabel("hertzCylinder p0 error [%]")
    for ax in (a1, a2):
        ax.set_xticks(x)
        ax.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
        ax.grid(alpha=0.3, axis="y")
        ax.legend(fontsize=8)
    fig.suptitle("contact methods side by side (make bench)")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("plot: %s" % png)


# --------------------------------------------------------------------------
# Friction (issue 10)
# The issue's minimum (issue 10): the reference, augmentedLagrange and the plain
# penalty
FRICTION_CATTANEO_METHODS = (LM, "augmentedLagrange", PENALTY)
CATTANEO_LEVELS = (1, 2, 4)    # Allrun -refine N: N times the faces across a


def step_log(case):
    """Per load step of the solver's log: (correctors, multiplierUpdates)."""
    path = os.path.join(case, "log." + SOLVER)
    log = open(path).read() if os.path.exists(path) else ""
    out = []
    for m in re.finditer(r"^Time = \S+\s+correctors = (\d+)(.*)$", log, flags=re.M):
        u = re.search(r"multiplierUpdates = (\d+)", m.group(2))
        out.append((int(m.group(1)), int(u.group(1)) if u else 0))
    return out


def per_step(r, updates=False):
    """'53 + 44' (correctors per step; with updates '222 + 169 (17 + 12)'),
    * where a step did not converge."""
    steps = step_log(r["case"])
    if not steps:
        return "-"
    text = " + ".join("%d" % s[0] for s in steps)
    if updates and any(s[1] for s in steps):
        text += " (%s)" % " + ".join("%d" % s[1] for s in steps)
    return text + ("" if r["converged"] else "*")


def cattaneo_errors(case):
    """compareCattaneo at t = 2 and the errors the bench tabulates: c of
    contactStick and of q against the closed form in slave-face widths at
    x = c; the RMS of q - closed form over |x| < a, and split into the
    stick zone (|x| < c) and the slip zone, in units of mu p0; the RMS of
    q at t = 1 (the normal load with every face stuck: identical materials
    give q = 0, so it is the stick law's own noise); and the RMS of the
    pressure against Hertz (units of p0) on the same faces."""
    import compareCattaneo
    res = compareCattaneo.compare(case, "2")
    x, q, qRef, p = (np.array(res[k]) for k in ("x", "q", "qRef", "p"))
    inA, inC = np.abs(x) < res["a"], np.abs(x) < res["c"]
    mp0 = res["mu"] * res["p0"]

    def rms(v, sel):
        return float(np.sqrt(np.mean(v[sel] ** 2))) if sel.any() else float("nan")
    from c4fpost import hertz
    pH = hertz.pressure(x, res["P"], compareCattaneo.R_EFF, res["Es"])
    first = compareCattaneo.compare(case, "1")
    x1, q1 = np.array(first["x"]), np.array(first["q"])
    # the face width at the centre: faces across the semi-width a
    w0 = res["hC"]
    return dict(res=res, faces=res["a"] / w0, ratio=res["ratio"],
                cStick=(res["cStick"] - res["c"]) / res["hC"],
                cQ=(res["cQ"] - res["c"]) / res["hC"],
                rms=res["rms"], rmsStick=rms(q - qRef, inC) / mp0,
                rmsSlip=rms(q - qRef, inA & ~inC) / mp0,
                rmsT1=rms(q1, np.abs(x1) < first["a"]) / (first["mu"] * first["p0"]),
                pRms=rms(p - pH, inA) / res["p0"])


def friction_bench():
    """Friction side by side (issue 10): cattaneoMindlin at three mesh
    levels (CATTANEO_LEVELS) for FRICTION_CATTANEO_METHODS (correctors per step, solver wall
    time, Q'/(mu P'), the stick-zone half-width c and the RMS of q against
    Cattaneo-Mindlin, the q at t = 1, the pressure's RMS against
    Hertz); slidingBlock with coulomb for every method of -listMethods
    (correctors per step, wall, F_T/(mu F_N) - 1 at the last step; a method
    without a slip law is listed as refused); the stick patch test
    (contactPatchTest -friction stick -shear one) for every method
    (correctors, the stress error against the exact uniform state and its
    spread). Markdown in WORK/friction.md, the q RMS against the faces
    across a (log-log) in WORK/friction.png."""
    sys.path.insert(0, os.path.join(ROOT, "tutorials/cattaneoMindlin/validation"))
    sys.path.insert(0, os.path.join(ROOT, "tutorials/slidingBlock/validation"))
    import compareSliding
    import compareStick
    names = methods.names()
    print("\n== friction: cattaneoMindlin (%s) at -refine %s, slidingBlock and the stick patch"
          " test for %s" % (", ".join(FRICTION_CATTANEO_METHODS),
                            " and ".join("%d" % n for n in CATTANEO_LEVELS), ", ".join(names)),
          flush=True)

    def fmt(v, f="%.3g"):
        return "-" if v is None or v != v else f % v

    # Cattaneo-Mindlin at three mesh levels
    cm = []
    for m in [x for x in FRICTION_CATTANEO_METHODS if x in names]:
        for level in CATTANEO_LEVELS:
            tag = "" if level == 1 else "_refine%d" % level
            allrun = ["-method", m] + ([] if level == 1 else ["-refine", "%d" % level])
            r = bench_case("friction_cattaneo_%s%s" % (m, tag),
                           os.path.join(ROOT, "tutorials/cattaneoMindlin"), allrun=allrun)
            row = dict(method=m, level=level, run=r)
            if r["rc"] == 0 and r["steps"] == 2:
                row.update(cattaneo_errors(r["case"]))
                cells = re.search(r"^\s*cells:\s+(\d+)", sh("checkMesh -constant", r["case"]),
                                  flags=re.M)
                row["cells"] = int(cells.group(1)) if cells else None
            cm.append(row)
            print("  cattaneoMindlin %-20s -refine %d: %s correctors, %.1f s, q RMS %s of mu p0"
                  % (m, level, per_step(r), r["wall"], fmt(row.get("rms"), "%.4f")), flush=True)
    lines = ["| method | -refine (faces across a) | cells | correctors per step (updates) |"
             " wall [s] | Q'/(mu P') | c error, contactStick [faces] | c error, q [faces] |"
             " q RMS [% mu p0] | stick zone / slip zone [% mu p0] | q RMS at t = 1 [% mu p0] |"
             " p RMS vs Hertz [% p0] |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for row in cm:
        r = row["run"]
        if "rms" not in row:
            lines.append("| %s | %d | - | %s | %s | failed (rc=%d, see %s) | | | | | | |"
                         % (row["method"], row["level"], per_step(r, True), fmt(r["wall"], "%.1f"),
                            r["rc"], r["case"]))
            continue
        lines.append("| %s | %d (%.1f) | %s | %s | %.1f | %.4f | %+.2f | %+.2f | %.2f | %.2f / %.2f |"
                     " %.2f | %.2f |" % (
                         row["method"], row["level"], row["faces"], fmt(row.get("cells"), "%d"),
                         per_step(r, True), r["wall"], row["ratio"], row["cStick"], row["cQ"],
                         100 * row["rms"], 100 * row["rmsStick"], 100 * row["rmsSlip"],
                         100 * row["rmsT1"], 100 * row["pRms"]))
    lines += ["", "cattaneoMindlin (`Allrun -method <m> [-refine N]`, coulomb mu 0.3): t = 1 the"
              " normal load, t = 2 the tangential one (correctors per step; multiplier updates in"
              " brackets). Faces across a: a over the slave face width at x = c. c error: the"
              " stick-zone half-width from contactStick and from where q falls below mu p, minus"
              " c = a sqrt(1 - Q'/(mu P')), in slave-face widths (the tests allow 1.5). q RMS: of"
              " q - Cattaneo-Mindlin over |x| < a for the measured P' and Q' (the tests allow"
              " 5 %), and split into |x| < c and c < |x| < a. q RMS at t = 1: the normal load,"
              " under which identical materials give q = 0 (faces closing within the step"
              " carry no friction in it: frictionModel). p RMS: the pressure against Hertz on the same faces."
              " Wall: the solver alone."]
    for m in FRICTION_CATTANEO_METHODS:
        rr = [x for x in cm if x["method"] == m and "rms" in x]
        if len(rr) >= 3:
            # Against the finest level's own q (interpolated at the coarser
            # faces): whether the solution converges, apart from what the
            # half-space closed form leaves out (a/R = 0.063)
            import compareCattaneo
            fine = compareCattaneo.compare(rr[-1]["run"]["case"], "2")
            xf, qf = np.array(fine["x"]), np.array(fine["q"])
            order = np.argsort(xf)
            self_rms = []
            for row in rr[:-1]:
                c = compareCattaneo.compare(row["run"]["case"], "2")
                x, q = np.array(c["x"]), np.array(c["q"])
                inA = np.abs(x) < c["a"]
                d = q - np.interp(x, xf[order], qf[order])
                self_rms.append(float(np.sqrt(np.mean(d[inA] ** 2))) / (c["mu"] * c["p0"]))
            print("  %-20s q against the finest level's: %s of mu p0" % (
                m, " -> ".join("%.4f" % v for v in self_rms)))
        for r0, r1 in zip(rr, rr[1:]):
            print("  %-20s q RMS %.4f -> %.4f of mu p0 (falls %.2fx for %.1fx the faces across"
                  " a; first order would be %.2fx)" % (m, r0["rms"], r1["rms"],
                                                      r0["rms"] / r1["rms"],
                                                      r1["faces"] / r0["faces"],
                                                      r1["faces"] / r0["faces"]))

    # slidingBlock, coulomb, every method
    sb = ["", "| method | correctors per step (updates) | wall [s] |"
          " F_T/(mu F_N) - 1, contactReport | F_T/(mu F_N) - 1, traction field |"
          " faces slipping / in contact |", "| --- | --- | --- | --- | --- | --- |"]
    for m in names:
        r = bench_case("friction_sliding_%s" % m, os.path.join(ROOT, "tutorials/slidingBlock"),
                       allrun=["-method", m])
        if r["rc"] != 0 or not r["steps"]:
            log = os.path.join(r["case"], "log." + SOLVER)
            text = open(log).read() if os.path.exists(log) else ""
            why = ("refused: FatalIOError (no slip law)" if "FOAM FATAL IO ERROR" in text
                   and "coulomb" in text else "failed (rc=%d, see %s)" % (r["rc"], r["case"]))
            sb.append("| %s | %s | | | | |" % (m, why))
            print("  slidingBlock %-20s %s" % (m, why), flush=True)
            continue
        res = compareSliding.compare(r["case"])
        last = res["steps"][-1]
        sb.append("| %s | %s | %.2f | %s | %s | %s / %s |" % (
            m, per_step(r, True).replace(" + ", ", "), r["wall"],
            fmt(last.get("ratio_report", float("nan")) - 1.0, "%.1e"),
            fmt(last["ratio"] - 1.0, "%.1e"), last.get("slipping", "-"),
            last.get("inContact", "-")))
        print("  slidingBlock %-20s %s correctors, F_T/(mu F_N) - 1 = %.1e" % (
            m, per_step(r), last.get("ratio_report", float("nan")) - 1.0), flush=True)
    sb += ["", "slidingBlock (`Allrun -method <m>`, coulomb mu 0.3): five steps, the press and"
           " four pushes, the last two in full slip; F_T/(mu F_N) - 1 at the last step (the tests"
           " allow 1e-6): contactReport's sum |t_T| A over sum p_N A, and the same sums from the"
           " written contactTraction and contactPressure."]

    # the stick patch test, every method
    st = ["", "| method | kind | correctors | multiplier updates | wall [s] |"
          " stress error against the exact state | spread (max - min) over the cells |"
          " sigma_xy / tau - 1 | sigma_yy / exact - 1 |",
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for m in names:
        r = bench_case("friction_stick_%s" % m, os.path.join(ROOT, "tutorials/contactPatchTest"),
                       allrun=["-method", m, "-friction", "stick", "-shear", "one"])
        if r["rc"] != 0 or not r["steps"]:
            st.append("| %s | | failed (rc=%d, see %s) | | | | | | |" % (m, r["rc"], r["case"]))
            print("  stick patch test %-20s failed" % m, flush=True)
            continue
        res = compareStick.compare(r["case"])
        info = res["times"][-1]
        steps = step_log(r["case"])
        st.append("| %s | %s | %s | %d | %.2f | %.1e | %.1e | %+.1e | %+.1e |" % (
            m, res["kind"], per_step(r), sum(s[1] for s in steps), r["wall"],
            max(info["err"].values()), max(info["spread"].values()),
            info["mean"]["xy"] / info["exact"]["xy"] - 1.0,
            info["mean"]["yy"] / info["exact"]["yy"] - 1.0))
        print("  stick patch test %-20s %s correctors, stress error %.1e" % (
            m, per_step(r), max(info["err"].values())), flush=True)
    st += ["", "The stick patch test (`contactPatchTest/Allrun -method <m> -friction stick -shear"
           " one`): uniform compression and shear across 10 on 7 non-matching faces. Stress"
           " error: max over the cells and the components of abs(sigma - sigma_exact) over"
           " max(abs(sigma_yy), abs(sigma_xy)) (the tests allow 1e-6 for the exact methods);"
           " spread: the same of max - min over the cells (uniformity). The penalty family"
           " (a tangential spring eps_T = eps_N in series with the column) is uniform but offset:"
           " the last two columns are the mean stresses against the exact ones."]
    text = "\n".join(lines + sb + st)
    print(text)
    with open(os.path.join(WORK, "friction.md"), "w") as f:
        f.write("# contact4foam friction (make bench)\n\n" + text + "\n")
    friction_chart(cm, os.path.join(WORK, "friction.png"))


def friction_chart(rows, png):
    """The RMS of q - Cattaneo-Mindlin (and the stick noise at t = 1)
    against the faces across a, log-log, one line per method; the
    pressure's RMS against Hertz of the first method beside them."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, ax = plt.subplots(figsize=(9.5, 4.8))
    faces = []
    for i, m in enumerate(FRICTION_CATTANEO_METHODS):
        rr = [r for r in rows if r["method"] == m and "rms" in r]
        if not rr:
            continue
        f = [r["faces"] for r in rr]
        faces += f
        ax.loglog(f, [100 * r["rms"] for r in rr], "o-", color="C%d" % i,
                  label="%s: q RMS at t = 2" % m)
        ax.loglog(f, [100 * r["rmsT1"] for r in rr], "s:", mfc="none", color="C%d" % i,
                  label="%s: q RMS at t = 1 (exact 0)" % m)
        if m == FRICTION_CATTANEO_METHODS[0]:
            ax.loglog(f, [100 * r["pRms"] for r in rr], "^-.", color="C7",
                      label="%s: p RMS against Hertz [%% of $p_0$]" % m)
    if faces:
        f0 = min(faces)
        ref = [r for r in rows if "rms" in r][0]
        ff = np.array([f0, max(faces)])
        ax.loglog(ff, 100 * ref["rms"] * f0 / ff, "k--", lw=1, label="first order")
    ax.axhline(5, color="k", ls=":", lw=1, label="test tolerance 5 %")
    ax.set_xlabel("slave faces across a")
    ax.set_ylabel(r"RMS of q - Cattaneo-Mindlin [% of $\mu p_0$]" "\n"
                  r"(of p - Hertz: % of $p_0$)")
    ax.set_title("cattaneoMindlin, coulomb mu 0.3 (make bench)", fontsize=10)
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        axis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("plot: %s" % png)


# --------------------------------------------------------------------------
# The meshes users bring (issue 21): gmsh prisms with a skewed slave strip
# (and the same with the cylinder the slave) and tetrahedra, at several
# levels (-refine), each against its closed form and, for the correctors,
# against the same mesh without contact (the converged state applied:
# c4fpost.contactfree, (u, t) and (t, t))
UNSTRUCTURED = (
    ("hertzCylinderPrisms", ("-skew", "yes"), (1, 2, 4), "blockContact", "cylinderContact"),
    ("hertzCylinderPrisms", ("-skew", "alternate"), (1, 2, 4), "blockContact",
     "cylinderContact"),
    # the same mesh with the roles swapped: the skewed strip the master
    ("hertzCylinderPrisms", ("-skew", "yes", "-slave", "cylinder"), (1, 2, 4),
     "cylinderContact", "blockContact"),
    ("hertzSphereTets", (), (1, 1.5, 2), "sphereContact", "blockContact"),
    # their polyhedral dual: the checks over the faces of regular size, the
    # peak and RMS over all faces printed beside them
    ("hertzSphereTets", ("-poly",), (1, 1.5, 2), "sphereContact", "blockContact"),
)


def variant(opts):
    """A variant's label from its Allrun options: what follows the first
    option ("-skew yes -slave cylinder" -> "yes -slave cylinder"), or a
    lone switch's name ("-poly" -> "poly")."""
    if len(opts) == 1:
        return opts[0].lstrip("-")
    return " ".join(opts[1:]) or "-"


def unstructured_bench():
    """Pressure against Hertz on gmsh meshes over mesh levels: the peak face
    against Hertz at that face, the RMS inside the contact (fractions of
    p0), correctors and solver wall time with contact and on the same mesh
    without it, twice: the slave's displacement and the master's traction
    prescribed (u, t), and both contact tractions prescribed (t, t), each
    body then held by tractions alone."""
    print("\n== The meshes users bring: Hertz on gmsh prisms and tetrahedra "
          "(lagrangeMultiplier)")
    print("%-20s %-18s %6s %8s %9s %9s %6s %13s %8s %13s" % (
        "tutorial", "variant", "level", "cells", "peak err", "RMS/p0", "corr",
        "free u,t / t,t", "wall s", "free s u,t/t,t"))
    for tutorial, opts, levels, slave, master in UNSTRUCTURED:
        sys.path.insert(0, os.path.join(ROOT, "tutorials", tutorial, "validation"))
        module = importlib.import_module(
            "comparePrisms" if tutorial == "hertzCylinderPrisms" else "compareSphereTets")
        for level in levels:
            name = "%s_%s_%s" % (tutorial, "".join(o.strip("-") for o in opts), level)
            r = bench_case(name, os.path.join(ROOT, "tutorials", tutorial),
                           allrun=["-refine", str(level)] + list(opts))
            if not r["converged"]:
                print("%-20s %-10s %6s  did not converge (rc=%d)" % (
                    tutorial, variant(opts), level, r["rc"]))
                continue
            res = module.compare(r["case"])
            pk = res["checks"][0]
            peak = (pk["value"] - pk["reference"]) / pk["reference"]
            frees = [bench_case(name + tag, r["case"], prepare=contact_free_prepare(
                r["case"], slave, master, slave_traction=st))
                for tag, st in (("_free", False), ("_freeTT", True))]
            cells = len(foamio.cell_centres_volumes(r["case"])[1])
            print("%-20s %-18s %6s %8d %+8.2f%% %8.2f%% %6d %13s %8.1f %13s" % (
                tutorial, variant(opts), level, cells,
                100 * peak,
                100 * res["rms"], r["ncorr"],
                " / ".join(str(f["ncorr"]) if f["converged"] else "no" for f in frees),
                r["wall"],
                " / ".join("%.1f" % f["wall"] if f["converged"] else "-" for f in frees)))
            if res.get("poly"):
                print("%-20s %-18s %6s %8s %+8.2f%% %8.2f%%  (all faces)" % (
                    "", "", "", "", 100 * (res["pMaxAll"] / res["p0H"] - 1),
                    100 * res["rmsAll"]))


GAMG_CASES = (("hertzCylinder", ["-refine", "1"], "cylinderContact", "blockContact"),
              ("hertzCylinder", ["-refine", "2"], "cylinderContact", "blockContact"),
              ("hertzCylinder", ["-refine", "4"], "cylinderContact", "blockContact"),
              ("hertzSphere", [], "sphereContact", "blockContact"))


def no_coarse_coupling(case):
    """The coarse levels without the contact coupling (the optimisation
    switch contactCoarseCoupling, contactGAMGInterfaceField), as before."""
    with open(os.path.join(case, "system/controlDict"), "a") as f:
        f.write("\nOptimisationSwitches\n{\n    contactCoarseCoupling 0;\n}\n")


def gauss_seidel(case):
    """GAMG's smoother GaussSeidel in place of the tutorial's."""
    fvs = os.path.join(case, "system/fvSolution")
    text = re.sub(r"^(\s*smoother\s+)\w+;", r"\g<1>GaussSeidel;", open(fvs).read(),
                  flags=re.M)
    open(fvs, "w").write(text)


# Rounds of the GAMG bench's paired re-timing: each of the contact run and
# its two contact-free equivalents run again, one after the other, this many
# times; the table's wall ratios are the medians of the rounds' ratios
GAMG_ROUNDS = 3


def rerun_wall(r):
    """The solver run again on the case of bench run `r` (serial, from 0,
    every later time removed first): its wall time, or NaN when the run
    fails or takes other correctors than `r` did (then not the same run)."""
    case = r["case"]
    for d in foamio.times(case):
        shutil.rmtree(os.path.join(case, d))
    logfile = os.path.join(case, "log.%s.rerun" % SOLVER)
    with open(logfile, "w") as f:
        t0 = time.time()
        rc = subprocess.run([SOLVER], cwd=case, stdout=f, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL).returncode
        wall = time.time() - t0
    steps = re.findall(r"^Time = \S+\s+correctors = (\d+)", open(logfile).read(), flags=re.M)
    if rc != 0 or sum(int(n) for n in steps) != r["ncorr"]:
        return float("nan")
    return wall


def paired_wall_ratios(contact, free, rounds=GAMG_ROUNDS):
    """The contact run's wall over each contact-free run's, the median over
    `rounds` rounds in which the three are re-run one after the other (a
    single run each is at the mercy of the machine's load of the moment:
    on the 2-core development machine the same run varies by 10-20 %)."""
    ratios = [[] for _ in free]
    for _ in range(rounds):
        w = rerun_wall(contact)
        for k, f in enumerate(free):
            ratios[k].append(w / rerun_wall(f))
    return [float(np.nanmedian(x)) if not all(np.isnan(x)) else float("nan") for x in ratios]


def gamg_bench():
    """GAMG with the contact on its coarse levels (issue 24): for each
    case the Lagrange multiplier run with and without the coarse coupling
    and two contact-free equivalents of the converged run (the slave's
    displacement and the master's traction prescribed, as the convergence
    table's; and both contact tractions prescribed, each body held by
    tractions as the contact holds it): the outer correctors, the linear
    solver's iterations per corrector (summed over the components) and the
    solver's wall time, with the ratios to the contact-free runs. Markdown
    in WORK/gamg.md."""
    print("\n== GAMG: the contact coupling on the coarse levels")
    head = ("case", "run", "correctors", "linear it. / corrector", "wall [s]",
            "wall / corrector [ms]", "it. / corr. over free (u, t) / (t, t)",
            "wall over free (u, t) / (t, t)")
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    paired = []
    print("%-22s %-18s %6s %8s %8s %8s %16s %16s" % (
        "case", "run", "corr", "it/corr", "wall", "ms/corr", "it ratio u,t/t,t", "wall u,t/t,t"))
    for tutorial, args, slave, master in GAMG_CASES:
        label = "%s %s" % (tutorial, " ".join(args)) if args else tutorial
        tag = "gamg_%s_%s" % (tutorial, "_".join(args[1:]) or "1")
        src = os.path.join(ROOT, "tutorials", tutorial)
        # The tutorial's smoother (DICGaussSeidel), with the coarse coupling
        # and without; and GaussSeidel, the smoother before: each against
        # the contact-free runs with its own smoother
        for smoother, runs in (
                (None, [("coupled (default)", "_coupled", None),
                        ("fine level only", "_fineOnly", no_coarse_coupling)]),
                ("GaussSeidel", [("coupled, GaussSeidel", "_coupled", gauss_seidel)])):
            sub = "" if smoother is None else "_" + smoother
            runs = [(kind, bench_case(tag + sub + suffix, src, allrun=args, edit=edit))
                    for kind, suffix, edit in runs]
            ref = runs[0][1]
            if not ref["converged"]:
                lines.append("| %s | %s did not converge | | | | | | |" % (label, runs[0][0]))
                print("%-22s %s did not converge" % (label, runs[0][0]))
                continue
            free = [(kind, bench_case(tag + sub + ("_freeTT" if st else "_freeUT"),
                                      ref["case"],
                                      prepare=contact_free_prepare(ref["case"], slave, master,
                                                                   slave_traction=st)))
                    for kind, st in (("free: u slave, t master", False),
                                     ("free: t both", True))]
            if smoother:
                free = [(kind + ", " + smoother, r) for kind, r in free]
            ok = [f for _, f in free if f["converged"] and f["linear"]]
            for kind, r in runs + free:
                if not r["converged"] or not r["linear"]:
                    lines.append("| %s | %s | %s | not converged | | | | |" % (
                        label, kind, r["ncorr"]))
                    print("%-22s %-18s not converged" % (label, kind))
                    continue
                per = r["linear"] / r["ncorr"]
                ratios = " / ".join("%.2f" % (per / (f["linear"] / f["ncorr"])) for f in ok)
                walls = " / ".join("%.2f" % (r["wall"] / f["wall"]) for f in ok)
                lines.append("| %s | %s | %d | %.1f | %.2f | %.1f | %s | %s |" % (
                    label, kind, r["ncorr"], per, r["wall"], 1e3 * r["wall"] / r["ncorr"],
                    ratios, walls))
                print("%-22s %-18s %6d %8.1f %8.2f %8.1f %16s %16s" % (
                    label, kind[:18], r["ncorr"], per, r["wall"], 1e3 * r["wall"] / r["ncorr"],
                    ratios, walls))
            if smoother is None and len(ok) == 2:
                med = paired_wall_ratios(ref, ok)
                paired.append((label, med))
                print("%-22s %-18s %52s %16s" % (
                    label, "paired, median", "wall over free, median of %d rounds" % GAMG_ROUNDS,
                    " / ".join("%.2f" % m for m in med)))
    notes = [
        "",
        "Each contact run's linear iterations per outer corrector and wall time over those of"
        " the two contact-free equivalents of its converged state (u, t: the slave's"
        " displacement and the master's traction prescribed; t, t: both tractions). The issue's"
        " target: iterations per corrector within 1.3x, the step's wall time within 1.3x.",
        "",
        "The wall ratios of the table are of one run each. Paired: the default contact run and"
        " its two contact-free runs re-run one after the other, %d rounds, the median of the"
        " rounds' ratios:" % GAMG_ROUNDS,
        "",
        "| case | wall over free (u, t) | wall over free (t, t) |",
        "| --- | --- | --- |",
    ] + ["| %s | %.2f | %.2f |" % (label, m[0], m[1]) for label, m in paired]
    with open(os.path.join(WORK, "gamg.md"), "w") as f:
        f.write("\n".join(lines + notes) + "\n")
    print("(markdown: %s)" % os.path.join(WORK, "gamg.md"))


# hertzSphere's cell counts times BIG_REFINE^3: 54,622 x 2.63^3, about 1e6
BIG_REFINE = "2.63"


def scotch_decomposition(case):
    """system/decomposeParDict's method scotch (balanced), in place of the
    tutorial's manual cut through the contact zone."""
    d = os.path.join(case, "system/decomposeParDict")
    text = re.sub(r"^method\s+\w+;", "method          scotch;", open(d).read(), flags=re.M)
    open(d, "w").write(text)


BIG_RUNS = (("serial", False, None),
            ("2 processors, the tutorial's cut", True, None),
            ("2 processors, scotch", True, scotch_decomposition))


def big_bench(variants=BIG_RUNS):
    """The big case (issue 24): hertzSphere at about 1e6 cells (-refine
    BIG_REFINE), serial and on 2 processors (-parallel): cells, outer
    correctors, the solver's wall time and per corrector, the linear
    iterations per corrector, the pair's update (moving the surfaces, the
    search and the overlaps: searchTime of the step summary) and the whole
    contact update (with the method and the coupling: contactTime) as
    shares of the step, the
    peak memory of each process (the solver's maxrss), the master faces
    each processor holds against the whole master (the gather-all of
    before), and the strong-scaling efficiency t1/(2 t2). Markdown in
    WORK/big.md. About half an hour on 2 cores."""
    print("\n== The big case: hertzSphere -refine %s, serial and on 2 processors" % BIG_REFINE)
    tut = os.path.join(ROOT, "tutorials", "hertzSphere")
    head = ("run", "cells", "correctors", "wall [s]", "wall / corrector [s]",
            "linear it. / corrector", "search / contact update / step",
            "maxrss per process [MB]", "master faces held / all")
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    walls = {}
    for label, parallel, edit in variants:
        tag = "serial" if not parallel else ("parallel" if edit is None else "scotch")
        r = bench_case("big_hertzSphere_" + tag, tut, edit=edit,
                       allrun=["-refine", BIG_REFINE] + (["-parallel"] if parallel else []))
        log = open(os.path.join(r["case"], "log." + SOLVER)).read() \
            if os.path.exists(os.path.join(r["case"], "log." + SOLVER)) else ""
        cells = re.search(r"nCells:\s+(\d+)",
                          open(os.path.join(r["case"], "log.blockMesh")).read()) \
            if os.path.exists(os.path.join(r["case"], "log.blockMesh")) else None
        mem = []
        memfile = os.path.join(r["case"], "mem." + SOLVER)
        if os.path.exists(memfile):
            for line in open(memfile):
                rank, kb = line.split()
                mem.append((int(rank), int(kb) / 1024.0))
        held = re.findall(r"master faces held per processor (\d+) \.\. (\d+) of (\d+)", log)
        if not r["converged"]:
            lines.append("| %s | %s | %s | not converged | | | | | |" % (
                label, cells.group(1) if cells else "?", r["ncorr"]))
            print("%-14s not converged (see %s)" % (label, r["case"]))
            continue
        walls[label] = r["wall"]
        step = r["wall"] / max(1, r["steps"])
        share = r["contact"] / step if r["contact"] else float("nan")
        sshare = r["search"] / step if r["search"] else float("nan")
        heldText = ("%s .. %s / %s" % held[-1]) if held else "all (serial)"
        memText = ", ".join("%.0f" % m for _, m in sorted(mem)) or "-"
        lines.append("| %s | %s | %d | %.1f | %.3f | %.1f | %.1f %% / %.1f %% | %s | %s |" % (
            label, cells.group(1) if cells else "?", r["ncorr"], r["wall"],
            r["wall"] / r["ncorr"], r["linear"] / r["ncorr"] if r["linear"] else float("nan"),
            100 * sshare, 100 * share, memText, heldText))
        print(lines[-1])
    if "serial" in walls:
        lines.append("")
        for label, t2 in walls.items():
            if label != "serial":
                lines.append("Strong-scaling efficiency, serial to %s, t1/(2 t2): %.2f." % (
                    label, walls["serial"] / (2 * t2)))
                print(lines[-1])
    with open(os.path.join(WORK, "big.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("(markdown: %s)" % os.path.join(WORK, "big.md"))


def finite_strain_bench():
    """finiteStrainCylinder's force against CalculiX's over the ten steps,
    with a CalculiX curve made in this run (ccx, when it
    is installed; the stored curve otherwise), and finiteStrainPatchTest's
    correctors for two Poisson's ratios."""
    print("\n== Finite deformation: finiteStrainCylinder against CalculiX "
          "(St Venant-Kirchhoff, 20 % of R in ten steps)")
    tut = os.path.join(ROOT, "tutorials", "finiteStrainCylinder")
    sys.path.insert(0, os.path.join(tut, "validation"))
    compare = importlib.import_module("compareCalculix")
    ref = None
    if shutil.which("ccx") and shutil.which("gmsh"):
        ref = os.path.join(WORK, "calculix-stVenantKirchhoff.csv")
        t0 = time.time()
        rc = subprocess.run([sys.executable, os.path.join(tut, "validation", "calculix.py"),
                             "--work", os.path.join(WORK, "calculix"), "--csv", ref],
                            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT).returncode
        if rc != 0:
            print("CalculiX failed (see %s/calculix/stVenantKirchhoff/log.ccx); "
                  "the stored curve instead" % WORK)
            ref = None
        else:
            print("CalculiX: %.0f s (%s)" % (time.time() - t0, ref))
    else:
        print("ccx or gmsh not installed: the stored curve "
              "(tutorials/finiteStrainCylinder/validation/calculix-stVenantKirchhoff.csv)")
    print("%-8s %-19s %8s %9s %9s %8s %7s" % ("refine", "method", "cells", "max|dF|",
                                               "F(20%)", "corr", "wall s"))
    # The barrier (dhat 1e-2 h from the tutorial's 0/D, its open start by
    # Allrun) beside the Lagrange multiplier on the default mesh
    for level, method in ((1, "lagrangeMultiplier"), (1, "barrier"),
                          (2, "lagrangeMultiplier")):
        r = bench_case("finiteStrainCylinder_%d_%s" % (level, method), tut,
                       allrun=["-refine", str(level), "-method", method])
        if not r["converged"]:
            print("%-8d %-19s did not converge (rc=%d)" % (level, method, r["rc"]))
            continue
        res = compare.compare(r["case"], ref)
        cells = len(foamio.cell_centres_volumes(r["case"])[1])
        print("%-8d %-19s %8d %8.3f%% %9.4g %8d %7.1f" % (
            level, method, cells, 100 * max(abs(x) for x in res["rel"]), res["F"][-1],
            r["ncorr"], r["wall"]))
    print("\nfiniteStrainPatchTest (80 % in one step)")
    for nu, method in (("0.3", "lagrangeMultiplier"), ("0.4", "lagrangeMultiplier"),
                       ("0.45", "lagrangeMultiplier"), ("0.3", "barrier")):
        r = bench_case("finiteStrainPatchTest_nu%s_%s" % (nu, method),
                       os.path.join(ROOT, "tutorials", "finiteStrainPatchTest"),
                       allrun=["-nu", nu, "-method", method])
        print("nu %-5s %-19s converged %-3s correctors %s" % (
            nu, method, "yes" if r["converged"] else "no", r["ncorr"]))


def ironing_contact_free(r):
    """The contact run r's case again, the two contact patches holding the
    displacement the contact run converged to at every step
    (timeVaryingMappedFixedValue from constant/boundaryData, nearest
    face): the same mesh and path without contact, the same solver
    settings. Returns bench_case's dict."""
    src = r["case"]
    times = foamio.times(src)

    def write_list(path, values):
        # boundaryData holds the bare list, without format_list's
        # "nonuniform List<...>" prefix
        with open(path, "w") as f:
            f.write(foamio.format_list(values).split(" ", 2)[2] + "\n")

    def prepare(case):
        for patch in ("foundationContact", "dieContact"):
            Cf, _ = foamio.patch_geometry(src, patch)
            base = os.path.join(case, "constant", "boundaryData", patch)
            series = [("0", np.zeros_like(Cf))] + [
                (t, foamio.read_patch(os.path.join(src, t, "D"), patch, len(Cf)))
                for t in times]
            os.makedirs(base, exist_ok=True)
            write_list(os.path.join(base, "points"), Cf)
            for t, D in series:
                os.makedirs(os.path.join(base, t), exist_ok=True)
                write_list(os.path.join(base, t, "D"), D)
            foamio.replace_patch_entry(
                os.path.join(case, "0", "D"), patch,
                "        type            timeVaryingMappedFixedValue;\n"
                "        mapMethod       nearest;\n"
                "        offset          constant (0 0 0);\n"
                "        setAverage      off;\n"
                "        value           uniform (0 0 0);")
        # The die pressed straight down keeps D_x at round-off, 1e-10 to
        # 1.2e-9 of D_y: noise above the default residualFloor that never
        # converged (the contact run's traction-free patches keep it
        # lower)
        fvs = os.path.join(case, "system", "fvSolution")
        text = open(fvs).read()
        text, n = re.subn(r"^(solidMechanics\s*\n\{)", r"\1\n    residualFloor   1e-8;",
                          text, count=1, flags=re.M)
        assert n == 1, "no solidMechanics dictionary in " + fvs
        open(fvs, "w").write(text)
        # Up to the contact run's last written step (a step that did not
        # converge is not written)
        ctl = os.path.join(case, "system", "controlDict")
        text = open(ctl).read()
        text = re.sub(r"\nfunctions\s*\{.*\n\}\n", "\n", text, flags=re.S)
        text = re.sub(r"^endTime\s+[^;]+;", "endTime %s;" % times[-1], text, flags=re.M)
        open(ctl, "w").write(text)

    return bench_case(os.path.basename(src) + "_free", src, prepare=prepare)


def ironing_bench():
    """shallowIroning on two meshes: the published quantities
    (compareIroning.py) with the correctors and the wall time."""
    print("\n== Large sliding: shallowIroning (die pressed 1 mm, ironed 10 mm, mu 0.3)")
    tut = os.path.join(ROOT, "tutorials", "shallowIroning")
    sys.path.insert(0, os.path.join(tut, "validation"))
    compare = importlib.import_module("compareIroning")
    print("%-7s %6s %5s %7s %7s %7s %7s %6s %8s %8s %7s" % (
        "refine", "cells", "conv", "V(1)", "H(1)", "V(1.5)", "H(1.5)", "H/V", "H p-p",
        "corr/st", "wall s"))
    free = []
    for level in ("1", "1.5"):
        r = bench_case("shallowIroning_%s" % level, tut, allrun=["-refine", level])
        free.append((level, r, ironing_contact_free(r)))
        res = compare.compare(r["case"])
        smooth = [c for c in res["checks"] if c["name"].endswith("H_smooth_while_sliding")]
        cells = len(foamio.cell_centres_volumes(r["case"])[1])
        print("%-7s %6d %5s %7.1f %7.1f %7.1f %7.1f %6.3f %7.1f%% %8.0f %7.0f" % (
            level, cells, "yes" if r["converged"] else "no", res["V1"], res["H1"],
            res["V15"], res["H15"], res["ratio"], 100 * smooth[0]["value"],
            (r["ncorr"] or 0) / max(1, r["steps"]), r["wall"]))
    print("published H/V at 1.5: 0.30 (Poulios & Renard) to 0.53 (Fischer & Wriggers);"
          " the issue's band 0.30-0.40, H p-p at most 5 %")
    print("\nThe same mesh and path without contact (both contact patches hold the"
          " displacement the contact run converged to; the same solver settings):")
    print("%-7s %10s %10s %8s %10s %10s %8s" % ("refine", "corr/step", "free", "ratio",
                                              "wall s", "free", "ratio"))
    for level, r, f in free:
        # Over the steps both runs made (the contact run's unconverged
        # last step, if any, is not in the free run)
        n = min(len(step_log(r["case"])), len(step_log(f["case"])))
        c = sum(x[0] for x in step_log(r["case"])[:n]) / max(1, n)
        cf = sum(x[0] for x in step_log(f["case"])[:n]) / max(1, n)
        print("%-7s %10.0f %10.0f %7.2fx %10.0f %10.0f %7.2fx  (%d steps)%s" % (
            level, c, cf, c / max(cf, 1e-9), r["wall"], f["wall"],
            r["wall"] / max(f["wall"], 1e-9), n,
            "" if f["converged"] else "  (free run failed)"))


def rigid_bench():
    """rigidPunch against Sneddon and selfContactStrip against CalculiX
    over mesh levels; the self-contact's correctors and wall time over the
    two-patch model's of the same strip (issue 23)."""
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    import runs as test_runs
    print("\n== Rigid tools: rigidPunch (an STL with a sharp edge) against Sneddon")
    tut = os.path.join(ROOT, "tutorials", "rigidPunch")
    sys.path.insert(0, os.path.join(tut, "validation"))
    punch = importlib.import_module("compareRigidPunch")
    print("%-7s %8s %-22s %8s %7s" % ("refine", "cells", "F/F_Sneddon - 1 [%]", "corr",
                                       "wall s"))
    for level in ("0.67", "1", "1.33"):
        r = bench_case("rigidPunch_%s" % level, tut, allrun=["-refine", level])
        if not r["converged"]:
            print("%-7s did not converge (rc=%d)" % (level, r["rc"]))
            continue
        res = punch.compare(r["case"])
        cells = len(foamio.cell_centres_volumes(r["case"])[1])
        print("%-7s %8d %-22s %8d %7.1f" % (
            level, cells, " ".join("%+.2f" % (100 * (st["F"] / st["FS"] - 1))
                                   for st in res["steps"]), r["ncorr"], r["wall"]))

    print("\n== Self-contact: selfContactStrip against CalculiX (0.5 mm CPE8); "
          "the same strip as a two-patch pair (roof/floor) alongside")
    tut = os.path.join(ROOT, "tutorials", "selfContactStrip")
    sys.path.insert(0, os.path.join(tut, "validation"))
    strip = importlib.import_module("compareSelfContact")
    print("%-7s %7s %-30s %7s %7s %8s %8s %7s" % (
        "refine", "cells", "F/F_ccx - 1 at contact [%]", "corr", "wall s", "corr2p",
        "wall2p s", "ratio"))
    for level in ("1", "2", "4"):
        r = bench_case("selfContactStrip_%s" % level, tut, allrun=["-refine", level])
        two = bench_case("selfContactStrip_twoPatches_%s" % level, tut,
                         allrun=["-refine", level],
                         edit=lambda case: test_runs.strip_as_two_patches(
                             case, "lagrangeMultiplier", "frictionless"))
        if not r["converged"]:
            print("%-7s did not converge (rc=%d)" % (level, r["rc"]))
            continue
        res = strip.compare(r["case"])
        cells = len(foamio.cell_centres_volumes(r["case"])[1])
        errs = " ".join("%+.2f" % (100 * (st["F"] / st["Fref"] - 1))
                        for st in res["steps"] if st["Fref"] >= 1e-4 * st["load"])
        print("%-7s %7d %-30s %7d %7.1f %8s %8s %7s" % (
            level, cells, errs, r["ncorr"], r["wall"],
            two["ncorr"] if two["converged"] else "-",
            "%.1f" % two["wall"] if two["converged"] else "-",
            "%.2f" % (r["wall"] / two["wall"]) if two["converged"] else "-"))


def set_nu(nu, plane_strain=False):
    """An edit that sets nu in every law of the case
    (c4fpost.foamio.set_poisson_ratio), and plane strain where asked."""
    def edit(case):
        foamio.set_poisson_ratio(case, nu, plane_strain)
    return edit


NEWTON_CASES = (("hertzCylinder", [], None, "cylinderContact"),
                ("hertzCylinder", ["-refine", "2"], None, "cylinderContact"),
                ("hertzCylinder", [], 0.49, "cylinderContact"),
                ("hertzSphere", [], None, "sphereContact"),
                ("hertzSphereTets", [], None, "sphereContact"),
                ("contactPatchTest", [], None, "lowerTop"),
                ("finiteStrainPatchTest", [], None, "lowerTop"),
                ("finiteStrainPatchTest", ["-friction", "coulomb"], None, "lowerTop"),
                ("shallowIroning", [], None, "foundationContact"),
                ("rigidSphere", [], None, "blockTop"),
                ("rigidPunch", [], None, "blockTop"))


def newton_log(case):
    """(Newton steps, products) per load step of a Newton run's log."""
    path = os.path.join(case, "log." + SOLVER)
    log = open(path).read() if os.path.exists(path) else ""
    return [(int(a), int(b)) for a, b in
            re.findall(r"newtonKrylov: (\d+) Newton steps, (\d+) products", log)]


def newton_bench():
    """Each case with the segregated loop (Anderson, as the tutorial sets
    it) and with Newton-Krylov, side by side."""
    print("\n== Newton-Krylov against the segregated loop (one run each, one after"
          " the other)")
    head = ("case", "loop", "steps", "corr", "Newton/step", "linear", "wall/step s",
            "wall ratio", "dF_N rel")
    fmt = "%-32s %-10s %5s %7s %12s %9s %11s %10s %9s"
    print(fmt % head)
    md = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for tutorial, opts, nu, patch in NEWTON_CASES:
        label = tutorial + ("".join(" " + o for o in opts)) + (" nu %g" % nu if nu else "")
        tag = (tutorial + "".join(o.strip("-") for o in opts)
               + ("_nu%g" % nu if nu else ""))
        src = os.path.join(ROOT, "tutorials", tutorial)
        edit = set_nu(nu) if nu else None
        seg = bench_case("newton_%s_segregated" % tag, src, allrun=list(opts), edit=edit)
        nk = bench_case("newton_%s_newtonKrylov" % tag, src,
                        allrun=list(opts) + ["-algorithm", "newtonKrylov"], edit=edit)
        fs = contactreport.last_row(seg["case"], patch) if seg["converged"] else None
        fn = contactreport.last_row(nk["case"], patch) if nk["converged"] else None
        dF = (abs(fn["normalForce"] - fs["normalForce"]) / abs(fs["normalForce"])
              if fs and fn and fs["normalForce"] else float("nan"))
        steps = newton_log(nk["case"])
        for r, loop in ((seg, "segregated"), (nk, "newton")):
            newton = ("%.1f (max %d)" % (sum(a for a, _ in steps) / len(steps),
                                         max(a for a, _ in steps))
                      if loop == "newton" and steps else "-")
            row = (label, loop, "%d" % r["steps"],
                   "%d%s" % (r["ncorr"] or 0, "" if r["converged"] else "*"), newton,
                   "%d" % (r["linear"] or 0), "%.3f" % r["wall_step"],
                   "%.2f" % (nk["wall"] / seg["wall"]) if loop == "newton" else "",
                   "%.1e" % dF if loop == "newton" else "")
            print(fmt % row)
            md.append("| " + " | ".join(row) + " |")
    print("(* a step did not converge; corr counts every corrector, Newton's products"
          " included)")
    open(os.path.join(WORK, "newton.md"), "w").write("\n".join(md) + "\n")


STABILISATION_NUS = (0.3, 0.45, 0.49)
STABILISATION_SCALES = (1, 0.3, 0.1)


def stabilisation_bench():
    """The smoothing term's share s (stabilisationScale) against two closed
    forms at three Poisson's ratios: hertzCylinder's p0 and a against Hertz,
    plateHole's sigma_xx along the symmetry line against Kirsch (plane
    strain: the stress does not depend on nu), hertzSphere's p_max and the
    RMS of p - p_Hertz (3D), and the correctors."""
    print("\n== Near-incompressible bodies: stabilisationScale s against Hertz and Kirsch")
    head = ("case", "nu", "s", "correctors", "wall s", "error 1", "error 2")
    fmt = "%-34s %5s %5s %10s %7s %16s %16s"
    print(fmt % head)
    md = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    sys.path.insert(0, os.path.join(ROOT, "tutorials", "plateHole", "validation"))
    for tutorial in ("hertzCylinder", "plateHole", "hertzSphere"):
        for nu in STABILISATION_NUS:
            for sc in STABILISATION_SCALES:
                name = "stabilisation_%s_nu%g_s%g" % (tutorial, nu, sc)
                r = bench_case(name, os.path.join(ROOT, "tutorials", tutorial), allrun=[],
                               entries={"stabilisationScale": "%g" % sc},
                               edit=set_nu(nu, tutorial == "plateHole"))
                if not r["converged"]:
                    row = (tutorial, "%g" % nu, "%g" % sc, "no (rc=%d)" % r["rc"], "", "", "")
                else:
                    if tutorial == "hertzCylinder":
                        c = {x["name"].split("/")[-1]: x
                             for x in compareHertz.compare(r["case"])["checks"]}
                        e1 = "p0 %.2f %%" % (100 * c["peak_pressure"]["error"])
                        e2 = "a %.3f mm" % (1e3 * c["contact_half_width"]["error"])
                    elif tutorial == "hertzSphere":
                        c = {x["name"].split("/")[-1]: x
                             for x in compareSphere.compare(r["case"])["checks"]}
                        e1 = "p_max %.2f %%" % (100 * c["peak_pressure"]["error"])
                        e2 = "RMS %.2f %% of p0" % (100 * c["pressure_rms"]["error"])
                    else:
                        c = {x["name"].split("/")[-1]: x
                             for x in compareKirsch.compare(r["case"])["checks"]}
                        e1 = "sxx %.1f %%" % (100 * c["sxx_symmetry_line_max_error"]["error"])
                        e2 = "first cell %.1f %%" % (100 * c["peak_sxx_first_cell"]["error"])
                    label = tutorial + (" (plane strain)" if tutorial == "plateHole" else "")
                    row = (label, "%g" % nu, "%g" % sc, "%d" % r["ncorr"], "%.1f" % r["wall"],
                           e1, e2)
                print(fmt % row)
                md.append("| " + " | ".join(row) + " |")
    open(os.path.join(WORK, "stabilisation.md"), "w").write("\n".join(md) + "\n")


def main():
    global FRICTION_CATTANEO_METHODS
    import argparse
    ap = argparse.ArgumentParser(description="contact4foam benchmarks")
    ap.add_argument("--only", choices=("convergence", "hertz", "plate", "uzawa", "roles",
                                       "perturbedLagrange", "methods", "friction",
                                       "unstructured", "finiteStrain", "ironing", "rigid",
                                       "gamg", "big", "newton", "stabilisation"),
                    help="run one part only (convergence includes hertz's runs)")
    ap.add_argument("--cattaneo-methods", nargs="+", metavar="METHOD",
                    help="the friction part's cattaneoMindlin methods (default: %s;"
                    " refine 4 takes ~13 min per method on 2 cores)"
                    % " ".join(FRICTION_CATTANEO_METHODS))
    args = ap.parse_args()
    if args.cattaneo_methods:
        FRICTION_CATTANEO_METHODS = tuple(args.cattaneo_methods)
    t0 = time.time()
    os.makedirs(WORK, exist_ok=True)
    if args.only in (None, "convergence", "hertz"):
        rows, runs = convergence_rows()
        convergence_table(rows, runs)
        hertz_bench(runs)
    if args.only in (None, "plate"):
        plate_bench()
    if args.only in (None, "uzawa"):
        uzawa_bench()
    if args.only in (None, "roles"):
        roles_bench()
    if args.only in (None, "perturbedLagrange"):
        perturbed_bench()
    if args.only in (None, "methods"):
        methods_bench()
    if args.only in (None, "friction"):
        friction_bench()
    if args.only in (None, "unstructured"):
        unstructured_bench()
    if args.only in (None, "finiteStrain"):
        finite_strain_bench()
    if args.only in (None, "ironing"):
        ironing_bench()
    if args.only in (None, "rigid"):
        rigid_bench()
    if args.only in (None, "gamg"):
        gamg_bench()
    if args.only in (None, "big"):
        big_bench()
    if args.only in (None, "newton"):
        newton_bench()
    if args.only in (None, "stabilisation"):
        stabilisation_bench()
    print("\n(bench: %.0f s)" % (time.time() - t0))


if __name__ == "__main__":
    main()
