#!/usr/bin/python3
"""contactPatchTest3D -finiteStrain: the uniaxial finite-strain state
across a non-matching interface, in 3D.

The checks, their tolerances and where the tolerances come from live here,
once: the tutorial prints them, the regression tests (tests/, pytest) read
them with --json.

The two boxes (column height L = 1 m, slave 10 x 8 faces on master 7 x 5)
are neo-Hookean (tau = mu (b - I) + lambda ln J I) under nonlinearGeometry
yes and pressed to a = 1 - Delta/L = 0.8 of their height in one step, the
top sliding freely along itself, the bottom held normally, x' = 0 and
y' = 0 symmetry planes, x' = 1 and y' = 1 free (primes: the box's axes,
turned by -rotate). The exact state is uniform and uniaxial, F' = diag(s,
s, a); the lateral stretch s makes the lateral Cauchy stress zero:

    tau_xx = mu (s^2 - 1) + lambda ln J = 0,   J = a s^2

(bisection), and then sigma'_zz = (mu (a^2 - 1) + lambda ln J)/J. The
displacement is linear: D' = ((s - 1) x', (s - 1) y', (a - 1)(z' + 0.5)).
The contact pressure the solver writes is per current area: -sigma'_zz on
every slave face.

Checks:
  - the step converged (outer residual below solidMechanics' tolerance,
    1e-9 as in the small-strain test);
  - exact methods (answer=exact in solidContactFoam -listMethods): in
    every cell |sigma'_zz/sigma_exact - 1| <= 1e-6 and D' within 1e-6
    Delta of the exact field; every slave face's pressure within 1e-6 of
    -sigma_exact;
  - the penalty family (a spring in series: uniform with an offset):
    (max - min) sigma'_zz/|sigma_exact| <= 1e-6, the offset printed;
  - every method: the other components of sigma' at most 1e-6
    |sigma_exact| in every cell (uniaxial).
"""
import os

import numpy as np

from c4fpost import foamio, neohookean, patchtest, report

NAME = "contactPatchTest3D"
L = 1.0          # column height [m], system/blockMeshDict
DELTA = 0.2      # the top's displacement [m] under -finiteStrain (Allrun)
SLAVE = "upperBottom"
TOP = "upperTop"
SYMMETRY_X = "symmetryX"
EXACT_TOL = 1e-6
OTHERS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}


def closed_form(E, nu, a):
    """(s, sigma'_zz) of the uniaxial 3D compressible neo-Hookean."""
    s, _, szz, _ = neohookean.uniaxial(E, nu, a, 2)
    return s, szz


def compare(case):
    contact, method = patchtest.contact_variant(case, SLAVE)
    mp = os.path.join(case, "constant", "mechanicalProperties")
    E = float(foamio.read_coeff(mp, "neoHookeanCoeffs", "E"))
    nu = float(foamio.read_coeff(mp, "neoHookeanCoeffs", "nu"))
    a = 1 - DELTA / L
    s, exact = closed_form(E, nu, a)
    res = dict(method=method, E=E, nu=nu, s=s, exact=exact)
    conv, step, ncorr = patchtest.convergence_check(case, NAME)
    checks = [conv]
    try:
        time = foamio.latest_time(case)
    except FileNotFoundError:
        checks.append(dict(name=NAME + "/result", value=float("inf"), reference=0.0,
                           error=float("inf"), tolerance=0.0, passed=False,
                           units="no time written: see log.solidContactFoam"))
        res["checks"] = checks
        return res

    R = patchtest.rotation_from_mesh(case, TOP, SYMMETRY_X)
    C, V = foamio.cell_centres_volumes(case)
    Cr = C @ R
    S = patchtest.stress_tensor(case, time, V.size)
    Sr = np.einsum("ki,nkl,lj->nij", R, S, R)
    szz = Sr[:, 2, 2]
    others = {k: float(np.abs(Sr[:, i, j]).max() / abs(exact)) for k, (i, j) in OTHERS.items()}
    worst = max(others, key=others.get)
    maxRel, spread = patchtest.uniformity(szz, exact)
    res.update(time=time, rotated=bool(np.abs(R - np.eye(3)).max() > 1e-6), maxRel=maxRel,
               spread=spread, others=others, step=step, nCorrectors=ncorr)

    if method and patchtest.method_check(method)["kind"] == "exact":
        checks.append(dict(name=NAME + "/finite_strain_szz", value=maxRel, reference=0.0,
                           error=maxRel, tolerance=EXACT_TOL,
                           units="max over cells |sigma'_zz/sigma_exact - 1| (sigma_exact"
                           " = %.8g Pa, s = %.8f)" % (exact, s)))
        D = foamio.read_internal(os.path.join(case, time, "D"), V.size) @ R
        Dexact = np.column_stack(((s - 1) * Cr[:, 0], (s - 1) * Cr[:, 1],
                                  (a - 1) * (Cr[:, 2] + 0.5 * L)))
        dErr = float(np.abs(D - Dexact).max() / DELTA)
        res["dErr"] = dErr
        checks.append(dict(name=NAME + "/finite_strain_displacement", value=dErr,
                           reference=0.0, error=dErr, tolerance=EXACT_TOL,
                           units="max over cells |D' - D'_exact|/Delta"))
        n = foamio.patch_face_cells(case, SLAVE).size
        p = np.asarray(foamio.read_patch(os.path.join(case, time, "contactPressure"),
                                         SLAVE, n), dtype=float)
        pErr = float(np.abs(p / -exact - 1).max())
        res["pErr"] = pErr
        checks.append(dict(name=NAME + "/finite_strain_pressure", value=pErr, reference=0.0,
                           error=pErr, tolerance=EXACT_TOL,
                           units="max over slave faces |p/(-sigma_exact) - 1|"))
    else:
        checks.append(dict(name=NAME + "/finite_strain_szz_uniform", value=spread,
                           reference=0.0, error=spread, tolerance=EXACT_TOL,
                           units="(max - min) sigma'_zz/|sigma_exact| (offset %+.3g)"
                           % (float(np.mean(szz)) / exact - 1)))
    checks.append(dict(name=NAME + "/finite_strain_other_components", value=others[worst],
                       reference=0.0, error=others[worst], tolerance=EXACT_TOL,
                       units="max |sigma'_%s|/|sigma_exact|" % worst))
    patchtest.set_passed(checks)
    res["checks"] = checks
    res["colZ"] = Cr[:, 2].tolist()
    res["szz"] = szz.tolist()
    return res


def plot(res, png):
    if "szz" not in res:
        return
    plt = patchtest.pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(res["colZ"], np.array(res["szz"]) / 1e3, ".", label="cells")
    ax.axhline(res["exact"] / 1e3, color="k", ls="--", label="closed form")
    ax.set_xlabel("z' of the cell centre (reference) [m]")
    ax.set_ylabel("sigma'_zz [kPa]")
    ax.set_title("contactPatchTest3D -finiteStrain: %s, nu %g%s"
                 % (res["method"], res["nu"], ", rotated" if res.get("rotated") else ""),
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    args = report.parse_args(__doc__, "finiteStrain3D.png")
    res = compare(args.case)
    print("%s -finiteStrain: method %s, nu %g, a = %.3f: s = %.8f, sigma'_zz exact %.8g Pa"
          % (NAME, res["method"], res["nu"], 1 - DELTA / L, res["s"], res["exact"]))
    report.finish(res, args.case, args.png, args.json, plot)
    return 0 if all(c["passed"] for c in res["checks"]) else 1


if __name__ == "__main__":
    raise SystemExit(main())
