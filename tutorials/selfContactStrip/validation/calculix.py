#!/usr/bin/env python3
"""The selfContactStrip problem in CalculiX (Debian calculix-ccx), the
finite-element reference for the force across the slot.

The same plane-strain C-shaped strip as the tutorial (system/
blockMeshDict): the spine x in [0, 10] mm, the lower arm 10 mm thick to
x = 110 mm, the slot 2 mm high, the upper arm 10 mm thick to x = 100 mm;
thickness 1 mm, so the forces are those of the tutorial's one-cell-thick
mesh. E = 200 GPa, nu = 0.3, small strain (no NLGEOM: the tutorial's
linear-elastic solid), or with --nlgeom finite deformation (NLGEOM, with
*ELASTIC St Venant-Kirchhoff: Allrun -finiteStrain; the pressure then a
dead load, nodal forces fixed in direction, as the tutorial's per
reference area). The bottom y = 0 is clamped; the upper arm's top
over x in [10, 100] mm carries the pressure of the tutorial's table
(0/D), read from there.

Mesh: gmsh (a .geo written here), quadrilaterals recombined and made
second order (8-node serendipity, CPE8), `--size` the element size
(default 0.5 mm). Contact: surface-to-surface (CalculiX's mortar-like
penalty) between the upper arm's underside (slave) and the lower arm's top
(master): CalculiX has no self-contact, and only these two faces of the
tutorial's patch can touch. Linear pressure-overclosure with a slope of
1e15 Pa/m (a penetration p/K below 1e-7 m, against the 2 mm slot),
frictionless.

The force across the slot, from equilibrium: the part of the upper arm
right of a section at x = 50 mm carries the pressure on its top, the
contact force from below (the contact lies right of the section) and the
section's shear force V. Without contact V = c p (the first step, open,
gives c); so the contact force is F = c p + V_y, V_y the y force on the
section's left faces (*SECTION PRINT, SOF). Nodal contact pressures
(CPRESS) integrated over the slave edges give no converged force: at the
arm's end corner they are singular; they give where the contact zone
starts. Writes <work>/model.inp (work: ./calculix), runs ccx there,
and writes (time, pressure [Pa], contact force [N], contact zone start
[m]) per step to --csv
(default: this script's directory, calculix.csv, or calculix-nlgeom.csv
with --nlgeom: the files compareSelfContact.py reads).

Usage:
    calculix.py [--size 5e-4] [--nlgeom] [--work DIR] [--csv FILE]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from c4fpost.calculix import (counter_clockwise, element_faces_on, face_edges,
                              read_frd_contact, read_inp, read_section_forces)

E = 2e11
NU = 0.3
DZ = 1e-3
XCUT = 0.05     # the section through the upper arm [m]

GEO = """// selfContactStrip for CalculiX (validation/calculix.py), lengths in m
h = {h};
Point(1) = {{0, 0, 0, h}};
Point(2) = {{0.01, 0, 0, h}};
Point(3) = {{0.11, 0, 0, h}};
Point(4) = {{0.11, 0.01, 0, h}};
Point(5) = {{0.01, 0.01, 0, h}};
Point(6) = {{0.01, 0.012, 0, h}};
Point(7) = {{0.1, 0.012, 0, h}};
Point(8) = {{0.1, 0.022, 0, h}};
Point(9) = {{0.01, 0.022, 0, h}};
Point(10) = {{0, 0.022, 0, h}};
Point(11) = {{{xcut}, 0.012, 0, h}};
Point(12) = {{{xcut}, 0.022, 0, h}};
Line(1) = {{1, 2}};     // the spine's bottom (clamped)
Line(2) = {{2, 3}};     // the lower arm's bottom (clamped)
Line(3) = {{3, 4}};
Line(4) = {{4, 5}};     // the slot's floor (master)
Line(5) = {{5, 6}};
Line(6) = {{6, 11}};    // the slot's roof (slave)
Line(16) = {{11, 7}};
Line(7) = {{7, 8}};
Line(8) = {{8, 12}};    // the upper arm's top (loaded)
Line(18) = {{12, 9}};
Line(11) = {{11, 12}};  // the cut through the upper arm
Line(9) = {{9, 10}};
Line(10) = {{10, 1}};
Curve Loop(1) = {{1, 2, 3, 4, 5, 6, 16, 7, 8, 18, 9, 10}};
Plane Surface(1) = {{1}};
Line{{11}} In Surface{{1}};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SecondOrderIncomplete = 1;
Mesh.ElementOrder = 2;
Mesh.SaveGroupsOfNodes = 1;
Physical Surface("BODY") = {{1}};
Physical Curve("SPINEBOT") = {{1}};
Physical Curve("ARMBOT") = {{2}};
Physical Curve("FLOOR") = {{4}};
Physical Curve("ROOF") = {{6, 16}};
Physical Curve("TOP") = {{8, 18}};
Physical Curve("CUT") = {{11}};
"""


def pressure_table(case):
    """The (time, pressure) pairs of the load patch's table in 0/D."""
    text = open(os.path.join(case, "0", "D")).read()
    m = re.search(r"pressure\s+table\s*\((.*?)\)\s*;", text, flags=re.S)
    if not m:
        sys.exit("calculix.py: no 'pressure table (...)' in %s/0/D" % case)
    return [(float(t), float(p)) for t, p in
            re.findall(r"\(\s*([^()\s]+)\s+([^()\s]+)\s*\)", m.group(1))]


