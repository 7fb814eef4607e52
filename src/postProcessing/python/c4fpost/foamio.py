"""Readers for OpenFOAM ASCII files (writeFormat ascii; a binary file is
refused by read_text with what to do), the one module of them in c4fpost:

  fields        a field's internalField or one patch's value (uniform and
                nonuniform scalar, vector, symmTensor and tensor lists);
                the times of a case
  polyMesh      boundary, owner, points, faces; a patch's face centres and
                area vectors, the cells' centres and volumes as OpenFOAM
                computes them
  dictionaries  an entry, a sub-dictionary, #include followed (simple
                files: no macros); the linear-elastic constants of
                constant/mechanicalProperties

The closed forms the comparisons use are elsewhere (hertz, cattaneo,
kirsch, elastic, patchtest).
"""
import os
import re
import sys

import numpy as np

_NCOMP = {"scalar": 1, "vector": 3, "symmTensor": 6, "tensor": 9, "label": 1}


def read_text(path):
    """The text of an OpenFOAM file. A file written with writeFormat binary
    is refused with what to do: these readers parse ASCII only."""
    raw = open(path, "rb").read()
    head = raw[:2000].decode("ascii", errors="replace")
    if re.search(r"\bformat\s+binary\s*;", head):
        raise ValueError(
            "%s is written in binary (writeFormat binary); c4fpost reads ASCII files:"
            " set writeFormat ascii in system/controlDict and run foamFormatConvert"
            " -constant (every time and the mesh)" % path)
    return raw.decode("utf-8", errors="replace")


