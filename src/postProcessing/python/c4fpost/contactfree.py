"""The contact-free equivalent of a converged contact case.

The same mesh, material and loads, with the contact pair replaced by what
the contact run converged to: the slave patch's face displacement as a
fixedValue, and the master patch's contact traction as a (non-uniform)
solidTraction. Its discrete problem has the contact run's solution, so its
outer correctors are the segregated solver's floor for that mesh: the
benchmarks measure a contact method's correctors against it.
"""
import os
import shutil

from c4fpost import foamio


def make_contact_free(case, time, slave, master, slave_traction=False):
    """Rewrite 0/D of `case` in place from the converged `time` of the same
    case (a contact run), and remove that time and later ones. With
    `slave_traction` the slave patch takes its contact traction too, as a
    solidTraction, instead of its displacement: both bodies are then held
    as the contact holds them, by tractions alone."""
    converged = os.path.join(case, time, "D")
    u = foamio.read_patch(converged, slave)
    t = foamio.read_patch(converged, master, key="contactTraction")

    d0 = os.path.join(case, "0", "D")
    if slave_traction:
        ts = foamio.read_patch(converged, slave, key="contactTraction")
        foamio.replace_patch_entry(
            d0, slave,
            "        type            solidTraction;\n"
            "        traction        %s;\n"
            "        value           uniform (0 0 0);" % foamio.format_list(ts))
    else:
        foamio.replace_patch_entry(
            d0, slave,
            "        type            fixedValue;\n"
            "        value           %s;" % foamio.format_list(u))
    foamio.replace_patch_entry(
        d0, master,
        "        type            solidTraction;\n"
        "        traction        %s;\n"
        "        value           uniform (0 0 0);" % foamio.format_list(t))

    for d in os.listdir(case):
        try:
            tv = float(d)
        except ValueError:
            continue
        if tv > 0:
            shutil.rmtree(os.path.join(case, d))
