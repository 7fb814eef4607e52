"""The contact-free equivalent of a converged contact case.

The same mesh, material and loads, with the contact pair replaced by what
the contact run converged to: each patch's contact traction as a
(non-uniform) solidTraction, with the contact patches' non-orthogonal face
correction, so that the face values and their gradients are formed alike
(a fixedValue slave would take the whole face-to-cell step as normal
gradient, and on the slightly leaning cells of hertzCylinder's O-grid
differed by 3.3e-5 of D). Its discrete problem has the contact run's solution, so its
outer correctors are the segregated solver's floor for that mesh: the
benchmarks measure a contact method's correctors against it.
"""
import os
import shutil

from c4fpost import foamio


def make_contact_free(case, time, slave, master):
    """Rewrite 0/D of `case` in place from the converged `time` of the same
    case (a contact run), and remove that time and later ones."""
    converged = os.path.join(case, time, "D")
    d0 = os.path.join(case, "0", "D")
    for patch in (slave, master):
        t = foamio.read_patch(converged, patch, key="contactTraction")
        foamio.replace_patch_entry(
            d0, patch,
            "        type            solidTraction;\n"
            "        traction        %s;\n"
            "        nonOrthogonalCorrection yes;\n"
            "        value           uniform (0 0 0);" % foamio.format_list(t))

    for d in os.listdir(case):
        try:
            tv = float(d)
        except ValueError:
            continue
        if tv > 0:
            shutil.rmtree(os.path.join(case, d))
