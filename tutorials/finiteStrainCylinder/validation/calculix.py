#!/usr/bin/env python3
"""The finiteStrainCylinder problem in CalculiX (Debian calculix-ccx), the
finite-element reference for the force against the approach.

The same plane-strain half-model as the tutorial: a cylinder R = 0.1 m
(its lower quarter disc, centre (0, R)) on a block 0.2 x 0.2 m, both
St Venant-Kirchhoff (CalculiX's *ELASTIC under NLGEOM: S = C : E) or, with
--law neoHookean, CalculiX's *HYPERELASTIC, NEO HOOKE with the same shear
and bulk moduli (C10 = mu/2, D1 = 2/K: the tutorial's neoHookean takes
the same energy with `form decoupled` in constant/mechanicalProperties).
Thickness 0.01 m, so the forces are those of the tutorial's one-cell-thick
mesh. The top of the cylinder goes down by 0.02 m in ten increments with
x held; the block's bottom is clamped; x = 0 is a symmetry line.

Mesh: gmsh (a .geo written here), quadrilaterals recombined and made
second order (8-node serendipity, CPE8), `--size` the element size at
the contact (default 2 mm, 1599 elements; 4.6 min on one core). Contact: surface-to-surface (CalculiX's
mortar-like penalty), the cylinder's arc faces the slave on the block's
top faces, linear pressure-overclosure with a slope of 1e12 Pa/m
(penetration p/K below 1e-6 m at these pressures), frictionless.

Writes <work>/<law>/model.inp (work: ./calculix), runs ccx there, and
writes the curve (approach [m], force [N]) to --csv (default: this
script's directory, calculix-<law>.csv, the file compareCalculix.py
reads).

With --rigid the cylinder is a rigid body (*RIGID BODY about a node at
its centre, moved down as the top was, x and the rotation held; the force
the reaction on the block's clamped bottom, CalculiX giving the
reference node none): Allrun -cylinder rigid's rigidSurface. Default CSV then
calculix-<law>-rigid.csv.

Usage:
    calculix.py [--law stVenantKirchhoff|neoHookean] [--size 2e-3]
                [--rigid] [--work DIR] [--csv FILE]
"""
import argparse
import os
import shutil
import subprocess
import sys

from c4fpost.calculix import (counter_clockwise, element_faces_on,
                              read_inp, read_totals)

R = 0.1
W = 0.2
H = 0.2
DZ = 0.01
DELTA = 0.02
STEPS = 10
E = 10e6
NU = 0.3

GEO = """// finiteStrainCylinder for CalculiX (validation/calculix.py)
R = {R}; W = {W}; H = {H}; hc = {hc}; hf = {hf};
Point(1) = {{0, 0, 0, hc}};        // O, the contact point of the cylinder
Point(2) = {{0, R, 0, hf}};        // C, the centre
Point(3) = {{R, R, 0, hf}};        // Q, the arc's end at 90 deg
Circle(1) = {{1, 2, 3}};           // the arc O -> Q
Line(2) = {{3, 2}};                // the top
Line(3) = {{2, 1}};                // the symmetry line
Curve Loop(1) = {{1, 2, 3}};
Plane Surface(1) = {{1}};
Point(11) = {{0, 0, 0, hc}};       // the block's top at O (not merged)
Point(12) = {{W, 0, 0, hf}};
Point(13) = {{W, -H, 0, hf}};
Point(14) = {{0, -H, 0, hf}};
Point(15) = {{0.08, 0, 0, hc}};   // the end of the fine part of the top
Line(11) = {{11, 15}};
Line(16) = {{15, 12}};
Line(12) = {{12, 13}};
Line(13) = {{13, 14}};
Line(14) = {{14, 11}};
Curve Loop(2) = {{11, 16, 12, 13, 14}};
Plane Surface(2) = {{2}};
Field[1] = Box;
Field[1].VIn = hc; Field[1].VOut = hf;
Field[1].XMin = -1; Field[1].XMax = 0.08; Field[1].YMin = -0.04;
Field[1].YMax = 0.03; Field[1].Thickness = 0.05;
Background Field = 1;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SecondOrderIncomplete = 1;
Mesh.ElementOrder = 2;
Mesh.SaveGroupsOfNodes = 1;
Physical Surface("CYL") = {{1}};
Physical Surface("BLK") = {{2}};
Physical Curve("ARC") = {{1}};
Physical Curve("TOP") = {{2}};
Physical Curve("CSYM") = {{3}};
Physical Curve("BTOP") = {{11, 16}};
Physical Curve("BSYM") = {{14}};
Physical Curve("BOT") = {{13}};
"""


