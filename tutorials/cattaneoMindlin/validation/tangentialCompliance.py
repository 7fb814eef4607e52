#!/usr/bin/python3
"""cattaneoMindlin: the tangential displacement UX of the cylinder's top that
gives a load ratio Q'/(mu P'), measured on this mesh without contact.

How UX of 0/D was chosen (a design aid, not a check). With elastically
identical bodies the tangential problem of step 2 is Cattaneo-Mindlin's
for the pressure of step 1: the increment of the contact traction is the
closed-form q(x) (c4fpost.cattaneo, for the two cylinders' effective
radius R/2), on the cylinder against +x (the base holds it back), on the
base along +x. Put those tractions on both contact patches of a copy of
the case (solidTraction, one value per face, along the face's tangent),
hold the cylinder's top and the base's bottom, and solve once: the base's
surface moves by u_b(x), the cylinder's by u_c(x). In the real step the top moves by UX and the stick zone does not
slip, so
    UX = u_b(x) - u_c(x),   |x| < c,
which must come out uniform over the stick zone (the closed form's stick
condition, on this mesh and these finite bodies: its spread is printed).

    validation/tangentialCompliance.py <case> [--ratio 0.5] [--mu 0.3]

<case> is a converged run of the tutorial (its time 1, the normal step,
gives P' from contactTraction); the copy goes to <case>_compliance.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from c4fpost import cattaneo, foamio, hertz

import numpy as np

R = 0.2                     # each cylinder's radius [m], system/blockMeshDict
R_EFF = hertz.effective_radius(R, R)   # Hertz's, of the two cylinders
SLAVE, MASTER = "cylinderContact", "baseContact"


def tangents(Sf):
    """Unit tangents of 2D faces (in the x-y plane), oriented along +x."""
    n = Sf / np.linalg.norm(Sf, axis=1)[:, None]
    t = np.stack([-n[:, 1], n[:, 0], np.zeros(len(n))], axis=1)
    return t * np.where(t[:, 0] < 0, -1.0, 1.0)[:, None]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case")
    ap.add_argument("--ratio", type=float, default=0.5, help="Q'/(mu P') (default 0.5)")
    ap.add_argument("--mu", type=float, default=0.3)
    args = ap.parse_args()

    case = os.path.abspath(args.case)
    dz = foamio.thickness(case)
    E, nu, _ = foamio.elastic_constants(case, "cylinder")
    Es = hertz.contact_modulus(E, nu)
    Cs, Ss = foamio.patch_geometry(case, SLAVE)
    Cm, Sm = foamio.patch_geometry(case, MASTER)
    tr = foamio.read_patch(os.path.join(case, "1", "contactTraction"), SLAVE, len(Cs))
    P = float(np.sum(tr[:, 1] * np.linalg.norm(Ss, axis=1))) / dz
    Q = args.ratio * args.mu * P
    a = hertz.half_width(P, R_EFF, Es)
    c = cattaneo.stick_half_width(P, Q, args.mu, R_EFF, Es)
    print("P' = %.6g N/m (time 1), a = %.4g mm, Q' = %.4g N/m (Q'/(mu P') = %g, mu = %g),"
          " c = %.4g mm" % (P, a * 1e3, Q, args.ratio, args.mu, c * 1e3))

    work = case.rstrip("/") + "_compliance"
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for d in ("constant", "system", "0"):
        shutil.copytree(os.path.join(case, d), os.path.join(work, d))
    cd = os.path.join(work, "system", "controlDict")
    text = re.sub(r"^endTime\s.*;", "endTime         1;", open(cd).read(), flags=re.M)
    open(cd, "w").write(text)

    ts, tm = tangents(Ss), tangents(Sm)
    qs = cattaneo.traction(Cs[:, 0], P, Q, args.mu, R_EFF, Es)
    qm = cattaneo.traction(Cm[:, 0], P, Q, args.mu, R_EFF, Es)
    d0 = os.path.join(work, "0", "D")
    for patch, t in ((SLAVE, -qs[:, None] * ts), (MASTER, qm[:, None] * tm)):
        foamio.replace_patch_entry(
            d0, patch,
            "        type            solidTraction;\n"
            "        traction        %s;\n"
            "        pressure        constant 0;\n"
            "        value           uniform (0 0 0);" % foamio.format_list(t))
    foamio.replace_patch_entry(d0, "cylinderTop",
                               "        type            fixedValue;\n"
                               "        value           uniform (0 0 0);")
    for app in ("solidContactFoam",):
        with open(os.path.join(work, "log." + app), "w") as log:
            if subprocess.call([app], cwd=work, stdout=log, stderr=subprocess.STDOUT):
                sys.exit("tangentialCompliance: %s failed, see %s/log.%s" % (app, work, app))

    us = foamio.read_patch(os.path.join(work, "1", "D"), SLAVE, len(Cs))[:, 0]
    um = foamio.read_patch(os.path.join(work, "1", "D"), MASTER, len(Cm))[:, 0]
    om = np.argsort(Cm[:, 0])
    stick = np.abs(Cs[:, 0]) < c
    x = Cs[stick, 0]
    ux = np.interp(x, Cm[om, 0], um[om]) - us[stick]
    o = np.argsort(x)
    print("u_b - u_c over the stick zone (%d slave faces): mean %.6g m, min %.6g, max %.6g"
          " (spread %.3g of the mean)" % (stick.sum(), ux.mean(), ux.min(), ux.max(),
                                           (ux.max() - ux.min()) / ux.mean()))
    for i in o[::max(1, len(o) // 10)]:
        print("  x = %8.4f mm  u_b - u_c = %.6g m" % (x[i] * 1e3, ux[i]))
    print("UX = %.4g m (0/D's cylinderTop at t = 2)" % ux.mean())


if __name__ == "__main__":
    main()
