#!/usr/bin/python3
"""rigidSphere: the rigid sphere as a triangulated surface (binary STL) for
Allrun -surface triSurface.

The lower cap of the sphere (radius R, centre (0, cy, 0)) over the square
|x|, |z| <= HALF (both signs: the symmetry planes x = 0 and z = 0 are
inside it), a grid of N x N squares of side h = 2 HALF/N in (x, z), each
cut in two triangles, the vertices on the sphere,
y = cy - sqrt(R^2 - x^2 - z^2). The triangles' normals point out of the
sphere (down at the pole), to the block, as the triSurface tool needs.

Size. HALF = 25 mm is 2.5 a at the last step (the cap's rim is 3.2 mm
above the block there, nowhere near it). h = 0.5 mm, half the slave faces
at the contact: a facet lies inside the sphere by at most its sag,
h^2 / (4 R) = 6e-7 m across the squares' diagonals (h^2 / (8 R) = 3e-7 m
along their sides), 0.3 % of the first step's indentation (2e-4 m) at the
worst, 0.03 % of the last; a uniform sag of s would lower F by 1.5 s/delta.
20000 triangles.

    python3 validation/writeSphereStl.py <out.stl> [--centre-y cy]
"""
import argparse
import struct

import numpy as np

R = 0.1
HALF = 0.025
N = 100


def cap(cy, R=R, half=HALF, n=N):
    """(points (m, 3), triangles (k, 3)) of the cap."""
    s = np.linspace(-half, half, n + 1)
    X, Z = np.meshgrid(s, s, indexing="ij")
    Y = cy - np.sqrt(R * R - X ** 2 - Z ** 2)
    pts = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    idx = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
    a, b = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel()        # (i, j), (i+1, j)
    c, d = idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()          # (i+1, j+1), (i, j+1)
    tris = np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    return pts, tris


def write_stl(path, pts, tris):
    p0, p1, p2 = pts[tris[:, 0]], pts[tris[:, 1]], pts[tris[:, 2]]
    nrm = np.cross(p1 - p0, p2 - p0)
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    with open(path, "wb") as f:
        f.write(b"rigidSphere: lower cap of the rigid sphere".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for k in range(len(tris)):
            f.write(struct.pack("<12fH", *nrm[k], *p0[k], *p1[k], *p2[k], 0))
    return nrm


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--centre-y", type=float, default=R)
    args = ap.parse_args()
    pts, tris = cap(args.centre_y)
    nrm = write_stl(args.out, pts, tris)
    # outward: the normal and the direction from the centre agree
    cen = pts[tris].mean(axis=1) - np.array([0.0, args.centre_y, 0.0])
    if (np.einsum("ij,ij->i", nrm, cen) <= 0).any():
        raise SystemExit("writeSphereStl: inward normals")
    h = 2 * HALF / N
    print("rigid sphere STL: %s, %d triangles, R = %g m, centre (0 %g 0), cap |x|, |z| <= %g m,"
          " h = %g m (sag <= %.2g m)" % (args.out, len(tris), R, args.centre_y, HALF, h,
                                         2 * h * h / (8 * R)))


if __name__ == "__main__":
    main()
