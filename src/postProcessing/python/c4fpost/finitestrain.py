"""The 3D finite-strain contact patch test (contactPatchTest3D and
contactPatchTestTets -finiteStrain): two neo-Hookean boxes (tau = mu (b - I)
+ lambda ln J I) of one column, height L, pressed to a = 1 - Delta/L of
their height in one step across a non-matching interface, the top sliding
freely along itself, the bottom held normally, x' = 0 and y' = 0 symmetry
planes, x' = 1 and y' = 1 free (primes: the box's axes, turned by
-rotate). The exact state is uniform and uniaxial, F' = diag(s, s, a); the
lateral stretch s makes the lateral Cauchy stress zero:

    tau_xx = mu (s^2 - 1) + lambda ln J = 0,   J = a s^2

(bisection), and then sigma'_zz = (mu (a^2 - 1) + lambda ln J)/J. The
displacement is linear: D' = ((s - 1) x', (s - 1) y', (a - 1)(z' + L/2)).
The contact pressure the solver writes is per current area: -sigma'_zz on
every slave face.

The tutorials' scripts keep the case's constants and tolerances; this
module builds the checks (c4fpost.report's dicts) and the plot:
  - the step converged (outer residual below solidMechanics' tolerance);
  - exact methods (answer=exact in solidContactFoam -listMethods): in
    every cell |sigma'_zz/sigma_exact - 1| <= exact_tol and D' within
    exact_tol Delta of the exact field; every slave face's pressure within
    exact_tol of -sigma_exact;
  - the penalty family (a spring in series: uniform with an offset):
    (max - min) sigma'_zz/|sigma_exact| <= exact_tol, the offset printed;
  - every method: the other components of sigma' at most exact_tol
    |sigma_exact| in every cell (uniaxial).
"""
import os

import numpy as np

from c4fpost import foamio, neohookean, patchtest, report

OTHERS = {"xx": (0, 0), "yy": (1, 1), "xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}


class FiniteStrainPatchTest3D:
    """`name` prefixes the checks; `slave`, `top` and `symmetry_x` are the
    patches (the last two give the mesh's rotation); `delta` and `length`
    the column's; `exact_tol` the tolerance of every check."""

    def __init__(self, name, slave, top, symmetry_x, delta, length, exact_tol):
        self.name = name
        self.slave = slave
        self.top = top
        self.symmetry_x = symmetry_x
        self.delta = delta
        self.length = length
        self.exact_tol = exact_tol

    @staticmethod
    def closed_form(E, nu, a):
        """(s, sigma'_zz) of the uniaxial 3D compressible neo-Hookean."""
        s, _, szz, _ = neohookean.uniaxial(E, nu, a, 2)
        return s, szz

    def compare(self, case):
        """The checks and fields of the case (a dict with 'checks')."""
        contact, method = patchtest.contact_variant(case, self.slave)
        mp = os.path.join(case, "constant", "mechanicalProperties")
        E = float(foamio.read_coeff(mp, "neoHookeanCoeffs", "E"))
        nu = float(foamio.read_coeff(mp, "neoHookeanCoeffs", "nu"))
        a = 1 - self.delta / self.length
        s, exact = self.closed_form(E, nu, a)
        res = dict(method=method, E=E, nu=nu, s=s, exact=exact)
        conv, step, ncorr = patchtest.convergence_check(case, self.name)
        checks = [conv]
        try:
            time = foamio.latest_time(case)
        except FileNotFoundError:
            checks.append(dict(name=self.name + "/result", value=float("inf"), reference=0.0,
                               error=float("inf"), tolerance=0.0, passed=False,
                               units="no time written: see log.solidContactFoam"))
            res["checks"] = checks
            return res

        R = patchtest.rotation_from_mesh(case, self.top, self.symmetry_x)
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
            checks.append(dict(name=self.name + "/finite_strain_szz", value=maxRel, reference=0.0,
                               error=maxRel, tolerance=self.exact_tol,
                               units="max over cells |sigma'_zz/sigma_exact - 1| (sigma_exact"
                               " = %.8g Pa, s = %.8f)" % (exact, s)))
            D = foamio.read_internal(os.path.join(case, time, "D"), V.size) @ R
            Dexact = np.column_stack(((s - 1) * Cr[:, 0], (s - 1) * Cr[:, 1],
                                      (a - 1) * (Cr[:, 2] + 0.5 * self.length)))
            dErr = float(np.abs(D - Dexact).max() / self.delta)
            res["dErr"] = dErr
            checks.append(dict(name=self.name + "/finite_strain_displacement", value=dErr,
                               reference=0.0, error=dErr, tolerance=self.exact_tol,
                               units="max over cells |D' - D'_exact|/Delta"))
            n = foamio.patch_face_cells(case, self.slave).size
            p = np.asarray(foamio.read_patch(os.path.join(case, time, "contactPressure"),
                                             self.slave, n), dtype=float)
            pErr = float(np.abs(p / -exact - 1).max())
            res["pErr"] = pErr
            checks.append(dict(name=self.name + "/finite_strain_pressure", value=pErr, reference=0.0,
                               error=pErr, tolerance=self.exact_tol,
                               units="max over slave faces |p/(-sigma_exact) - 1|"))
        else:
            checks.append(dict(name=self.name + "/finite_strain_szz_uniform", value=spread,
                               reference=0.0, error=spread, tolerance=self.exact_tol,
                               units="(max - min) sigma'_zz/|sigma_exact| (offset %+.3g)"
                               % (float(np.mean(szz)) / exact - 1)))
        checks.append(dict(name=self.name + "/finite_strain_other_components", value=others[worst],
                           reference=0.0, error=others[worst], tolerance=self.exact_tol,
                           units="max |sigma'_%s|/|sigma_exact|" % worst))
        patchtest.set_passed(checks)
        res["checks"] = checks
        res["colZ"] = Cr[:, 2].tolist()
        res["szz"] = szz.tolist()
        return res

    def plot(self, res, png):
        """sigma'_zz of every cell against the closed form."""
        plt = patchtest.pyplot()
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(res["colZ"], np.array(res["szz"]) / 1e3, ".", label="cells")
        ax.axhline(res["exact"] / 1e3, color="k", ls="--", label="closed form")
        ax.set_xlabel("z' of the cell centre (reference) [m]")
        ax.set_ylabel("sigma'_zz [kPa]")
        ax.set_title("%s -finiteStrain: %s, nu %g%s"
                     % (self.name, res["method"], res["nu"], ", rotated" if res.get("rotated") else ""),
                     fontsize=9)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(png, dpi=110)

    def main(self, doc, png):
        """Compare the case of the command line, print, plot, write JSON."""
        args = report.parse_args(doc, png)
        res = self.compare(args.case)
        print("%s -finiteStrain: method %s, nu %g, a = %.3f: s = %.8f, sigma'_zz exact %.8g Pa"
              % (self.name, res["method"], res["nu"], 1 - self.delta / self.length, res["s"],
                 res["exact"]))
        return report.finish(res, args.case, args.png, args.json, self.plot,
                             complete="szz" in res)
