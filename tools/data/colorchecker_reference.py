#!/usr/bin/python3
"""Independent reference for the ColorChecker validation (docs/cameras.md, "Colour checker"): the CIELAB
values of the 24 ColorChecker patches (BabelColor average reflectances) lit by a uniform illuminant and seen
by the CIE 1931 observer or by a camera sensor white-balanced to D65, computed from the project's data tables
with numpy alone (no code of the renderer):

  observer:  XYZ_i = sum_l E(l) rho_i(l) cmf(l) / sum_l E(l) ybar(l), 1 nm steps over 360-830 nm, the tables
             interpolated linearly (reflectances held constant beyond their 380-730 nm range, as the renderer's
             CSV spectra are by default); L*a*b* relative to the white under the same illuminant;
  camera:    c_i = sum_l E(l) rho_i(l) s(l) over the sensor's table range (zero outside); a 3x3 matrix M fitted
             by least squares from the c_i (under E) to the observer's XYZ of the same patches under D65,
             constrained to map the white under E onto D65 white (solved as a KKT system, not with the
             closed form the renderer uses); L*a*b* of M c_i relative to D65 white.

Writes CSV rows: illuminant, sensor, patch, L, a, b. Usage:
  /usr/bin/python3 tools/data/colorchecker_reference.py SPECTRA_DATA_DIR OUT.csv
"""
import os
import sys

import numpy as np
from spectral_csv import read_columns

data = sys.argv[1]
lam = np.arange(360.0, 831.0, 1.0)


def table(name):
    return read_columns(os.path.join(data, name))


def resample(t, column, zero_outside=False):
    w = t[list(t)[0]]
    v = np.interp(lam, w, t[column])
    if zero_outside:
        v[(lam < w[0]) | (lam > w[-1])] = 0.0
    return v


cmf_t = table("cie1931_2deg_1nm.csv")
cmf = np.stack([resample(cmf_t, c) for c in ("xbar", "ybar", "zbar")])
d65 = resample(table("d65_5nm.csv"), "S")
checker_t = table("colorchecker_babelcolor_10nm.csv")
patches = list(checker_t)[1:]
rho = np.stack([resample(checker_t, p) for p in patches])


def planck(t):
    l = lam * 1e-9
    return 1.0 / (l**5 * np.expm1(1.4387769e-2 / (l * t)))


def xyz(light, reflectances):
    return (reflectances * light) @ cmf.T / (light * cmf[1]).sum()


def lab(c, white):
    def f(t):
        return np.where(t > (6 / 29) ** 3, np.cbrt(t), t / (3 * (6 / 29) ** 2) + 4 / 29)

    fx, fy, fz = (f(c[:, k] / white[k]) for k in range(3))
    return np.stack([116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)], axis=1)


def camera_matrix(sens, light):
    c = (rho * light) @ sens.T
    x = xyz(d65, rho)
    cw = light @ sens.T
    xw = xyz(d65, np.ones((1, lam.size)))[0]
    # Each row m of M: minimise |C m - x_col|^2 subject to cw . m = xw[row]: KKT [[2 C^T C, cw], [cw^T, 0]].
    kkt = np.zeros((4, 4))
    kkt[:3, :3] = 2 * c.T @ c
    kkt[:3, 3] = cw
    kkt[3, :3] = cw
    M = np.zeros((3, 3))
    for row in range(3):
        rhs = np.concatenate([2 * c.T @ x[:, row], [xw[row]]])
        M[row] = np.linalg.solve(kkt, rhs)[:3]
    return M, c


illuminants = {"D65": d65, "torch": planck(1700.0)}
sensors = {
    "canon_5d_mark_ii": "camera_canon_5d_mark_ii_10nm.csv",
    "nokia_n900": "camera_nokia_n900_10nm.csv",
}
rows = []
for ill_name, light in illuminants.items():
    white = xyz(light, np.ones((1, lam.size)))[0]
    for p, v in zip(patches, lab(xyz(light, rho), white)):
        rows.append((ill_name, "cie1931", p, *v))
    for s_name, file in sensors.items():
        t = table(file)
        sens = np.stack([resample(t, ch, zero_outside=True) for ch in ("r", "g", "b")])
        M, c = camera_matrix(sens, light)
        d65_white = xyz(d65, np.ones((1, lam.size)))[0]
        for p, v in zip(patches, lab(c @ M.T, d65_white)):
            rows.append((ill_name, s_name, p, *v))
