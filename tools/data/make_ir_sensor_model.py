#!/usr/bin/python3
"""Writes spectra/data/sensor_ir720_model_10nm.csv: a MODEL (not a measurement) of a full-spectrum-converted
camera (IR-cut filter removed) behind a 720 nm IR-pass filter, 360-1000 nm, for the `ir720_model` sensor
(docs/cameras.md). No measured sensitivities of such a camera were available to us; every shape is an estimate:

  silicon quantum efficiency q(l): 0.10 at 360 nm, rising linearly to 0.55 at 550 nm, flat to 700 nm, falling
      linearly to 0.15 at 1000 nm (the usual shape of a front-illuminated CMOS sensor);
  IR-pass filter T(l) = 1 / (1 + exp(-(l - 720) / 8)) (a "720 nm" long-pass: 50 % at 720 nm);
  Bayer dyes: the red dye passes the near infrared; green and blue become transparent above about 800 and
      820 nm: R = q T, G = q T s(l; 800), B = q T s(l; 820), s(l; m) = 1 / (1 + exp(-(l - m) / 20)).
"""
import sys

import numpy as np

lam = np.arange(360, 1001, 10, dtype=float)
q = np.interp(lam, [360, 550, 700, 1000], [0.10, 0.55, 0.55, 0.15])
T = 1 / (1 + np.exp(-(lam - 720) / 8))
s = lambda m: 1 / (1 + np.exp(-(lam - m) / 20))
r, g, b = q * T, q * T * s(800), q * T * s(820)
with open(sys.argv[1], "w") as out:
    out.write("# MODEL (not a measurement) of a full-spectrum camera behind a 720 nm IR-pass filter, 360-1000 nm:\n")
    out.write("# written by tools/data/make_ir_sensor_model.py, which documents every estimate in it (docs/cameras.md)\n")
    out.write("wavelength_nm,r,g,b\n")
    for row in zip(lam, r, g, b):
        out.write("%d,%.6f,%.6f,%.6f\n" % row)
