#!/usr/bin/env python3
"""Log-log plot of relative MSE against render time, one curve per variant (docs/tools.md).

Usage: plot_convergence.py CONVERGENCE.csv OUT.png [TITLE]

Reads the CSV written by ochre-converge (variant,spp,seconds,relmse,rmse,relmse_x_seconds) and draws,
for each variant, relMSE against seconds with the spp of each point, plus a dashed 1/t line through the
first variant's first point: an unbiased Monte Carlo estimator's MSE falls as 1/t, so a curve parallel
to it converges at the expected rate and a lower curve is more efficient.
"""
import csv
import sys


def read_rows(path):
    variants = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            curve = variants.setdefault(row["variant"], [])
            curve.append((float(row["seconds"]), float(row["relmse"]), int(row["spp"])))
    for curve in variants.values():
        curve.sort()
    return variants


def main():
    if len(sys.argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 2
    csv_path, png_path = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) == 4 else "ochre-converge"
    try:
        import matplotlib

        matplotlib.use("Agg")  # no display needed
        import matplotlib.pyplot as plt
    except ImportError as error:
        sys.stderr.write(f"plot_convergence.py: matplotlib is not available ({error})\n")
        return 1

    variants = read_rows(csv_path)
    if not variants:
        sys.stderr.write(f"plot_convergence.py: {csv_path} has no rows\n")
        return 1
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=100)
    for name, curve in variants.items():
        seconds = [c[0] for c in curve]
        relmse = [c[1] for c in curve]
        ax.plot(seconds, relmse, marker="o", label=name)
        for t, e, spp in curve:
            ax.annotate(str(spp), (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)

    # The 1/t reference slope through the first point of the first variant, over the whole time range.
    t0, e0, _ = next(iter(variants.values()))[0]
    all_t = [c[0] for curve in variants.values() for c in curve]
    t_lo, t_hi = min(all_t), max(all_t)
    ax.plot([t_lo, t_hi], [e0 * t0 / t_lo, e0 * t0 / t_hi], "k--", linewidth=0.8, label="1/t")

    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render time (s)")
    ax.set_ylabel("relative MSE")
    ax.set_title(title)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, format="png")  # the path is a temporary name without .png
    return 0


if __name__ == "__main__":
    sys.exit(main())
