#!/usr/bin/env python3
"""Measurements and fitted model in the plane of incidence (ochre-fit powder --plot, docs/tools.md).

Usage: plot_fit.py VALUES.csv OUT.png [TITLE]

Reads the CSV written by ochre-fit (theta_i,lambda_nm,theta_o_signed,kind,brdf): kind "data" rows are the
measurements of the plane of incidence, kind "model" rows the fitted BRDF every half degree. One column
of panels per incidence angle; the abscissa is the signed outgoing angle, negative on the light's side
(backscattering at -theta_i), positive on the far side (the mirror direction at +theta_i). One colour per
wavelength: measurements as dots, the model as a line; below, the relative residuals (data - fit) / fit
of the measurements in percent. The PNG is written to OUT.png whatever its extension (ochre-fit passes a
temporary name).
"""
import csv
import sys


def read_values(path):
    """{theta_i: {lambda: {"data": [(angle, brdf)], "model": [(angle, brdf)]}}}."""
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            by_lambda = curves.setdefault(float(row["theta_i"]), {})
            curve = by_lambda.setdefault(float(row["lambda_nm"]), {"data": [], "model": []})
            curve[row["kind"]].append((float(row["theta_o_signed"]), float(row["brdf"])))
    return curves


def model_at(model, angle):
    """The model's value at `angle`, linear between its half-degree samples."""
    for (a0, f0), (a1, f1) in zip(model, model[1:]):
        if a0 <= angle <= a1:
            t = 0.0 if a1 == a0 else (angle - a0) / (a1 - a0)
            return f0 + t * (f1 - f0)
    return None


def colour_of(lam, lambdas, colormap):
    """Blue to red over the wavelengths present."""
    low, high = min(lambdas), max(lambdas)
    return colormap(0.0 if high == low else 0.05 + 0.9 * (lam - low) / (high - low))


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
    incidences = sorted(curves)
    lambdas = sorted({lam for by_lambda in curves.values() for lam in by_lambda})
    columns = max(1, len(incidences))
    fig, axes = plt.subplots(2, columns, figsize=(3.4 * columns + 1.0, 6.0), sharex=True, squeeze=False,
                             gridspec_kw={"height_ratios": [3.0, 1.2]})
    colormap = plt.get_cmap("turbo")
    for column, theta_i in enumerate(incidences):
        plane, residual = axes[0][column], axes[1][column]
        for lam, curve in sorted(curves[theta_i].items()):
            colour = colour_of(lam, lambdas, colormap)
            model = sorted(curve["model"])
            data = sorted(curve["data"])
            if model:
                plane.plot([a for a, _ in model], [f for _, f in model], color=colour, linewidth=1.2,
                           label=f"{lam:g} nm")
            if data:
                plane.plot([a for a, _ in data], [f for _, f in data], "o", color=colour, markersize=3.0)
                points = [(a, f, model_at(model, a)) for a, f in data]
                points = [(a, 100.0 * (f - m) / m) for a, f, m in points if m]
                residual.plot([a for a, _ in points], [r for _, r in points], "o", color=colour, markersize=2.5)
        plane.set_title(f"theta_i = {theta_i:g} deg", fontsize=10)
        plane.set_yscale("log")
        plane.grid(True, alpha=0.3)
        residual.axhline(0.0, color="0.5", linewidth=0.8)
        residual.set_xlim(-90, 90)
        residual.set_xticks([-80, -40, 0, 40, 80])
        residual.grid(True, alpha=0.3)
        residual.set_xlabel("theta_o (deg; < 0: light's side)", fontsize=9)
    axes[0][0].set_ylabel("BRDF (1/sr)")
    axes[1][0].set_ylabel("(data - fit) / fit (%)")
    axes[0][0].legend(fontsize=8, title="dots: data, lines: fit", title_fontsize=8)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png_path, format="png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
