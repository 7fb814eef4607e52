"""Minimal readers for OpenFOAM ASCII files (writeFormat ascii).

Only what validation needs: a field's internalField or one patch's value,
a polyMesh boundary file, and the owner list. Uniform and nonuniform
scalar, vector, symmTensor and tensor lists are understood.
"""
import os
import re

import numpy as np

_NCOMP = {"scalar": 1, "vector": 3, "symmTensor": 6, "tensor": 9, "label": 1}


def _strip_comments(text):
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
    text = _strip_comments(open(path).read())
    m = re.search(r"\binternalField\b", text)
    return _parse_value(text, m.end(), ncells or 0)


def read_patch(path, patch, nfaces=None, key="value"):
    """The 'value' (or another field-valued) entry of one patch of a field
    file."""
    text = _strip_comments(open(path).read())
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
    text = open(path).read()
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


def read_boundary(case):
    """{patch: (startFace, nFaces, type)} from constant/polyMesh/boundary."""
    text = _strip_comments(open(os.path.join(case, "constant/polyMesh/boundary")).read())
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
    text = _strip_comments(open(os.path.join(case, "constant/polyMesh/owner")).read())
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