def write_model(work, size, table, nlgeom):
    geo = os.path.join(work, "mesh.geo")
    with open(geo, "w") as f:
        f.write(GEO.format(h=size, xcut=XCUT))
    subprocess.run(["gmsh", "-2", geo, "-format", "inp", "-o",
                    os.path.join(work, "mesh.inp")],
                   check=True, stdout=subprocess.DEVNULL)
    nodes, elsets, nsets = read_inp(os.path.join(work, "mesh.inp"))
    body = [(eid, counter_clockwise(c, nodes)) for eid, c in elsets.get("Surface1", [])]
    if not body or any(len(c) != 8 for _, c in body):
        sys.exit("calculix.py: gmsh gave no 8-node quadrilaterals only")

    slave = element_faces_on(body, nsets["ROOF"])
    master = element_faces_on(body, nsets["FLOOR"])
    top = element_faces_on(body, nsets["TOP"])
    # The cut's faces of the elements on its left: SOF is the force the
    # part right of the cut exerts on them
    left = set(eid for eid, c in body
               if sum(nodes[n][0] for n in c[:4])/4 < XCUT)
    cut = [(eid, k) for eid, k in element_faces_on(body, nsets["CUT"])
           if eid in left]
    tend = table[-1][0]
    with open(os.path.join(work, "model.inp"), "w") as f:
        f.write("*HEADING\nselfContactStrip (contact4foam)\n")
        f.write("*NODE, NSET=NALL\n")
        for i in sorted(nodes):
            f.write("%d, %.12g, %.12g, 0\n" % (i, nodes[i][0], nodes[i][1]))
        f.write("*ELEMENT, TYPE=CPE8, ELSET=BODY\n")
        for eid, c in body:
            f.write("%d, %s\n" % (eid, ", ".join(str(n) for n in c)))
        for s in ("SPINEBOT", "ARMBOT"):
            f.write("*NSET, NSET=%s\n" % s)
            ids = sorted(set(nsets[s]))
            for k in range(0, len(ids), 10):
                f.write(", ".join(str(n) for n in ids[k:k + 10]) + "\n")
        for name, faces in (("SLAVE", slave), ("MASTER", master), ("CUT", cut)):
            f.write("*SURFACE, NAME=%s, TYPE=ELEMENT\n" % name)
            for eid, k in faces:
                f.write("%d, S%d\n" % (eid, k))
        f.write("*MATERIAL, NAME=M\n*ELASTIC\n%.12g, %.12g\n" % (E, NU))
        f.write("*SOLID SECTION, ELSET=BODY, MATERIAL=M\n%.12g\n" % DZ)
        f.write("*SURFACE INTERACTION, NAME=SI\n"
                "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
                "1e15\n"
                "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n"
                "SLAVE, MASTER\n")
        f.write("*AMPLITUDE, NAME=LOAD\n")
        for t, p in table:
            f.write("%.12g, %.12g\n" % (t, p))
        f.write("*TIME POINTS, NAME=STEPS\n")
        f.write(", ".join("%.12g" % t for t, _ in table if t > 0) + "\n")
        f.write("*BOUNDARY\nSPINEBOT, 1, 2, 0\nARMBOT, 1, 2, 0\n")
        f.write("*STEP%s, INC=10000\n*STATIC\n%.12g, %.12g, 1e-6, %.12g\n"
                % (", NLGEOM" if nlgeom else "", 0.05, tend, 0.25))
        if nlgeom:
            # A dead load, as the tutorial's (solidTraction's pressure under
            # nonlinearGeometry is per reference area along the reference
            # normal): the consistent nodal forces of p = 1 on each
            # quadratic edge, (1, 4, 1)/6 of its length, fixed in direction
            nodal = {}
            for a_, b_, m_ in face_edges(body, top):
                length = abs(nodes[b_][0] - nodes[a_][0])
                for n_, w in ((a_, 1/6), (b_, 1/6), (m_, 4/6)):
                    nodal[n_] = nodal.get(n_, 0.0) + w*length*DZ
            f.write("*CLOAD, AMPLITUDE=LOAD\n")
            for n_ in sorted(nodal):
                f.write("%d, 2, %.12g\n" % (n_, -nodal[n_]))
        else:
            f.write("*DLOAD, AMPLITUDE=LOAD\n")
            for eid, k in top:
                f.write("%d, P%d, 1\n" % (eid, k))
        f.write("*SECTION PRINT, SURFACE=CUT, NAME=SP1, TIME POINTS=STEPS\nSOF\n"
                "*CONTACT FILE, TIME POINTS=STEPS\nCSTR\n*END STEP\n")
    roof = sorted(set(nsets["ROOF"]), key=lambda n: nodes[n][0])
    return len(body), len(slave), [(n, nodes[n][0]) for n in roof]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--size", type=float, default=5e-4)
    ap.add_argument("--nlgeom", action="store_true")
    ap.add_argument("--work", default="calculix")
    ap.add_argument("--csv")
    a = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    csv = a.csv or os.path.join(here, "calculix-nlgeom.csv" if a.nlgeom else "calculix.csv")
    for tool in ("gmsh", "ccx"):
        if not shutil.which(tool):
            sys.exit("calculix.py: %s not found (Debian: gmsh, calculix-ccx)" % tool)
    table = pressure_table(os.path.dirname(here))
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    nel, nslave, roof = write_model(a.work, a.size, table, a.nlgeom)
    r = subprocess.run(["ccx", "-i", "model"], cwd=a.work,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    open(os.path.join(a.work, "log.ccx"), "w").write(r.stdout)
    section = read_section_forces(os.path.join(a.work, "model.dat"))
    times = sorted(section)
    if r.returncode != 0 or "Job finished" not in r.stdout or not times \
            or abs(times[-1] - table[-1][0]) > 1e-9:
        sys.exit("calculix.py: ccx did not finish the step; see %s/log.ccx" % a.work)
    load = dict(table)
    t1 = times[0]
    c = -section[t1][1]/load[t1]
    contact = read_frd_contact(os.path.join(a.work, "model.frd"))

    def start(t):
        """The smallest x of the roof's nodes in contact (nan: none)."""
        p = contact.get(t, {})
        pmax = max([p.get(n, 0.0) for n, _ in roof] + [0.0])
        xs = [x for n, x in roof if pmax > 0 and p.get(n, 0.0) > 1e-3*pmax]
        return min(xs) if xs else float("nan")

    forces = [(t, load[t], c*load[t] + section[t][1], start(t)) for t in times]
    with open(csv, "w") as f:
        f.write("# CalculiX, %d CPE8, element size %g m, %d slave faces, "
                "frictionless, %s\n# time, pressure [Pa], force across "
                "the slot [N] (thickness %g m; time %g the open reference of the "
                "section force), start of the contact zone on the roof: the "
                "least x of a slave node with CPRESS > 1e-3 of the largest [m]\n"
                % (nel, a.size, nslave,
                   "NLGEOM, St Venant-Kirchhoff" if a.nlgeom else "small strain", DZ, t1))
        for t, p, fc, x0 in forces:
            f.write("%.9g, %.9g, %.9g, %.9g\n" % (t, p, fc, x0))
    print("CalculiX (%d elements): %s -> %s"
          % (nel, ", ".join("%g: %.6g N from x = %.4g m" % (t, fc, x0)
                            for t, _, fc, x0 in forces), csv))


if __name__ == "__main__":
    main()
