#!/usr/bin/env python3
"""Incidence-plane and polar plots of a material's BRDF (ochre-brdf plot, docs/tools.md).

Usage: plot_brdf.py VALUES.csv OUT.png [TITLE]

Reads the CSV written by ochre-brdf plot (incidence_deg,theta_o_deg,phi_o_deg,f): for each incidence
angle, the BRDF f (1/sr, no cosine) on a grid of outgoing directions, with the light at azimuth 0 (so
phi_o = 0 is the light's side). Draws
- top: f in the plane of incidence, one curve per incidence; the abscissa is the signed outgoing angle,
  negative on the light's side (backscatter), positive on the far side (where a mirror reflects);
- bottom: one polar map of f per incidence (radius = theta_o in degrees, angle = phi_o; the light is
  at phi_o = 0).
The PNG is written to OUT.png whatever its extension (ochre-brdf passes a temporary name).
"""
import csv
import sys


def read_values(path):
    """{incidence: {(theta, phi): f}} in file order."""
    data = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            grid = data.setdefault(float(row["incidence_deg"]), {})
            grid[(float(row["theta_o_deg"]), float(row["phi_o_deg"]))] = float(row["f"])
    return data


def incidence_plane(grid):
    """(signed angles, f): phi_o = 0 as negative angles, phi_o = 180 as positive ones."""
    back = sorted((-t, f) for (t, p), f in grid.items() if p == 0.0 and t > 0.0)
    front = sorted((t, f) for (t, p), f in grid.items() if p == 180.0)
    points = back + front
    return [a for a, _ in points], [f for _, f in points]


def polar_map(grid, np):
    thetas = sorted({t for t, _ in grid})
    phis = sorted({p for _, p in grid})
    values = np.array([[grid[(t, p)] for p in phis] for t in thetas])
    return np.radians(phis), np.array(thetas), values


def main():
    if len(sys.argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 2
    csv_path, png_path = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) == 4 else ""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    data = read_values(csv_path)
    n = len(data)
    fig = plt.figure(figsize=(max(8.0, 3.6 * n), 8.0))
    grid_spec = fig.add_gridspec(2, n, height_ratios=[1.0, 1.1])
    plane = fig.add_subplot(grid_spec[0, :])
    vmax = max(max(g.values()) for g in data.values())
    for incidence, grid in data.items():
        angles, values = incidence_plane(grid)
        plane.plot(angles, values, label=f"incidence {incidence:g} deg")
        plane.axvline(-incidence, color="0.85", linewidth=0.8)
    plane.set_xlabel("outgoing angle in the plane of incidence (deg; < 0: light's side)")
    plane.set_ylabel("f (1/sr)")
    plane.set_xlim(-90, 90)
    plane.set_ylim(bottom=0.0)
    plane.grid(True, alpha=0.3)
    plane.legend()
    for i, (incidence, grid) in enumerate(data.items()):
        ax = fig.add_subplot(grid_spec[1, i], projection="polar")
        phi, theta, values = polar_map(grid, np)
        ax.grid(False)  # pcolormesh would remove it anyway (deprecated behaviour)
        mesh = ax.pcolormesh(phi, theta, values, shading="auto", vmin=0.0, vmax=vmax, cmap="magma")
        ax.set_title(f"incidence {incidence:g} deg (light at phi = 0)", fontsize=9)
        ax.set_ylim(0, 90)
        ax.set_yticks([30, 60, 90])
        ax.tick_params(labelsize=7)
        fig.colorbar(mesh, ax=ax, shrink=0.7, label="f (1/sr)")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png_path, format="png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
