"""Kirsch (1898) solution: infinite plane with a circular hole of radius R
under remote uniaxial tension T along x, in polar coordinates (r, theta)
with theta measured from the load axis (Timoshenko & Goodier, 3rd ed.,
sec. 35, eq. 61):

  s_rr = T/2 (1 - R^2/r^2) + T/2 (1 + 3R^4/r^4 - 4R^2/r^2) cos 2t
  s_tt = T/2 (1 + R^2/r^2) - T/2 (1 + 3R^4/r^4) cos 2t
  s_rt = -T/2 (1 - 3R^4/r^4 + 2R^2/r^2) sin 2t

On the symmetry line x = 0 this gives s_xx = T (1 + R^2/(2y^2) + 3R^4/(2y^4)),
3T at the hole.
"""
import numpy as np


def stress_xy(x, y, T, R):
    """Cartesian (s_xx, s_yy, s_xy) at points (x, y)."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    r2 = x * x + y * y
    t = np.arctan2(y, x)
    q = R * R / r2
    c2, s2 = np.cos(2 * t), np.sin(2 * t)
    srr = 0.5 * T * (1 - q) + 0.5 * T * (1 + 3 * q * q - 4 * q) * c2
    stt = 0.5 * T * (1 + q) - 0.5 * T * (1 + 3 * q * q) * c2
    srt = -0.5 * T * (1 - 3 * q * q + 2 * q) * s2
    c, s = np.cos(t), np.sin(t)
    sxx = srr * c * c + stt * s * s - 2 * srt * s * c
    syy = srr * s * s + stt * c * c + 2 * srt * s * c
    sxy = (srr - stt) * s * c + srt * (c * c - s * s)
    return sxx, syy, sxy


def sxx_symmetry_line(y, T, R):
    """s_xx on x = 0."""
    y = np.asarray(y, float)
    return T * (1 + 0.5 * R ** 2 / y ** 2 + 1.5 * R ** 4 / y ** 4)