def strip_comments(text):
    """text without its // and /* */ comments."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def _parse_list(text, pos, kind):
    """Parse 'N ( ... )' starting at pos; return (array, end position)."""
    m = re.compile(r"\s*(\d+)\s*\(").match(text, pos)
    if not m:
        raise ValueError("expected a counted list at offset %d" % pos)
    n = int(m.group(1))
    depth, i = 1, m.end()
    while depth:
        c = text[i]
        depth += (c == "(") - (c == ")")
        i += 1
    body = text[m.end():i - 1].replace("(", " ").replace(")", " ")
    vals = np.array(body.split(), dtype=float)
    ncomp = _NCOMP[kind]
    if vals.size != n * ncomp:
        raise ValueError("list length %d does not match %d x %d" % (vals.size, n, ncomp))
    return (vals if ncomp == 1 else vals.reshape(n, ncomp)), i


def _parse_value(text, pos, size):
    """Parse 'uniform X' or 'nonuniform List<T> N (...)' at pos."""
    m = re.compile(r"\s*uniform\s+").match(text, pos)
    if m:
        mm = re.compile(r"\(([^)]*)\)|([-+0-9.eE]+)").match(text, m.end())
        if mm.group(1) is not None:
            v = np.array(mm.group(1).split(), dtype=float)
            return np.tile(v, (size, 1))
        return np.full(size, float(mm.group(2)))
    m = re.compile(r"\s*nonuniform\s+List<(\w+)>").match(text, pos)
    if not m:
        raise ValueError("cannot parse field value at offset %d" % pos)
    vals, _ = _parse_list(text, m.end(), m.group(1))
    return vals


def read_internal(path, ncells=None):
    """Internal field values of a volField file."""
    text = strip_comments(read_text(path))
    m = re.search(r"\binternalField\b", text)
    return _parse_value(text, m.end(), ncells or 0)


def read_patch(path, patch, nfaces=None, key="value"):
    """The 'value' (or another field-valued) entry of one patch of a field
    file."""
    text = strip_comments(read_text(path))
    bm = re.search(r"\bboundaryField\b", text)
    pm = re.compile(r"\b%s\s*\{" % re.escape(patch)).search(text, bm.end())
    if not pm:
        raise KeyError("patch %s not in %s" % (patch, path))
    vm = re.compile(r"\b%s\b" % re.escape(key)).search(text, pm.end())
    if not vm:
        raise KeyError("no entry %s after patch %s in %s" % (key, patch, path))
    return _parse_value(text, vm.end(), nfaces or 0)


def format_list(values):
    """An OpenFOAM 'nonuniform List<...>' entry value for a scalar or vector
    array."""
    values = np.asarray(values, dtype=float)
    if values.ndim == 1:
        body = "\n".join("%.17g" % v for v in values)
        kind = "scalar"
    else:
        body = "\n".join("(" + " ".join("%.17g" % c for c in v) + ")" for v in values)
        kind = "vector"
    return "nonuniform List<%s> %d\n(\n%s\n)" % (kind, len(values), body)


def replace_patch_entry(path, patch, body):
    """Replace the dictionary of one patch in boundaryField of a field file
    by the given entries (text inside the braces)."""
    text = read_text(path)
    bm = re.search(r"\bboundaryField\b", text)
    pm = re.compile(r"\b%s\s*\{" % re.escape(patch)).search(text, bm.end())
    if not pm:
        raise KeyError("patch %s not in %s" % (patch, path))
    depth, i = 1, pm.end()
    while depth:
        depth += (text[i] == "{") - (text[i] == "}")
        i += 1
    new = "%s\n    {\n%s\n    }" % (patch, body)
    open(path, "w").write(text[:pm.start()] + new + text[i:])


def set_poisson_ratio(case, nu, plane_strain=False):
    """Set every `nu` entry of the case's laws to nu: in
    constant/mechanicalProperties and in each file of constant/materials
    (the material sets tutorials #include), one-line coefficient
    dictionaries included, comments left alone; with plane_strain every
    `planeStress yes` becomes no. Returns how many entries were set (a case
    with none raises)."""
    paths = [os.path.join(case, "constant", "mechanicalProperties")]
    d = os.path.join(case, "constant", "materials")
    if os.path.isdir(d):
        paths += [os.path.join(d, f) for f in sorted(os.listdir(d))]
    n = 0
    for path in paths:
        # a number after `nu`, so that "nu = 0.25," in a comment is left
        text, k = re.subn(r"\b(nu\s+)[-+0-9.eE]+\s*;", r"\g<1>%s;" % nu, read_text(path))
        if plane_strain:
            text = re.sub(r"\b(planeStress\s+)yes;", r"\g<1>no;", text)
        open(path, "w").write(text)
        n += k
    if n == 0:
        raise KeyError("no nu entry in " + ", ".join(paths))
    return n


def read_boundary(case):
    """{patch: (startFace, nFaces, type)} from constant/polyMesh/boundary."""
    text = strip_comments(read_text(os.path.join(case, "constant/polyMesh/boundary")))
    out = {}
    for m in re.finditer(r"(\w+)\s*\{([^}]*)\}", text):
        body = m.group(2)
        nf = re.search(r"nFaces\s+(\d+)", body)
        sf = re.search(r"startFace\s+(\d+)", body)
        ty = re.search(r"\btype\s+(\w+)", body)
        if nf and sf:
            out[m.group(1)] = (int(sf.group(1)), int(nf.group(1)), ty.group(1))
    return out


def read_owner(case):
    """Owner cell of every face."""
    text = strip_comments(read_text(os.path.join(case, "constant/polyMesh/owner")))
    m = re.search(r"\bFoamFile\s*\{[^}]*\}", text)
    vals, _ = _parse_list(text, m.end(), "label")
    return vals.astype(int)


def patch_face_cells(case, patch):
    """Cells next to the faces of a patch, in face order."""
    start, n, _ = read_boundary(case)[patch]
    return read_owner(case)[start:start + n]


def times(case):
    """Names of the numeric time directories other than 0, in time order."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(case, d)):
            out.append((t, d))
    return [d for _, d in sorted(out)]


def latest_time(case):
    """Name of the latest numeric time directory other than 0."""
    ts = times(case)
    if not ts:
        raise FileNotFoundError("no time directory in %s" % case)
    return ts[-1]


# --------------------------------------------------------------------------
# polyMesh geometry and dictionaries

def strip(text):
    """text without comments and without the FoamFile header."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return re.sub(r"\bFoamFile\s*\{[^}]*\}", "", text, count=1)


def _body(path):
    """The text inside the top-level counted list 'N ( ... )' of a file."""
    text = strip(read_text(path))
    m = re.search(r"(\d+)\s*\(", text)
    if not m:
        raise ValueError("no counted list in %s" % path)
    return int(m.group(1)), text[m.end():text.rindex(")")]


def read_points(case):
    """constant/polyMesh/points as an (n, 3) array."""
    n, body = _body(os.path.join(case, "constant/polyMesh/points"))
    pts = np.array(body.replace("(", " ").replace(")", " ").split(), float)
    if pts.size != 3 * n:
        raise ValueError("points: %d values for %d points" % (pts.size, n))
    return pts.reshape(n, 3)


def read_faces(case):
    """constant/polyMesh/faces (ASCII faceList) as a list of index arrays."""
    n, body = _body(os.path.join(case, "constant/polyMesh/faces"))
    faces = [np.array(f.split(), int) for f in re.findall(r"\d+\s*\(([^)]*)\)", body)]
    if len(faces) != n:
        raise ValueError("faces: read %d of %d" % (len(faces), n))
    return faces


def read_labels(case, name):
    """constant/polyMesh/<name> (owner, neighbour) as an int array."""
    n, body = _body(os.path.join(case, "constant/polyMesh", name))
    vals = np.array(body.split(), int)
    if vals.size != n:
        raise ValueError("%s: %d values for %d" % (name, vals.size, n))
    return vals


def face_geometry(points, face):
    """(centre, area vector) of one face the way OpenFOAM computes them:
    triangles fanned from the vertex average, area-weighted centroids."""
    p = points[face]
    c0 = p.mean(axis=0)
    q = np.roll(p, -1, axis=0)
    tri_n = 0.5 * np.cross(p - c0, q - c0)
    tri_c = (p + q + c0) / 3.0
    mag = np.linalg.norm(tri_n, axis=1)
    Sf = tri_n.sum(axis=0)
    Cf = (tri_c * mag[:, None]).sum(axis=0) / mag.sum() if mag.sum() > 0 else c0
    return Cf, Sf


def boundary_patches(case):
    """{patch: (startFace, nFaces)} from constant/polyMesh/boundary."""
    text = strip(read_text(os.path.join(case, "constant/polyMesh/boundary")))
    out = {}
    for m in re.finditer(r"(\w+)\s*\{([^}]*)\}", text):
        nf = re.search(r"\bnFaces\s+(\d+)", m.group(2))
        sf = re.search(r"\bstartFace\s+(\d+)", m.group(2))
        if nf and sf:
            out[m.group(1)] = (int(sf.group(1)), int(nf.group(1)))
    return out


def patch_geometry(case, patch):
    """Face centres Cf (n, 3) and outward area vectors Sf (n, 3) of a patch,
    in face order, in the mesh's (reference) configuration."""
    start, n = boundary_patches(case)[patch]
    points = read_points(case)
    faces = read_faces(case)
    Cf = np.empty((n, 3))
    Sf = np.empty((n, 3))
    for i in range(n):
        Cf[i], Sf[i] = face_geometry(points, faces[start + i])
    return Cf, Sf


def cell_centres_volumes(case):
    """Cell centres (n, 3) and volumes (n,) as OpenFOAM computes them
    (pyramids from each face to the mean of the cell's face centres)."""
    points = read_points(case)
    faces = read_faces(case)
    owner = read_labels(case, "owner")
    neigh = read_labels(case, "neighbour")
    nf = len(faces)
    # the largest label of either list: a mesh's last cell may own no face
    # (gmshToFoam's meshes)
    ncells = max(owner.max(), neigh.max() if neigh.size else -1) + 1
    Cf = np.empty((nf, 3))
    Sf = np.empty((nf, 3))
    for i, f in enumerate(faces):
        Cf[i], Sf[i] = face_geometry(points, f)
    nIn = neigh.size
    # estimated centre: the mean of the face centres
    cEst = np.zeros((ncells, 3))
    nFc = np.zeros(ncells)
    np.add.at(cEst, owner, Cf)
    np.add.at(nFc, owner, 1)
    np.add.at(cEst, neigh, Cf[:nIn])
    np.add.at(nFc, neigh, 1)
    cEst /= nFc[:, None]
    V = np.zeros(ncells)
    C = np.zeros((ncells, 3))
    for cells, sl, sign in ((owner, slice(None), 1.0), (neigh, slice(0, nIn), -1.0)):
        pyr = sign * np.einsum("ij,ij->i", Sf[sl], Cf[sl] - cEst[cells])
        pc = 0.75 * Cf[sl] + 0.25 * cEst[cells]
        np.add.at(V, cells, pyr)
        np.add.at(C, cells, pyr[:, None] * pc)
    C /= V[:, None]
    return C, V / 3.0


def thickness(case):
    """Extent of the mesh in z (one cell thick 2-D cases)."""
    z = read_points(case)[:, 2]
    return float(z.max() - z.min())


def read_entry(path, key):
    """First 'key value;' scalar or word in a dictionary file (no macros)."""
    text = strip(read_text(path))
    m = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), text)
    if not m:
        raise KeyError("%s not in %s" % (key, path))
    v = m.group(1)
    try:
        return float(v)
    except ValueError:
        return v


