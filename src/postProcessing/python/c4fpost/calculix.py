"""CalculiX (Debian calculix-ccx) helpers of the tutorials' finite-element
references: gmsh's Abaqus .inp read back, plane 8-node quadrilaterals
(CPE8) made counter-clockwise, element faces on a node set, and the total
reaction of a node set from ccx's .dat.

Used by the validation/calculix.py of finiteStrainCylinder and
selfContactStrip; nothing here runs in make test (the references are
committed as CSV files).
"""
import re

import numpy as np


def read_inp(path):
    """Nodes {id: (x, y)}, elements by ELSET {name: [(id, [nodes])]},
    node sets {name: [ids]} of gmsh's .inp."""
    nodes, elsets, nsets = {}, {}, {}
    mode, name = None, None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("**"):
                continue
            if s.startswith("*"):
                head = s.upper()
                if head.startswith("*NODE") and "NSET" not in head.split(",")[0][5:]:
                    mode = "node"
                elif head.startswith("*ELEMENT"):
                    m = re.search(r"ELSET=([^,\s]+)", s, re.I)
                    name = m.group(1) if m else None
                    mode = "elem" if name else None
                    if name:
                        elsets.setdefault(name, [])
                elif head.startswith("*NSET"):
                    m = re.search(r"NSET=([^,\s]+)", s, re.I)
                    name = m.group(1)
                    nsets.setdefault(name, [])
                    mode = "nset"
                else:
                    mode = None
                continue
            vals = [v for v in s.split(",") if v.strip()]
            if mode == "node":
                nodes[int(vals[0])] = (float(vals[1]), float(vals[2]))
            elif mode == "elem":
                ids = [int(v) for v in vals]
                if elsets[name] and len(elsets[name][-1][1]) < 8:
                    elsets[name][-1][1].extend(ids)
                else:
                    elsets[name].append((ids[0], ids[1:]))
            elif mode == "nset":
                nsets[name].extend(int(v) for v in vals)
    return nodes, elsets, nsets


def counter_clockwise(conn, nodes):
    """The 8-node quad's connectivity, reversed if it runs clockwise."""
    if len(conn) != 8:
        return conn
    p = np.array([nodes[n] for n in conn[:4]])
    area = 0.5*sum(p[k, 0]*p[(k + 1) % 4, 1] - p[(k + 1) % 4, 0]*p[k, 1]
                   for k in range(4))
    if area > 0:
        return conn
    c, m = conn[:4], conn[4:]
    return [c[0], c[3], c[2], c[1], m[3], m[2], m[1], m[0]]


def element_faces_on(elements, nodeset):
    """(element, face) of the 8-node quads whose edge has both corners in
    nodeset; faces 1-4 are the edges 1-2, 2-3, 3-4, 4-1 (CalculiX's
    numbering for plane elements)."""
    faces = []
    inset = set(nodeset)
    for eid, conn in elements:
        c = conn[:4]
        for k in range(4):
            if c[k] in inset and c[(k + 1) % 4] in inset:
                faces.append((eid, k + 1))
    return faces


def read_totals(dat, nset, column=1):
    """(time, total force component) of every increment's *NODE PRINT,
    TOTALS=ONLY of node set nset in ccx's .dat (column 0, 1, 2: x, y,
    z)."""
    out = []
    lines = open(dat).read().splitlines()
    pattern = re.compile(r"total force \(fx,fy,fz\) for set %s and time\s+(\S+)"
                         % re.escape(nset.upper()))
    for i, line in enumerate(lines):
        m = pattern.search(line)
        if m:
            t = float(m.group(1))
            for j in range(i + 1, min(i + 4, len(lines))):
                v = lines[j].split()
                if len(v) == 3:
                    out.append((t, float(v[column])))
                    break
    return out


def read_frd_contact(frd):
    """{time: {node: CPRESS}} of every CONTACT block (*CONTACT FILE, CSTR)
    in ccx's .frd: the contact pressure at the slave nodes."""
    out = {}
    time, block = None, None
    with open(frd) as f:
        for line in f:
            if line.startswith("  100CL"):
                time = float(line[12:25])
                block = None
            elif line.startswith(" -4"):
                block = {} if line.split()[1] == "CONTACT" else None
                if block is not None:
                    out[time] = block
            elif block is not None and line.startswith(" -1"):
                # fixed format: the node in columns 3-12, then 12-wide values
                node = int(line[3:13])
                vals = [float(line[13 + 12*k:25 + 12*k]) for k in range(6)]
                block[node] = vals[3]
            elif line.startswith(" -3"):
                block = None
    return out


def edge_force(nodes, edges, pressure):
    """The force of a nodal pressure over the 3-node edges (corner, corner,
    middle) of 8-node quadrilaterals: Simpson's rule on each edge (exact for
    the quadratic interpolation), per unit thickness."""
    total = 0.0
    for a, b, m in edges:
        length = np.hypot(nodes[b][0] - nodes[a][0], nodes[b][1] - nodes[a][1])
        total += length*(pressure.get(a, 0.0) + 4*pressure.get(m, 0.0)
                         + pressure.get(b, 0.0))/6
    return total


def face_edges(elements, faces):
    """The (corner, corner, middle) nodes of element faces (element, k) of
    element_faces_on."""
    conn = dict(elements)
    out = []
    for eid, k in faces:
        c = conn[eid]
        out.append((c[k - 1], c[k % 4], c[4 + k - 1]))
    return out


def read_section_forces(dat):
    """{time: (fx, fy, fz)} of *SECTION PRINT, SOF in ccx's .dat: the total
    force on the surface set."""
    out = {}
    lines = open(dat).read().splitlines()
    for i, line in enumerate(lines):
        m = re.search(r"statistics for surface set \S+ and time\s+(\S+)", line)
        if m:
            for j in range(i + 1, min(i + 6, len(lines))):
                v = lines[j].split()
                if len(v) == 6:
                    out[float(m.group(1))] = tuple(float(x) for x in v[:3])
                    break
    return out
