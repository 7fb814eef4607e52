"""Bad-input cases (test_badInput.py runs them): each edits a copy of a
tutorial, runs the solver, and must see it stop with a FatalIOError that
names the file, the entry and what is valid, with no crash and no time
directory written."""
import os
import re

CRASH_MARKERS = ("sigSegv", "Segmentation fault", "sigFpe", "Aborted", "core dumped")


def edit(case, relpath, pattern, repl, count=1):
    """Replace `pattern` in the file; with pattern None write a new file."""
    path = os.path.join(case, relpath)
    if pattern is None:
        with open(path, "w") as f:
            f.write(repl)
        return
    text = open(path).read()
    new, n = re.subn(pattern, repl, text, count=count, flags=re.M)
    if n == 0:
        raise RuntimeError("edit %r not applied to %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(new)


MP = "constant/mechanicalProperties"

# A zoned law for contactPatchTest (cellZones lower and upper) in place of
# its #include line; `entries` is the body of zonedCoeffs
INCLUDE = r'^#include\s+"materials/equal"'
LAW = "{ materialLaw linearElastic; linearElasticCoeffs { E 1e6; nu 0; } }"


def zoned(entries):
    return "materialLaw zoned;\nzonedCoeffs\n{\n%s\n}\n" % entries


# A cellZone `all` of every cell, which overlaps both blocks' zones
TOPOSET = """FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions
(
    { name all; type cellZoneSet; action new; source boxToCell; box (-1 -1 -1) (2 2 2); }
);
"""

# name, tutorial, [(file, pattern, replacement)], expected texts in the output
CASES = [
    ("unknownMaterialLaw", "plateHole",
     [(MP, r"^materialLaw\s+linearElastic;", "materialLaw     linearElastik;")],
     ["FOAM FATAL IO ERROR", "Unknown materialLaw linearElastik",
      "Valid materialLaw types", "linearElastic", "mechanicalProperties"]),
    ("missingCoeffsDict", "plateHole",
     [(MP, r"^linearElasticCoeffs", "someOtherCoeffs")],
     ["FOAM FATAL IO ERROR", "linearElasticCoeffs", "mechanicalProperties"]),
    ("missingE", "plateHole",
     [(MP, r"^\s*E\s+70e9;\n", "")],
     ["FOAM FATAL IO ERROR", "'E'", "linearElasticCoeffs"]),
    ("negativeE", "plateHole",
     [(MP, r"^(\s*)E\s+70e9;", r"\1E -70e9;")],
     ["FOAM FATAL IO ERROR", "Entry 'E' = -70000000000", "E > 0", "linearElasticCoeffs"]),
    ("nuAtHalf", "plateHole",
     [(MP, r"^(\s*)nu\s+0\.33;", r"\1nu 0.5;")],
     ["FOAM FATAL IO ERROR", "Entry 'nu' = 0.5", "(-1, 0.5)", "linearElasticCoeffs"]),
    ("nuBelowMinusOne", "plateHole",
     [(MP, r"^(\s*)nu\s+0\.33;", r"\1nu -1.5;")],
     ["FOAM FATAL IO ERROR", "Entry 'nu' = -1.5", "(-1, 0.5)", "linearElasticCoeffs"]),
    ("planeStressOn3DMesh", "plateHole",
     [("system/blockMeshDict", r"(frontAndBack\s*\{\s*type\s+)empty;", r"\1patch;"),
      ("0/D", r"(frontAndBack\s*\{\s*type\s+)empty;",
       r"\1solidTraction; traction constant (0 0 0); value uniform (0 0 0);")],
     ["FOAM FATAL IO ERROR", "planeStress", "2D mesh", "linearElasticCoeffs"]),
    ("zeroCorrectors", "plateHole",
     [("system/fvSolution", r"^(\s*)nCorrectors\s+\d+;", r"\1nCorrectors 0;")],
     ["FOAM FATAL IO ERROR", "Entry 'nCorrectors' = 0", ">= 1", "fvSolution"]),
    ("negativeTolerance", "plateHole",
     [("system/fvSolution", r"^(\s*)tolerance\s+1e-9;", r"\1tolerance -1;")],
     ["FOAM FATAL IO ERROR", "Entry 'tolerance' = -1", "> 0", "fvSolution"]),
    ("invalidOnNonConvergence", "plateHole",
     [("system/fvSolution", r"^(\s*)tolerance\s+1e-9;", r"\1tolerance 1e-9; onNonConvergence ignore;")],
     ["FOAM FATAL IO ERROR", "Entry 'onNonConvergence' = ignore", "stop", "continue",
      "fvSolution"]),
    ("invalidAcceleration", "plateHole",
     [("system/fvSolution", r"^(\s*)tolerance\s+1e-9;", r"\1tolerance 1e-9; acceleration aitken;")],
     ["FOAM FATAL IO ERROR", "Entry 'acceleration' = aitken", "anderson", "none",
      "fvSolution"]),
    ("zeroAndersonDepth", "plateHole",
     [("system/fvSolution", r"^(\s*)tolerance\s+1e-9;", r"\1tolerance 1e-9; andersonDepth 0;")],
     ["FOAM FATAL IO ERROR", "Entry 'andersonDepth' = 0", ">= 1", "fvSolution"]),
    ("tractionFieldWrongSize", "plateHole",
     [("0/D", r"(right\s*\{[^}]*?\btraction\s+)[^;]*;",
       r"\1nonuniform List<vector> 2((1 0 0) (2 0 0));")],
     ["FOAM FATAL IO ERROR", "size 2 is not equal to", "right"]),
    # A load step that does not converge stops the run, writing nothing of it
    ("stepNotConverged", "contactPatchTest",
     [("system/fvSolution", r"^(\s*)nCorrectors\s+\d+;", r"\1nCorrectors 1;")],
     ["FOAM FATAL ERROR", "Load step at time 1 did not converge in nCorrectors = 1",
      "Contact state:", "F_N =", "onNonConvergence"]),
    # A step that carries the upper block 1.2 m down, through the lower one and
    # beyond the search distance (ten cells, 1 m): without the check it
    # converged with no contact and overlapping bodies
    ("passedThroughInOneStep", "contactPatchTest",
     [("0/D", r"fixedValue(\s+)uniform \(0 -0\.01 0\);", r"fixedValue\1uniform (0 -1.2 0);")],
     ["FOAM FATAL ERROR", "Contact patch lowerTop at time 1: 10 of its 10 faces passed"
      " through the master patch upperBottom", "search distance 1 m", "deltaT",
      "searchDistance"]),
    ("neoHookeanUnknownForm", "finiteStrainPatchTest",
     [(MP, r"^(\s*)nu(\s+)0\.3;", r"\1nu\g<2>0.3;\n\1form        bogus;")],
     ["FOAM FATAL IO ERROR", "Entry 'form' = bogus", "neoHookeanCoeffs", "simo",
      "decoupled"]),
    # Contact pair entries (contactPatchTest: slave lowerTop, master upperBottom)
    ("shadowPatchMissing", "contactPatchTest",
     [("0/D", r"^(\s*)shadowPatch\s+upperBottom;", r"\1shadowPatch upperBotom;")],
     ["FOAM FATAL IO ERROR", "shadowPatch upperBotom", "there is no patch upperBotom",
      "Valid patches", "lowerTop"]),
    ("shadowPatchNotContact", "contactPatchTest",
     [("0/D", r"(upperBottom\s*\{\s*)type\s+solidContact;\s*shadowPatch\s+lowerTop;\s*master\s+yes;",
       r"\1type solidTraction; traction constant (0 0 0);")],
     ["FOAM FATAL IO ERROR", "has type 'solidTraction'", "must be solidContact", "upperBottom"]),
    ("bothMaster", "contactPatchTest",
     [("0/D", r"^(\s*)master\s+no;", r"\1master yes;")],
     ["FOAM FATAL IO ERROR", "exactly one patch of a pair is the master", "lowerTop"]),
    ("unknownMethod", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplyer;")],
     ["FOAM FATAL IO ERROR", "Unknown method lagrangeMultiplyer", "Valid methods",
      "lagrangeMultiplier", "penalty"]),
    # Friction (slave lowerTop)
    ("unknownFrictionModel", "contactPatchTest",
     [("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction coulumb;")],
     ["FOAM FATAL IO ERROR", "Unknown friction model coulumb", "entry 'friction'",
      "Valid friction models", "coulomb", "frictionless", "stick"]),
    ("coulombUnknownClosing", "contactPatchTest",
     [("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction coulomb;"),
      ("0/D", r"^(\s*)mu\s+0\.3;", r"\1mu 0.3; closing glued;")],
     ["FOAM FATAL IO ERROR", "Invalid closing glued", "coulombCoeffs", "lowerTop",
      "free", "tied"]),
    ("coulombWithoutMu", "contactPatchTest",
     [("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction coulomb;"),
      ("0/D", r"^(\s*)mu\s+0\.3;", "")],
     ["FOAM FATAL IO ERROR", "Missing entry 'mu'", "coulombCoeffs", "lowerTop"]),
    ("negativeMu", "contactPatchTest",
     [("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction coulomb;"),
      ("0/D", r"^(\s*)mu\s+0\.3;", r"\1mu -0.3;")],
     ["FOAM FATAL IO ERROR", "Invalid mu -0.3", "coulombCoeffs", "lowerTop", "mu >= 0"]),
    ("stickWithCoeffs", "contactPatchTest",
     [("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction stick; stickCoeffs { mu 0.3; }")],
     ["FOAM FATAL IO ERROR", "stick has no coefficients", "stickCoeffs", "mu"]),
    ("perturbedLagrangeCoulomb", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method perturbedLagrange;"),
      ("0/D", r"^(\s*)friction\s+frictionless;", r"\1friction coulomb;")],
     ["FOAM FATAL IO ERROR", "'friction coulomb'", "perturbedLagrange", "no slip law",
      "remark 2.7.3", "frictionless and stick"]),
    ("frictionOnMaster", "contactPatchTest",
     [("0/D", r"(upperBottom\s*\{\s*type\s+solidContact;)", r"\1 friction stick;")],
     ["FOAM FATAL IO ERROR", "Entry 'friction'", "on the master patch", "lowerTop"]),
    ("negativePenaltyScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method penalty; penaltyCoeffs { penaltyScale -1; }")],
     ["FOAM FATAL IO ERROR", "Invalid penaltyScale -1", "penaltyCoeffs", "lowerTop"]),
    ("zeroPenaltyScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method penalty; penaltyCoeffs { penaltyScale 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid penaltyScale 0", "penaltyCoeffs"]),
    # The multiplier family: every entry named with its value and what is valid
    ("constitutiveLawZeroCN", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method constitutiveLaw;"),
      ("0/D", r"^(\s*)cN\s+1e10;", r"\1cN 0;")],
     ["FOAM FATAL IO ERROR", "Invalid constitutive law cN 0", "entry 'cN'", "positive",
      "constitutiveLawCoeffs", "lowerTop"]),
    ("constitutiveLawNegativeN", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method constitutiveLaw;"),
      ("0/D", r"^(\s*)n\s+2;", r"\1n -1;")],
     ["FOAM FATAL IO ERROR", "n -1", "entry 'n'", "positive", "constitutiveLawCoeffs"]),
    ("constitutiveLawMissingN", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method constitutiveLaw;"),
      ("0/D", r"^(\s*)n\s+2;", r"")],
     ["FOAM FATAL IO ERROR", "Missing entry 'n'", "constitutiveLawCoeffs", "lowerTop"]),
    ("augmentedLagrangeNegativePenaltyScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method augmentedLagrange; augmentedLagrangeCoeffs { penaltyScale -1; }")],
     ["FOAM FATAL IO ERROR", "Invalid penaltyScale -1", "augmentedLagrangeCoeffs", "lowerTop"]),
    ("augmentedLagrangeZeroPenetrationTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method augmentedLagrange; augmentedLagrangeCoeffs { penetrationTolerance 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid penetrationTolerance 0", "positive",
      "augmentedLagrangeCoeffs"]),
    ("augmentedLagrangeNegativeMultiplierTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method augmentedLagrange; augmentedLagrangeCoeffs { multiplierTolerance -1e-6; }")],
     ["FOAM FATAL IO ERROR", "Invalid multiplierTolerance -1e-06", "positive",
      "augmentedLagrangeCoeffs"]),
    ("crossConstraintZeroMaxUpdates", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method crossConstraint; crossConstraintCoeffs { maxUpdates 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid maxUpdates 0", "at least 1", "crossConstraintCoeffs"]),
    ("augmentedLagrangeUnknownMultiplierUpdate", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method augmentedLagrange; augmentedLagrangeCoeffs { multiplierUpdate always; }")],
     ["FOAM FATAL IO ERROR", "Invalid multiplierUpdate always", "valid are corrector",
      "converged", "augmentedLagrangeCoeffs"]),
    # The barrier: its coefficients, and a touching start (the tutorial
    # without Allrun's -gap: the blocks meet at y = 0.5)
    ("barrierZeroDhat", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { dhat 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid dhat 0", "positive, finite length", "barrierCoeffs",
      "lowerTop"]),
    ("barrierZeroDhatScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
       r"\1method barrier; barrierCoeffs { dhatScale 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid dhatScale 0", "strictly between 0 and 1",
      "barrierCoeffs", "lowerTop"]),
    ("barrierNegativeKappaScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { kappaScale -2; }")],
     ["FOAM FATAL IO ERROR", "Invalid kappaScale -2", "positive, finite", "barrierCoeffs",
      "lowerTop"]),
    ("barrierStepFractionOne", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { stepFraction 1; }")],
     ["FOAM FATAL IO ERROR", "Invalid stepFraction 1", "strictly between 0 and 1",
      "barrierCoeffs"]),
    ("barrierZeroGapFloor", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { gapFloor 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid gapFloor 0", "strictly between 0 and 1", "barrierCoeffs"]),
    ("barrierLawToleranceOne", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { lawTolerance 1; }")],
     ["FOAM FATAL IO ERROR", "Invalid lawTolerance 1", "strictly between 0 and 1",
      "barrierCoeffs"]),
    ("barrierSmallMaxKappaFactor", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method barrier; barrierCoeffs { maxKappaFactor 0.5; }")],
     ["FOAM FATAL IO ERROR", "Invalid maxKappaFactor 0.5", ">= 1", "barrierCoeffs"]),
    ("barrierTouchingStart", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method barrier;")],
     ["FOAM FATAL IO ERROR", "needs an open start", "contact patch lowerTop", "barrierCoeffs",
      "10 of its 10 faces in range", "g_N <= 0", "worst g_N =", "Allrun -gap"]),
    ("perturbedLagrangeNegativePenaltyScale", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method perturbedLagrange; perturbedLagrangeCoeffs { penaltyScale -1; }")],
     ["FOAM FATAL IO ERROR", "Invalid penaltyScale -1", "positive", "perturbedLagrangeCoeffs",
      "lowerTop"]),
    ("perturbedLagrangeZeroConstraintTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method perturbedLagrange; perturbedLagrangeCoeffs { constraintTolerance 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid constraintTolerance 0", "positive",
      "perturbedLagrangeCoeffs", "lowerTop"]),
    ("perturbedLagrangeNegativeMultiplierTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method perturbedLagrange; perturbedLagrangeCoeffs { multiplierTolerance -1e-6; }")],
     ["FOAM FATAL IO ERROR", "Invalid multiplierTolerance -1e-06", "positive",
      "perturbedLagrangeCoeffs"]),
    ("perturbedLagrangeZeroMaxUpdates", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method perturbedLagrange; perturbedLagrangeCoeffs { maxUpdates 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid maxUpdates 0", "at least 1", "perturbedLagrangeCoeffs"]),
    # The exact methods' stopping entry: perturbedLagrange's penetration at
    # convergence is lambda/eps, so it names the entry to use instead
    ("perturbedLagrangePenetrationTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method perturbedLagrange; perturbedLagrangeCoeffs { penetrationTolerance 1e-3; }")],
     ["FOAM FATAL IO ERROR", "Entry 'penetrationTolerance 0.001'", "not an entry of perturbedLagrange",
      "constraintTolerance", "perturbedLagrangeCoeffs", "lowerTop"]),
    # Nitsche's gamma0 and the coefficient-free direct elimination
    ("nitscheZeroGamma0", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method nitsche; nitscheCoeffs { gamma0 0; }")],
     ["FOAM FATAL IO ERROR", "Invalid gamma0 0", "positive, finite", "nitscheCoeffs",
      "lowerTop"]),
    ("nitscheNegativeGamma0", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method nitsche; nitscheCoeffs { gamma0 -10; }")],
     ["FOAM FATAL IO ERROR", "Invalid gamma0 -10", "positive, finite", "nitscheCoeffs"]),
    # inf and nan are words to OpenFOAM's tokenizer: its own FatalIOError
    # names the entry (1e400 is no test: the tokenizer's strtod overflow
    # traps, sigFpe, before any check; validNitscheParameter's test of
    # finiteness is the kernel's, unit-tested)
    ("nitscheInfiniteGamma0", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method nitsche; nitscheCoeffs { gamma0 inf; }")],
     ["FOAM FATAL IO ERROR", "expected scalar value", "word 'inf'", "nitscheCoeffs.gamma0"]),
    ("nitscheUnknownWeights", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method nitsche; nitscheCoeffs { weights harmonic; }")],
     ["FOAM FATAL IO ERROR", "Invalid weights harmonic", "equal", "stiffness", "nitscheCoeffs",
      "lowerTop"]),
    ("directEliminationWithCoefficient", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;",
        r"\1method directElimination; directEliminationCoeffs { activeSetScale 1; }")],
     ["FOAM FATAL IO ERROR", "Entry 'activeSetScale'", "directElimination has no coefficients",
      "directEliminationCoeffs", "lowerTop"]),
    ("invalidNormals", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; normals smooth;")],
     ["FOAM FATAL IO ERROR", "Invalid normals smooth", "faces", "smoothed", "lowerTop"]),
    ("invalidConstraintFaces", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; constraintFaces masters;")],
     ["FOAM FATAL IO ERROR", "Invalid constraintFaces masters", "slave", "master", "auto",
      "lowerTop"]),
    ("obsoleteCouplingRelaxation", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; couplingRelaxation 0.3;")],
     ["FOAM FATAL IO ERROR", "Entry 'couplingRelaxation'", "no longer used", "lowerTop"]),
    # -1 is the internal "not given": a given -1 is refused like any other
    ("searchDistanceMinusOne", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; searchDistance -1;")],
     ["FOAM FATAL IO ERROR", "Invalid searchDistance -1", "positive length", "lowerTop"]),
    ("invalidCellSize", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; cellSize cube;")],
     ["FOAM FATAL IO ERROR", "Invalid cellSize cube", "face", "patch", "lowerTop"]),
    ("negativeRebuildTolerance", "contactPatchTest",
     [("0/D", r"^(\s*)method\s+lagrangeMultiplier;", r"\1method lagrangeMultiplier; rebuildTolerance -1;")],
     ["FOAM FATAL IO ERROR", "Invalid rebuildTolerance -1", ">= 0", "lowerTop"]),
    ("contactOnEmptyPatch", "contactPatchTest",
     [("0/D", r"(frontAndBack\s*\{\s*type\s+)empty;",
       r"\1solidContact; shadowPatch lowerTop; master yes; value uniform (0 0 0);")],
     # OpenFOAM's own constraint-type check stops it before our constructor
     ["FOAM FATAL IO ERROR", "frontAndBack", "patch type empty and patchField type solidContact"]),
    # The zoned law: every bad entry named
    ("zonedUnknownZone", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s\nuppr %s" % (LAW, LAW)))],
     ["FOAM FATAL IO ERROR", "Entry 'uppr'", "is not a cellZone", "lower", "upper",
      "zonedCoeffs"]),
    ("zonedZoneTwice", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s\nupper %s\nlower %s" % (LAW, LAW, LAW)))],
     ["FOAM FATAL IO ERROR", "duplicate entry: lower", "mechanicalProperties"]),
    ("zonedOverlappingZones", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s\nall %s" % (LAW, LAW))),
      ("system/topoSetDict", None, TOPOSET)],
     ["FOAM FATAL IO ERROR", "Entries 'lower' and 'all'", "overlapping cellZones",
      "share 50 cells", "zonedCoeffs"]),
    ("zonedMissingLaw", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s\nupper { linearElasticCoeffs { E 1e6; nu 0; } }" % LAW))],
     ["FOAM FATAL IO ERROR", "Entry 'upper'", "has no law", "materialLaw", "zonedCoeffs"]),
    ("zonedUnassignedCells", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s" % LAW))],
     ["FOAM FATAL IO ERROR", "28 cells of the mesh are in no cellZone", "default",
      "zonedCoeffs"]),
    ("zonedNested", "contactPatchTest",
     [(MP, INCLUDE, zoned("lower %s\nupper { materialLaw zoned; zonedCoeffs {} }" % LAW))],
     ["FOAM FATAL IO ERROR", "Entry 'upper'", "selects materialLaw zoned"]),
    ("missingTraction", "plateHole",
     [("0/D", r"(right\s*\{[^}]*?)\btraction\s[^;]*;", r"\1")],
     ["FOAM FATAL IO ERROR", "traction", "right"]),
]