def read_coeff(path, dict_name, key, default=None):
    """'key value;' inside the first sub-dictionary `dict_name { ... }` of a
    dictionary file (one level, no macros), e.g. penaltyScale of
    perturbedLagrangeCoeffs in 0/D; `default` when the dictionary or the
    key is absent (None: KeyError)."""
    text = strip(read_text(path))
    m = re.search(r"(?:^|[\s{;])%s\s*\{([^{}]*)\}" % re.escape(dict_name), text)
    v = None
    if m:
        e = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), m.group(1))
        v = e.group(1) if e else None
    if v is None:
        if default is not None:
            return default
        raise KeyError("%s of %s not in %s" % (key, dict_name, path))
    try:
        return float(v)
    except ValueError:
        return v


def with_includes(path):
    """The text of a dictionary file with its #include "file" lines
    replaced by the files (relative to its directory), comments removed."""
    text = strip(read_text(path))

    def include(m):
        return with_includes(os.path.join(os.path.dirname(path), m.group(1)))

    return re.sub(r'^\s*#include\s+"([^"]+)"', include, text, flags=re.M)


def entry(text, key, default=None):
    """The first `key value;` in text (a dictionary's text, see strip): a
    float where it is a number, else the word; `default` (None: KeyError)
    where there is none."""
    m = re.search(r"(?:^|[\s{;])%s\s+([^\s;]+)\s*;" % re.escape(key), text)
    if not m:
        if default is not None:
            return default
        raise KeyError(key)
    v = m.group(1)
    try:
        return float(v)
    except ValueError:
        return v


