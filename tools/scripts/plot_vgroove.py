#!/usr/bin/env python3
"""Figures of ochre-vgroove (docs/tools.md), after Saint-Pierre et al. 2019, JOSA A 36(11) C51.

Usage:
  plot_vgroove.py grid PANELS.csv OUT.png [COUNTS_OUT.png]
  plot_vgroove.py profile PROFILE.csv OUT.png [TITLE]

grid: PANELS.csv (material,alpha_deg,model,colour_png,counts_png) lists maps written by ochre-vgroove
maps (Lambert azimuthal equal-area disks, phi = 0 to the right, phi = 90 deg up). They are laid out
with one column per dihedral angle and one row per (material, model) as in the paper's Fig 6, or, with
a single angle, one column per model and one row per material (Fig 8). The reflection-count maps go to
COUNTS_OUT.png with a legend (1 light grey, 2 blue, 3 orange, 4 red, more purple).

profile: PROFILE.csv (phi_deg,theta_deg,model,L) from ochre-vgroove profile. Draws L* along the
horizontal (phi = 0, across the grooves) and vertical (phi = 90 deg, along the grooves) diameters of the
maps, as in the paper's Fig 9: the abscissa runs from -90 to 90 degrees (R is symmetric under
phi -> phi + 180 deg for a symmetric groove, so each half is the same curve).

PNGs are written whatever the output's extension (ochre-vgroove passes temporary names).
"""
import csv
import sys

COUNT_LEGEND = [
    ("1", (211, 211, 211)),
    ("2", (68, 119, 170)),
    ("3", (238, 153, 51)),
    ("4", (204, 51, 17)),
    ("> 4", (119, 51, 136)),
]
MODEL_LABELS = {
    "rigorous": "rigorous",
    "unpolarized": "unpolarized (1st approx.)",
    "sp": "s/p separately (2nd approx.)",
    "paper_literal": "paper-literal Eq 33",
}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def layout(panels):
    """[(row, column, panel)], row labels, column labels."""
    alphas = list(dict.fromkeys(p["alpha_deg"] for p in panels))
    if len(alphas) > 1:
        rows = list(dict.fromkeys((p["material"], p["model"]) for p in panels))
        single_model = len({p["model"] for p in panels}) == 1
        row_labels = [m if single_model else "%s\n%s" % (m, MODEL_LABELS.get(mod, mod)) for m, mod in rows]
        cells = [(rows.index((p["material"], p["model"])), alphas.index(p["alpha_deg"]), p) for p in panels]
        return cells, row_labels, ["%s\u00b0" % a for a in alphas]
    materials = list(dict.fromkeys(p["material"] for p in panels))
    models = list(dict.fromkeys(p["model"] for p in panels))
    cells = [(materials.index(p["material"]), models.index(p["model"]), p) for p in panels]
    return cells, ["%s, %s\u00b0" % (m, alphas[0]) for m in materials], [MODEL_LABELS.get(m, m) for m in models]


def draw_grid(panels, image_key, out_path, legend):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Patch

    cells, row_labels, column_labels = layout(panels)
    n_rows, n_cols = len(row_labels), len(column_labels)
    size = 1.6 if n_cols > 3 else 2.4
    fig, axes = plt.subplots(n_rows, n_cols, figsize=(size * n_cols + 0.9, size * n_rows + 0.6), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for r, c, p in cells:
        image = plt.imread(p[image_key])
        axes[r][c].imshow(image, interpolation="nearest")
        # The disk's edge, so that near-white maps (silver) stand out from the white background.
        n = image.shape[0]
        axes[r][c].add_patch(Circle(((n - 1) / 2, (n - 1) / 2), n / 2, fill=False, edgecolor="0.5", linewidth=0.6))
    for c, label in enumerate(column_labels):
        axes[0][c].set_title(label, fontsize=9)
    for r, label in enumerate(row_labels):
        axes[r][0].text(-0.06, 0.5, label, transform=axes[r][0].transAxes, ha="right", va="center", fontsize=9)
    if legend:
        handles = [Patch(facecolor=[v / 255 for v in rgb], edgecolor="black", label=name) for name, rgb in COUNT_LEGEND]
        fig.legend(handles=handles, title="max. reflections", loc="lower center", ncol=len(handles), fontsize=8,
                   title_fontsize=8, frameon=False)
    fig.tight_layout(rect=(0.0, 0.08 if legend else 0.0, 1.0, 1.0))
    fig.savefig(out_path, format="png", dpi=80)
    plt.close(fig)


def draw_profile(path, out_path, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curves = {}
    for row in read_rows(path):
        curves.setdefault((float(row["phi_deg"]), row["model"]), []).append((float(row["theta_deg"]), float(row["L"])))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, phi, name in ((axes[0], 0.0, "a) across the grooves (phi = 0, 180\u00b0)"),
                          (axes[1], 90.0, "b) along the grooves (phi = 90, 270\u00b0)")):
        for (p, model), points in curves.items():
            if p != phi:
                continue
            points.sort()
            thetas = [-t for t, _ in reversed(points) if t > 0] + [t for t, _ in points]
            values = [v for t, v in reversed(points) if t > 0] + [v for _, v in points]
            ax.plot(thetas, values, label=MODEL_LABELS.get(model, model))
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("theta (degrees)")
        ax.set_xlim(-90, 90)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("L*")
    axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out_path, format="png", dpi=80)
    plt.close(fig)


def main():
    args = sys.argv[1:]
    if len(args) >= 3 and args[0] == "grid" and len(args) <= 4:
        panels = read_rows(args[1])
        draw_grid(panels, "colour_png", args[2], legend=False)
        if len(args) == 4:
            draw_grid(panels, "counts_png", args[3], legend=True)
        return 0
    if len(args) in (3, 4) and args[0] == "profile":
        draw_profile(args[1], args[2], args[3] if len(args) == 4 else "")
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
