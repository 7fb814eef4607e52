#!/usr/bin/python3
"""hertzCylinder: the contact pressure of runs with constitutiveLaw (stiff and soft interface laws) against Hertz.

    validation/plotLaws.py [--png lawPressure.png] <case> [<case> ...]

Each case is a finished `Allrun -method constitutiveLaw [-law soft]`. For
each: the pressure on the slave faces (markers), Hertz's problem with the
case's interface law p = c_N (-g)^n between the surfaces for its measured
load (line; c4fpost.hertz.interface_law_contact) and Hertz's pressure for
that load (dashed): a stiff law lies on Hertz, a soft one spreads the
pressure (lower peak, wider strip). The checks are compareHertz.py's,
run by each case's Allrun; this script only plots. The PNG goes to the
current directory unless --png names another path.
"""
import argparse
import sys

import compareHertz
from c4fpost import hertz, patchtest

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--png", default="lawPressure.png")
    args = ap.parse_args()

    plt = patchtest.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    xr, pr = 0.0, 0.0
    for k, case in enumerate(args.cases):
        res = compareHertz.compare(case)
        if not res.get("law"):
            sys.exit("plotLaws: %s did not run the constitutiveLaw method" % case)
        law, col = res["law"], "C%d" % k
        x, p = np.array(res["x"]), np.array(res["p"])
        xr = max(xr, 1.4 * max(res["aH"], res["aNum"]))
        pr = max(pr, res["p0H"], p.max())
        xx = np.linspace(0, xr, 600)
        name = "c_N = %g, n = %g" % (law["cN"], law["n"])
        ax.plot(xx * 1e3, hertz.pressure(xx, res["P"], compareHertz.R, res["Es"]) / 1e6, "--",
                color=col, lw=1, label="Hertz, P' = %.4g N/m" % res["P"])
        ax.plot(np.array(law["x"]) * 1e3, np.array(law["p"]) / 1e6, "-", color=col, lw=1,
                label="Hertz with the law %s" % name)
        sel = x < xr
        ax.plot(x[sel] * 1e3, p[sel] / 1e6, "o", ms=3.5, color=col,
                label="solidContactFoam, %s: p0 %+.1f %%, a %+.2f mm from Hertz"
                % (name, 100 * (p.max() / res["p0H"] - 1), 1e3 * (res["aNum"] - res["aH"])))
        print("%s: %s, P' = %.6g N/m; Hertz p0 %.5g MPa, a %.4g mm; with the law p0 %.5g MPa,"
              " a %.4g mm; numerical p0 %.5g MPa, a %.4g mm, max penetration %.4g m"
              % (case, name, res["P"], res["p0H"] / 1e6, res["aH"] * 1e3, law["p0"] / 1e6,
                 law["a"] * 1e3, p.max() / 1e6, res["aNum"] * 1e3, law["maxPenetration"]))
    ax.set_xlim(0, xr * 1e3)
    ax.set_ylim(0, 1.1 * pr / 1e6)
    ax.set_xlabel("x [mm] on the slave patch")
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_title("hertzCylinder, constitutiveLaw: stiff and soft interface laws")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print("plot: %s" % args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
