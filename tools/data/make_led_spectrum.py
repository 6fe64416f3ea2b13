#!/usr/bin/python3
"""Writes spectra/data/led_white_4100k_model_5nm.csv: a MODEL of a phosphor-converted white LED (blue pump
plus a broad phosphor band), not a measured spectrum. Used by the LED work-light preset (docs/lights.md)
because no tabulated CIE LED illuminant (CIE 15:2018, LED-B3) ships with ochre. The model has LED-B3's
correlated colour temperature (4103 K) and lies on the Planckian locus (Duv 0).

  S(l) = G(l; 452 nm, 11 nm) + a G(l; 558 nm, 50 nm) + b G(l; 615 nm, 42 nm),  G = exp(-(l - m)^2 / (2 s^2))

a and b are solved so that the CIE 1931 chromaticity of S is that of a blackbody at 4103 K. numpy only.
Run: /usr/bin/python3 tools/data/make_led_spectrum.py spectra/data/cie1931_2deg_1nm.csv OUT.csv
"""
import sys

import numpy as np
from spectral_csv import read_table

header, table = read_table(sys.argv[1])
lam, xbar, ybar, zbar = (table[:, header.index(name)] for name in (header[0], "xbar", "ybar", "zbar"))


def gauss(m, s):
    return np.exp(-((lam - m) ** 2) / (2 * s * s))


def xy(spd):
    X, Y, Z = (spd * xbar).sum(), (spd * ybar).sum(), (spd * zbar).sum()
    return np.array([X / (X + Y + Z), Y / (X + Y + Z)])


def planck(t):
    l = lam * 1e-9
    return 1.0 / (l**5 * (np.exp(1.4387769e-2 / (l * t)) - 1.0))


target = xy(planck(4103.0))
blue, green, red = gauss(452, 11), gauss(558, 50), gauss(615, 42)
p = np.array([1.5, 0.5])
for _ in range(50):  # Newton on (a, b) with a numerical Jacobian
    f = xy(blue + p[0] * green + p[1] * red) - target
    J = np.empty((2, 2))
    for k in range(2):
        dp = p.copy()
        dp[k] += 1e-6
        J[:, k] = (xy(blue + dp[0] * green + dp[1] * red) - target - f) / 1e-6
    p = p - np.linalg.solve(J, f)
spd = blue + p[0] * green + p[1] * red
spd /= spd.max()
with open(sys.argv[2], "w") as out:
    out.write("# MODEL of a phosphor-converted white LED (not a measurement): written by tools/data/make_led_spectrum.py\n")
    out.write("# S = G(452, 11) + a G(558, 50) + b G(615, 42) nm, a = %.6f, b = %.6f, peak-normalised;\n" % tuple(p))
    out.write("# chromaticity of a 4103 K blackbody (the CCT of CIE 15:2018 LED-B3), CIE 1931 x, y = %.5f, %.5f\n" % tuple(target))
    out.write("wavelength_nm,S\n")
    for l in range(360, 831, 5):
        out.write("%d,%.6f\n" % (l, spd[int(l - lam[0])]))
print("a, b =", p, "xy =", xy(spd), "target", target)
