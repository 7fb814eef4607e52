"""Prototype (issue 10), usage: checkStick.py <case> ux uy [E_upper]. Stick patch test: every cell's sigma against the uniform state
sigma_yy = -E uy/L, sigma_xy = G ux/L, sigma_xx = 0 (nu = 0)."""
import sys, os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../src/postProcessing/python"))
from c4fpost import foamio, patchtest, hertz
import numpy as np
case = sys.argv[1]; ux = float(sys.argv[2]); uy = float(sys.argv[3])
E2 = float(sys.argv[4]) if len(sys.argv) > 4 else 1e6
L = 1.0; E = L/(0.5/1e6 + 0.5/E2); G = E/2
time = foamio.latest_time(case)
C, V = hertz.cell_centres_volumes(case)
S = patchtest.stress_tensor(case, time, V.size)
ex = np.array([[0, G*ux/L, 0], [G*ux/L, -E*uy/L, 0], [0, 0, 0]])
scale = max(abs(E*uy/L), abs(G*ux/L))
err = np.abs(S - ex).max(axis=0)/scale
print("time", time, "max |sigma - exact|/scale per component:")
print("  xx %.3e  xy %.3e  yy %.3e" % (err[0,0], err[0,1], err[1,1]))
print("  sigma_xy range %.9g .. %.9g (exact %g)" % (S[:,0,1].min(), S[:,0,1].max(), G*ux/L))
print("  sigma_yy range %.9g .. %.9g (exact %g)" % (S[:,1,1].min(), S[:,1,1].max(), -E*uy/L))
print("MAXERR %.3e" % err.max())
