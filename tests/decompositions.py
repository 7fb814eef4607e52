"""Decompositions of a contact case (issue 24): the layouts a user's
decomposePar can produce around a contact interface, each as a
decomposeParDict (scotch, simple) or a manual cell list
(constant/cellDecomposition), and the decomposed run against the serial
one. Used by tests/regression/test_decompositions.py."""
import os
import re
import shutil

import numpy as np

import harness
from c4fpost import foamio

DICT = """FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains %d;
method %s;
%s
"""


def slave_master(case):
    """The slave and master patch names from 0/D (master no / yes)."""
    text = foamio.strip(open(os.path.join(case, "0", "D")).read())
    slave = master = None
    for name in foamio.boundary_patches(case):
        body = foamio.sub_dict(text, name) if re.search(r"\b%s\s*\{" % re.escape(name), text) else ""
        if "solidContact" in body:
            if re.search(r"\bmaster\s+yes\s*;", body):
                master = name
            elif re.search(r"\bmaster\s+no\s*;", body):
                slave = name
    return slave, master


def bodies(case, slave):
    """Per cell 0 for the slave's body (the cells connected to the slave
    patch's through internal faces), 1 for the rest."""
    owner = foamio.read_labels(case, "owner")
    neigh = foamio.read_labels(case, "neighbour")
    n = int(owner.max()) + 1
    nb = [[] for _ in range(n)]
    for o, m in zip(owner[:len(neigh)], neigh):
        nb[o].append(m)
        nb[m].append(o)
    body = np.ones(n, int)
    stack = list(foamio.patch_face_cells(case, slave))
    for c in stack:
        body[c] = 0
    while stack:
        c = stack.pop()
        for m in nb[c]:
            if body[m]:
                body[m] = 0
                stack.append(m)
    return body


def layouts(case):
    """name -> (processors, decomposeParDict body or a cell list). The
    tangential direction is the one of the largest extent of the slave
    patch; 'cut' means through both contact patches."""
    slave, master = slave_master(case)
    C, _ = foamio.cell_centres_volumes(case)
    body = bodies(case, slave)
    Cs, _ = foamio.patch_geometry(case, slave)
    Cm, _ = foamio.patch_geometry(case, master)
    t = int(np.argmax(np.ptp(Cs, axis=0)))
    mid = float(np.median(Cs[:, t]))
    fcS = np.asarray(foamio.patch_face_cells(case, slave))
    fcM = np.asarray(foamio.patch_face_cells(case, master))
    threeD = np.ptp(C[:, 2]) > 0 and len(np.unique(np.round(C[:, 2], 12))) > 1
    def simple(n):
        return "simple\nsimpleCoeffs { n (%d %d %d); delta 0.001; }" % tuple(n)
    n2 = [1, 1, 1]
    n2[t] = 2
    n4 = list(n2)
    n4[[d for d in range(3 if threeD else 2) if d != t][0]] = 2
    out = {"scotch2": (2, "scotch"), "scotch3": (3, "scotch"), "scotch4": (4, "scotch"),
           "simpleCut2": (2, simple(n2)), "simpleCut4": (4, simple(n4))}
    # every slave face on one processor, the master's body split
    p = np.where(body == 0, 0, (C[:, t] >= mid).astype(int))
    out["slaveOnOne"] = (2, p)
    # every master face on one processor, the slave's body split
    p = np.where(body == 1, 0, (C[:, t] >= mid).astype(int))
    out["masterOnOne"] = (2, p)
    # a third processor with no contact face: the master body's cells
    # farther from its patch than half the body's depth
    dist = np.min(np.linalg.norm(C[:, None, :] - Cm[None, :, :], axis=2), axis=1) \
        if len(C) * len(Cm) < 4e7 else None
    p = (C[:, t] >= mid).astype(int)
    if dist is not None:
        far = (body == 1) & (dist > 0.5 * dist[body == 1].max())
        p[far] = 2
        out["noContactFace3"] = (3, p)
    # one processor holding one face of each patch: the cell of the slave
    # face nearest the patch's middle and the cell of the master face
    # nearest that face
    i = int(np.argmin(np.abs(Cs[:, t] - mid)))
    j = int(np.argmin(np.linalg.norm(Cm - Cs[i], axis=1)))
    p = np.zeros(len(C), int)
    p[fcS[i]] = 1
    p[fcM[j]] = 1
    out["oneFaceEach"] = (2, p)
    return out


def run_decomposed(serial_case, name, layout):
    """Copy the serial case (mesh and 0/ only), decompose it by `layout`
    (processors, dict text or cell list), run, reconstruct. Returns the
    case and the return code."""
    nproc, how = layout
    case = serial_case + "_" + name
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(serial_case, case, ignore=shutil.ignore_patterns(
        "[1-9]*", "processor*", "log.*", "VTK", "postProcessing", "*.png", "checks.json"))
    path = os.path.join(case, "system", "decomposeParDict")
    if isinstance(how, str):
        text = DICT % (nproc, how.split("\n")[0], "\n".join(how.split("\n")[1:]))
    else:
        with open(os.path.join(case, "constant", "cellDecomposition"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class labelList;"
                    " location \"constant\"; object cellDecomposition; }\n")
            f.write("%d\n(\n%s\n)\n" % (len(how), "\n".join(str(int(x)) for x in how)))
        text = DICT % (nproc, "manual", "manualCoeffs { dataFile \"cellDecomposition\"; }")
    with open(path, "w") as f:
        f.write(text)
    rc, _ = harness.run(["decomposePar", "-force"], cwd=case,
                        log=os.path.join(case, "log.decomposePar"))
    if rc == 0:
        # A hang (a collective call some processors skip) fails, not stalls
        cmd = ["timeout", "600", "mpirun", "-np", str(nproc)] + (["--oversubscribe"] if nproc > 2 else []) \
            + [harness.SOLVER, "-parallel"]
        rc, _ = harness.run(cmd, cwd=case, log=os.path.join(case, "log.solidContactFoam"))
    if rc == 0:
        rc, _ = harness.run(["reconstructPar"], cwd=case,
                            log=os.path.join(case, "log.reconstructPar"))
    return case, rc
