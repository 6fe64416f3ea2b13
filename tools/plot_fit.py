#!/usr/bin/env python3
"""Measurements and fitted model in the plane of incidence (ochre-fit powder --plot, docs/tools.md).

Usage: plot_fit.py VALUES.csv OUT.png [TITLE]

Reads the CSV written by ochre-fit (theta_i,lambda_nm,theta_o_signed,kind,brdf): kind "data" rows are the
measurements of the plane of incidence, kind "model" rows the fitted BRDF every half degree. The abscissa
is the signed outgoing angle, negative on the light's side (backscattering at -theta_i), positive on the
far side (the mirror direction at +theta_i). One colour per (theta_i, wavelength): measurements as dots,
the model as a line; below, the relative residuals (data - model) / model of the measurements.
The PNG is written to OUT.png whatever its extension (ochre-fit passes a temporary name).
"""
import csv
import sys


def read_values(path):
    """{(theta_i, lambda): {"data": [(angle, brdf)], "model": [(angle, brdf)]}}."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (float(row["theta_i"]), float(row["lambda_nm"]))
            curve = curves.setdefault(key, {"data": [], "model": []})
            curve[row["kind"]].append((float(row["theta_o_signed"]), float(row["brdf"])))
    return curves


def model_at(model, angle):
    """The model's value at `angle`, linear between its half-degree samples."""
    for (a0, f0), (a1, f1) in zip(model, model[1:]):
        if a0 <= angle <= a1:
            t = 0.0 if a1 == a0 else (angle - a0) / (a1 - a0)
            return f0 + t * (f1 - f0)
    return None


def main():
    if len(sys.argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 2
    csv_path, png_path = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) == 4 else ""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curves = read_values(csv_path)
    fig, (plane, residual) = plt.subplots(2, 1, figsize=(9.0, 7.5), sharex=True,
                                          gridspec_kw={"height_ratios": [3.0, 1.2]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, ((theta_i, lam), curve) in enumerate(sorted(curves.items())):
        colour = colours[i % len(colours)]
        label = f"theta_i {theta_i:g} deg, {lam:g} nm"
        model = sorted(curve["model"])
        data = sorted(curve["data"])
        if model:
            plane.plot([a for a, _ in model], [f for _, f in model], color=colour, linewidth=1.2,
                       label=label + " (fit)")
        if data:
            plane.plot([a for a, _ in data], [f for _, f in data], "o", color=colour, markersize=3.5,
                       label=label + " (data)")
            points = [(a, f, model_at(model, a)) for a, f in data]
            points = [(a, (f - m) / m) for a, f, m in points if m]
            residual.plot([a for a, _ in points], [r for _, r in points], "o", color=colour, markersize=3.0)
    plane.set_ylabel("BRDF (1/sr)")
    plane.set_ylim(bottom=0.0)
    plane.grid(True, alpha=0.3)
    plane.legend(fontsize=7, ncol=2)
    residual.axhline(0.0, color="0.5", linewidth=0.8)
    residual.set_xlabel("outgoing angle in the plane of incidence (deg; < 0: light's side)")
    residual.set_ylabel("(data - fit) / fit")
    residual.set_xlim(-90, 90)
    residual.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png_path, format="png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
