#!/usr/bin/python3
"""rigidPunch: write the flat-ended cylindrical punch as an ASCII STL, a
closed surface with outward normals: the flat end (a disc of radius a in
the plane y = y0), the side up to y0 + H, and the top.

    writePunchStl.py <file.stl> [--radius A] [--height H] [--bottom Y0] [--n N]

The rim is a polygon of N points on the circle (default 720: its area is
(N/2pi) sin(2pi/N) of the disc's, 1 - 1.3e-5, far below the mesh's
error)."""
import argparse
import math

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("file")
    ap.add_argument("--radius", type=float, default=0.01)
    ap.add_argument("--height", type=float, default=0.02)
    ap.add_argument("--bottom", type=float, default=0.0)
    ap.add_argument("--n", type=int, default=720)
    a = ap.parse_args()
    th = np.linspace(0, 2 * math.pi, a.n, endpoint=False)
    rim = np.c_[a.radius * np.cos(th), np.full(a.n, a.bottom), a.radius * np.sin(th)]
    top = rim + np.array([0, a.height, 0])
    c0 = np.array([0, a.bottom, 0.0])
    c1 = np.array([0, a.bottom + a.height, 0.0])
    tris = []
    for i in range(a.n):
        j = (i + 1) % a.n
        # Each triangle's vertices in the order of its outward normal
        tris.append((c0, rim[i], rim[j]))             # the end, normal -y
        tris.append((rim[i], top[j], rim[j]))         # the side, radial
        tris.append((rim[i], top[i], top[j]))
        tris.append((c1, top[j], top[i]))             # the top, normal +y
    with open(a.file, "w") as f:
        f.write("solid punch\n")
        for t in tris:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            n /= np.linalg.norm(n)
            f.write("facet normal %.9g %.9g %.9g\n outer loop\n" % tuple(n))
            for p in t:
                f.write("  vertex %.12g %.12g %.12g\n" % tuple(p))
            f.write(" endloop\nendfacet\n")
        f.write("endsolid punch\n")
    print("punch: radius %g m, height %g m, end at y = %g, %d triangles"
          % (a.radius, a.height, a.bottom, len(tris)))


if __name__ == "__main__":
    main()