def write_model(work, law, size, rigid=False):
    geo = os.path.join(work, "mesh.geo")
    with open(geo, "w") as f:
        f.write(GEO.format(R=R, W=W, H=H, hc=size, hf=20*size))
    subprocess.run(["gmsh", "-2", geo, "-format", "inp", "-o",
                    os.path.join(work, "mesh.inp")],
                   check=True, stdout=subprocess.DEVNULL)
    nodes, elsets, nsets = read_inp(os.path.join(work, "mesh.inp"))
    # gmsh writes each geometric surface's elements as Surface<n>
    elsets = {"CYL": elsets.get("Surface1", []), "BLK": elsets.get("Surface2", [])}
    # CalculiX wants plane elements counter-clockwise about +z
    for s in elsets:
        elsets[s] = [(eid, counter_clockwise(c, nodes)) for eid, c in elsets[s]]
    for s in ("CYL", "BLK"):
        bad = [c for _, c in elsets.get(s, []) if len(c) != 8]
        if not elsets.get(s) or bad:
            sys.exit("calculix.py: gmsh gave %s no 8-node quadrilaterals only" % s)

    master = element_faces_on(elsets["BLK"], nsets["BTOP"])
    slave = element_faces_on(elsets["CYL"], nsets["ARC"])
    with open(os.path.join(work, "model.inp"), "w") as f:
        f.write("*HEADING\nfiniteStrainCylinder (contact4foam), %s\n" % law)
        f.write("*NODE, NSET=NALL\n")
        for i in sorted(nodes):
            f.write("%d, %.12g, %.12g, 0\n" % (i, nodes[i][0], nodes[i][1]))
        for s in ("CYL", "BLK"):
            f.write("*ELEMENT, TYPE=CPE8, ELSET=%s\n" % s)
            for eid, c in elsets[s]:
                f.write("%d, %s\n" % (eid, ", ".join(str(n) for n in c)))
        for s in ("ARC", "TOP", "CSYM", "BSYM", "BOT"):
            f.write("*NSET, NSET=%s\n" % s)
            ids = sorted(set(nsets[s]))
            for k in range(0, len(ids), 10):
                f.write(", ".join(str(n) for n in ids[k:k + 10]) + "\n")
        f.write("*SURFACE, NAME=SLAVE, TYPE=ELEMENT\n")
        for eid, k in slave:
            f.write("%d, S%d\n" % (eid, k))
        f.write("*SURFACE, NAME=MASTER, TYPE=ELEMENT\n")
        for eid, k in master:
            f.write("%d, S%d\n" % (eid, k))
        f.write("*MATERIAL, NAME=M\n")
        if law == "stVenantKirchhoff":
            f.write("*ELASTIC\n%.12g, %.12g\n" % (E, NU))
        else:
            mu = E/(2*(1 + NU))
            K = E/(3*(1 - 2*NU))
            f.write("*HYPERELASTIC, NEO HOOKE\n%.12g, %.12g\n" % (mu/2, 2/K))
        for s in ("CYL", "BLK"):
            f.write("*SOLID SECTION, ELSET=%s, MATERIAL=M\n%.12g\n" % (s, DZ))
        f.write("*SURFACE INTERACTION, NAME=SI\n"
                "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
                "1e12\n"
                "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n"
                "SLAVE, MASTER\n")
        load = "TOP"
        if rigid:
            # The cylinder a rigid body about a reference node at its
            # centre (and CalculiX's rotation node), the reference node
            # moved as the top was; x held, no rotation
            ref, rot = max(nodes) + 1, max(nodes) + 2
            cyl = sorted(set(n for _, c in elsets["CYL"] for n in c))
            f.write("*NODE, NSET=REF\n%d, 0, %.12g, 0\n" % (ref, R))
            f.write("*NODE, NSET=ROT\n%d, 0, %.12g, 0\n" % (rot, R))
            f.write("*NSET, NSET=CYLALL\n")
            for k in range(0, len(cyl), 10):
                f.write(", ".join(str(n) for n in cyl[k:k + 10]) + "\n")
            f.write("*RIGID BODY, NSET=CYLALL, REF NODE=%d, ROT NODE=%d\n" % (ref, rot))
            f.write("*BOUNDARY\nBOT, 1, 2, 0\nBSYM, 1, 1, 0\nREF, 1, 1, 0\n"
                    "REF, 3, 3, 0\nROT, 1, 3, 0\n")
            load = "REF"
        else:
            f.write("*BOUNDARY\nBOT, 1, 2, 0\nCSYM, 1, 1, 0\nBSYM, 1, 1, 0\n"
                    "TOP, 1, 1, 0\n")
        f.write("*STEP, NLGEOM, INC=10000\n*STATIC\n%.12g, 1.0, 1e-6, %.12g\n"
                % (1.0/STEPS, 1.0/STEPS))
        f.write("*BOUNDARY\n%s, 2, 2, %.12g\n" % (load, -DELTA))
        # The force through the block: the reaction on its clamped bottom
        # (CalculiX gives a rigid body's reference node no reaction)
        f.write("*NODE PRINT, NSET=%s, TOTALS=ONLY\nRF\n*END STEP\n"
                % ("BOT" if rigid else load))
    return len(elsets["CYL"]) + len(elsets["BLK"]), len(master)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--law", default="stVenantKirchhoff",
                    choices=["stVenantKirchhoff", "neoHookean"])
    ap.add_argument("--size", type=float, default=2e-3)
    ap.add_argument("--rigid", action="store_true",
                    help="the cylinder a rigid body (Allrun -cylinder rigid)")
    ap.add_argument("--work", default="calculix")
    ap.add_argument("--csv")
    a = ap.parse_args()
    csv = a.csv or os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "calculix-%s%s.csv" % (a.law, "-rigid" if a.rigid else ""))
    for tool in ("gmsh", "ccx"):
        if not shutil.which(tool):
            sys.exit("calculix.py: %s not found (Debian: gmsh, calculix-ccx)" % tool)
    work = os.path.join(a.work, a.law + ("-rigid" if a.rigid else ""))
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    nel, nmaster = write_model(work, a.law, a.size, a.rigid)
    r = subprocess.run(["ccx", "-i", "model"], cwd=work,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    open(os.path.join(work, "log.ccx"), "w").write(r.stdout)
    forces = read_totals(os.path.join(work, "model.dat"), "BOT" if a.rigid else "TOP")
    if a.rigid:
        # the bottom's reaction pushes up: the contact force, as the top's
        # reaction (pushing down) is in the elastic run
        forces = [(t, -fy) for t, fy in forces]
    if r.returncode != 0 or "Job finished" not in r.stdout or not forces \
            or abs(forces[-1][0] - 1) > 1e-9:
        sys.exit("calculix.py: ccx did not finish the step; see %s/log.ccx" % work)
    with open(csv, "w") as f:
        f.write("# CalculiX %s, %d CPE8, element size %g m at the contact, "
                "%d master faces%s\n# approach [m], force [N] (thickness %g m)\n"
                % (a.law, nel, a.size, nmaster,
                   ", the cylinder a rigid body" if a.rigid else "", DZ))
        for t, fy in forces:
            f.write("%.9g, %.9g\n" % (t*DELTA, -fy))
    print("CalculiX (%s, %d elements): %d increments, F(%.3g m) = %.6g N -> %s"
          % (a.law, nel, len(forces), DELTA, -forces[-1][1], csv))


if __name__ == "__main__":
    main()
