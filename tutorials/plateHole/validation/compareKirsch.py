#!/usr/bin/python3
"""plateHole: compare sigma_xx along the symmetry line x = 0 with Kirsch.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) reads
them with --json.

Tolerance on max |sigma_xx - Kirsch| / (3T) along the line:
    0.5 h1/R + 0.025
  - 0.025 bounds the mesh-converged error, which is the finite plate's
    departure from Kirsch's infinite one (plate 12R x 12R, uniform traction
    on the right edge, free top edge). `make bench` measured it levelling
    off at 2.06 % of 3T on 19200 cells (h1/R = 0.02).
  - h1 is the radial size of the first cell at the hole. The stress is
    sampled at cell centres; above the floor the error falls about
    linearly with h1 (measured 7.2 %, 3.6 %, 2.4 %, 2.1 % of the peak for
    h1/R = 0.16, 0.082, 0.041, 0.02), i.e. a slope of 0.2-0.35 above the
    floor, which 0.5 bounds with margin.
  The default mesh (h1/R = 0.082) measures 3.6 % against 6.6 %.
"""
import os
import sys

from c4fpost import foamio, kirsch, report

import numpy as np

T = 1e6     # applied traction [Pa], 0/D
R = 0.1     # hole radius [m], system/blockMeshDict


def compare(case):
    time = foamio.latest_time(case)
    C = foamio.read_internal(os.path.join(case, time, "C"))
    sigma = foamio.read_internal(os.path.join(case, time, "sigma"))
    cells = foamio.patch_face_cells(case, "left")
    order = np.argsort(C[cells, 1])
    cells = cells[order]
    x, y = C[cells, 0], C[cells, 1]
    num = sigma[cells, 0]
    ref, _, _ = kirsch.stress_xy(x, y, T, R)
    err = np.abs(num - ref) / (3 * T)
    h1 = 2 * (y.min() - R)
    tol = 0.5 * h1 / R + 0.025
    szz = np.abs(sigma[:, 5]).max() / T
    checks = [
        dict(name="plateHole/sxx_symmetry_line_max_error", value=float(err.max()),
             reference=0.0, error=float(err.max()), tolerance=float(tol),
             units="fraction of 3T"),
        dict(name="plateHole/peak_sxx_first_cell", value=float(num[0]),
             reference=float(ref[0]), error=float(abs(num[0] - ref[0]) / ref[0]),
             tolerance=float(tol * 3 * T / ref[0]), units="Pa"),
        dict(name="plateHole/plane_stress_szz", value=float(szz), reference=0.0,
             error=float(szz), tolerance=1e-12, units="fraction of T"),
    ]
    for c in checks:
        c["passed"] = bool(c["error"] <= c["tolerance"])
    return dict(time=time, y=y.tolist(), sxx=num.tolist(), kirsch=ref.tolist(),
                h1=float(h1), checks=checks)


def plot(result, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    y = np.array(result["y"])
    yy = np.linspace(R, y.max(), 400)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(yy / R, kirsch.sxx_symmetry_line(yy, T, R) / T, "k-", label="Kirsch (infinite plate)")
    ax.plot(y / R, np.array(result["sxx"]) / T, "o", ms=4, label="solidContactFoam (cell centres)")
    ax.set_xlabel("y / R on x = 0")
    ax.set_ylabel(r"$\sigma_{xx}$ / T")
    ax.set_title("plateHole: stress concentration at the hole")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = report.parse_args(__doc__, "plateHole.png")
    res = compare(args.case)
    print("plateHole: sigma_xx on x = 0 against Kirsch (time %s, h1/R = %.4f)"
          % (res["time"], res["h1"] / R))
    print("%10s %14s %14s %10s" % ("y/R", "sxx [Pa]", "Kirsch [Pa]", "err/3T"))
    for yi, n, k in list(zip(res["y"], res["sxx"], res["kirsch"]))[::3]:
        print("%10.4f %14.6g %14.6g %10.4f" % (yi / R, n, k, abs(n - k) / (3 * T)))
    return report.finish(res, args.case, args.png, args.json, plot)


if __name__ == "__main__":
    sys.exit(main())