with open(sys.argv[2], "w") as out:
    out.write("# written by tools/data/colorchecker_reference.py from spectra/data (docs/cameras.md, 'Colour checker')\n")
    out.write("illuminant,sensor,patch,L,a,b\n")
    for r in rows:
        out.write("%s,%s,%s,%.4f,%.4f,%.4f\n" % r)


def ciede2000(lab1, lab2):
    """Sharma, Wu & Dalal (2005), equations (1)-(22); arrays of shape (n, 3)."""
    L1, a1, b1 = lab1.T
    L2, a2, b2 = lab2.T
    C1, C2 = np.hypot(a1, b1), np.hypot(a2, b2)
    Cm = (C1 + C2) / 2
    G = 0.5 * (1 - np.sqrt(Cm**7 / (Cm**7 + 25.0**7)))
    a1p, a2p = (1 + G) * a1, (1 + G) * a2
    C1p, C2p = np.hypot(a1p, b1), np.hypot(a2p, b2)
    h1p = np.where(C1p == 0, 0, np.degrees(np.arctan2(b1, a1p)) % 360)
    h2p = np.where(C2p == 0, 0, np.degrees(np.arctan2(b2, a2p)) % 360)
    dLp, dCp = L2 - L1, C2p - C1p
    dh = h2p - h1p
    dh = np.where(C1p * C2p == 0, 0, np.where(dh > 180, dh - 360, np.where(dh < -180, dh + 360, dh)))
    dHp = 2 * np.sqrt(C1p * C2p) * np.sin(np.radians(dh / 2))
    Lpm, Cpm = (L1 + L2) / 2, (C1p + C2p) / 2
    hs = h1p + h2p
    hpm = np.where(C1p * C2p == 0, hs, np.where(np.abs(h1p - h2p) <= 180, hs / 2, np.where(hs < 360, (hs + 360) / 2, (hs - 360) / 2)))
    T = (1 - 0.17 * np.cos(np.radians(hpm - 30)) + 0.24 * np.cos(np.radians(2 * hpm))
         + 0.32 * np.cos(np.radians(3 * hpm + 6)) - 0.20 * np.cos(np.radians(4 * hpm - 63)))
    dtheta = 30 * np.exp(-(((hpm - 275) / 25) ** 2))
    RC = 2 * np.sqrt(Cpm**7 / (Cpm**7 + 25.0**7))
    SL = 1 + 0.015 * (Lpm - 50) ** 2 / np.sqrt(20 + (Lpm - 50) ** 2)
    SC, SH = 1 + 0.045 * Cpm, 1 + 0.015 * Cpm * T
    RT = -np.sin(np.radians(2 * dtheta)) * RC
    return np.sqrt((dLp / SL) ** 2 + (dCp / SC) ** 2 + (dHp / SH) ** 2 + RT * (dCp / SC) * (dHp / SH))


if len(sys.argv) > 3 and sys.argv[3] == "--camera-errors":
    # How far each white-balanced camera is from the observer under D65 (Delta E00 over the 24 patches): the
    # colours a photograph white-balanced to D65 shows against the patches' daylight colours.
    ref = {}
    for r in rows:
        ref.setdefault((r[0], r[1]), []).append(r[3:])
    for ill in illuminants:
        for s_name in sensors:
            d = ciede2000(np.array(ref[("D65", "cie1931")]), np.array(ref[(ill, s_name)]))
            print("%-6s %-17s mean %.2f  max %.2f (%s)" % (ill, s_name, d.mean(), d.max(), patches[int(d.argmax())]))