def sub_dict(text, key):
    """The body of the first `key { ... }` in text (braces balanced)."""
    m = re.search(r"(?:^|[\s{;])%s\s*\{" % re.escape(key), text)
    if not m:
        raise KeyError("%s not found" % key)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def _law_constants(text):
    ps = str(entry(text, "planeStress", "no")).lower() in ("yes", "on", "true", "1")
    return entry(text, "E"), entry(text, "nu"), ps


def materials(case):
    """The linear-elastic constants of constant/mechanicalProperties, as
    {zone: (E, nu, planeStress)} for a zoned law and {None: (...)} for one
    law of the whole mesh. #include lines are followed."""
    text = with_includes(os.path.join(case, "constant/mechanicalProperties"))
    if entry(text, "materialLaw") != "zoned":
        return {None: _law_constants(text)}
    coeffs = sub_dict(text, "zonedCoeffs")
    zones = re.findall(r"(?:^|[\s;}])(\w+)\s*\{\s*materialLaw\b", coeffs)
    return {z: _law_constants(sub_dict(coeffs, z)) for z in zones}


def body_constants(case, zones=None):
    """The (E, nu) of the two bodies of a contact case and a one-line
    description, from constant/mechanicalProperties: the one law of the
    whole mesh for both, or (a zoned law) those of the cellZones `zones`
    (two names). A plane-stress law gives nu = 0, so that the plane-strain
    E/(1 - nu^2) of the contact modulus is E. Exits naming the file when
    the law is zoned and `zones` does not name two of its zones."""
    mats = materials(case)

    def plane(c):
        return c[0], 0.0 if c[2] else c[1]

    if None in mats:
        E, nu = plane(mats[None])
        return ((E, nu), (E, nu)), "one law: E = %.6g Pa, nu = %g" % (E, nu)
    if not zones or any(z not in mats for z in zones):
        sys.exit("%s: expected one material law for both bodies, or a zoned law with"
                 " the cellZones %s (found %s)"
                 % (os.path.join(case, "constant/mechanicalProperties"),
                    " and ".join(zones) if zones else "of the two bodies",
                    ", ".join(sorted(mats))))
    bodies = tuple(plane(mats[z]) for z in zones)
    return bodies, "; ".join("%s E = %.6g Pa, nu = %g" % (z, b[0], b[1])
                             for z, b in zip(zones, bodies))


def elastic_constants(case, zone=None):
    """(E, nu, planeStress) from constant/mechanicalProperties: of the one
    law, or of `zone`'s law of a zoned one."""
    mats = materials(case)
    return mats[None] if None in mats else mats[zone]
