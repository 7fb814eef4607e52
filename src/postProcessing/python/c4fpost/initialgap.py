#!/usr/bin/python3
"""Open an initial gap between two bodies that touch in the mesh, by an
initial displacement of one body (a cellZone), for a contact method that
needs an open start (barrier: every gap > 0 before the first solve).

The mesh is not changed: the body's cells and its patches' faces start at
D = lift (a rigid translation, no strain, no stress) and the boundary
conditions stay what they were, the total displacement from the meshed
(touching) configuration. So the load is unchanged: the converged state is
the touching case's, except for what the contact law itself leaves (the
barrier's gap); the lift only makes the first configuration open.

    python3 -m c4fpost.initialgap <case> <zone> <lx> <ly> <lz> <patch> [<patch> ...]

sets 0/D's internalField to the lift in the cells of <zone> (0 elsewhere)
and the value of each listed patch to the lift on its faces whose cell is
in <zone> (0 on the others): the contact patch of the lifted body and any
fixed-gradient patch (solidTraction) that reads its face values from
`value`. The other patches (fixed values, symmetry planes) evaluate theirs.

A zero lift writes `uniform (0 0 0)` instead (the internalField and the
listed patches' values; no mesh needed). The tutorials' Allrun lifts a
copy of 0/D (bin/tools/c4fRunFunctions keeps the original for Allclean).
"""
import os
import re
import sys

import numpy as np

from c4fpost import foamio


def zone_cells(case, zone):
    """The cell labels of a cellZone (constant/polyMesh/cellZones)."""
    text = foamio.strip_comments(open(os.path.join(case, "constant/polyMesh/cellZones")).read())
    m = re.search(r"\b%s\s*\{" % re.escape(zone), text)
    if not m:
        raise KeyError("no cellZone %s in %s/constant/polyMesh/cellZones" % (zone, case))
    c = re.compile(r"cellLabels\s+List<label>").search(text, m.end())
    vals, _ = foamio._parse_list(text, c.end(), "label")
    return np.asarray(vals, dtype=int)


def ncells(case):
    """Number of cells: one more than the largest owner or neighbour label
    (a mesh's last cell may own no face: gmshToFoam's meshes)."""
    n = int(foamio.read_owner(case).max()) + 1
    neighbour = foamio.read_labels(case, "neighbour")
    return max(n, int(neighbour.max()) + 1 if neighbour.size else 0)


def _set_patch_value(text, patch, value, add=True):
    """text of 0/D with the patch entry's `value` set (replaced, or with
    `add` added before its closing brace); value None removes the line."""
    bm = re.search(r"\bboundaryField\b", text)
    pm = re.compile(r"^\s*%s\s*\{" % re.escape(patch), flags=re.M).search(text, bm.end())
    if not pm:
        raise KeyError("patch %s not in boundaryField of 0/D" % patch)
    depth, i = 1, pm.end()
    while depth:
        depth += (text[i] == "{") - (text[i] == "}")
        i += 1
    body = text[pm.end():i - 1]
    if value is None:
        body = re.sub(r"\n[ \t]*value\s+[^;]*;[ \t]*(?=\n)", "", body, count=1)
        return text[:pm.end()] + body + text[i - 1:]
    entry = "value           %s;" % value
    body, n = re.subn(r"^(\s*)value\s+[^;]*;", lambda m: m.group(1) + entry, body, count=1,
                      flags=re.M)
    if n == 0 and add:
        body = body.rstrip() + "\n        " + entry + "\n    "
    return text[:pm.end()] + body + text[i - 1:]


def lift(case, zone, vector, patches):
    """Displace the cells of `zone` and the faces of `patches` next to them
    by `vector` in 0/D (see the module's description)."""
    vector = np.asarray(vector, dtype=float)
    path = os.path.join(case, "0", "D")
    if not vector.any():
        return reset(path, patches)
    cells = zone_cells(case, zone)
    n = ncells(case)
    D = np.zeros((n, 3))
    D[cells] = vector
    inZone = np.zeros(n, dtype=bool)
    inZone[cells] = True

    text = open(path).read()
    text, k = re.subn(r"^internalField\s+[^;]*;", "internalField   %s;"
                      % foamio.format_list(D).replace("\\", "\\\\"), text, count=1, flags=re.M)
    if k != 1:
        raise RuntimeError("no internalField line in " + path)
    for patch in patches:
        fc = foamio.patch_face_cells(case, patch)
        Df = np.where(inZone[fc][:, None], vector[None, :], 0.0)
        text = _set_patch_value(text, patch, foamio.format_list(Df))
    open(path, "w").write(text)
    return cells.size


def _expands_macro(text, patch):
    """Whether the patch's entry in boundaryField starts with `$name;`."""
    bm = re.search(r"\bboundaryField\b", text)
    return re.compile(r"^\s*%s\s*\{\s*\$\w+\s*;" % re.escape(patch),
                      flags=re.M).search(text, bm.end()) is not None


def reset(path, patches):
    """0/D (at `path`) back to no lift: internalField and the values of
    `patches` uniform (0 0 0); in an entry that expands a macro
    (`$slaveContact;`) the value line a lift added is removed, the
    macro's applies again. Returns 0 (no cell displaced)."""
    text = open(path).read()
    text, k = re.subn(r"^internalField\s+[^;]*;", "internalField   uniform (0 0 0);", text,
                      count=1, flags=re.M)
    if k != 1:
        raise RuntimeError("no internalField line in " + path)
    for patch in patches:
        text = _set_patch_value(text, patch,
                                None if _expands_macro(text, patch) else "uniform (0 0 0)",
                                add=False)
    open(path, "w").write(text)
    return 0


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    case, zone = sys.argv[1], sys.argv[2]
    vector = [float(x) for x in sys.argv[3:6]]
    n = lift(case, zone, vector, sys.argv[6:])
    if not any(vector):
        print("initial gap: none (0/D internalField and %s uniform (0 0 0))"
              % " ".join(sys.argv[6:]))
        return
    print("initial gap: %d cells of zone %s and their faces on %s displaced by (%s)"
          % (n, zone, " ".join(sys.argv[6:]), " ".join("%g" % x for x in vector)))


if __name__ == "__main__":
    main()
