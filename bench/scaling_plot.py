#!/usr/bin/env python3
"""Log-log plot of bench/scaling.sh's CSV: wall time and peak memory of the default profile and compare against
vertex count, with the fitted exponent of each (1 = linear growth).

  bench/scaling_plot.py scaling.csv scaling.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def slope(xs, ys):
    """Least-squares exponent of y ~ x^k on log scales."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    n = [int(r["vertices"]) for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (unit, cols) in zip(axes, (("s", ("profile_s", "compare_s")), ("MB", ("profile_mb", "compare_mb")))):
        for col, style in zip(cols, ("o-", "s--")):
            y = [float(r[col]) for r in rows]
            k = slope(n, y)
            ax.loglog(n, y, style, label=f"{col.split('_')[0]} (exponent {k:.2f})")
            print(f"{col}: exponent {k:.3f}")
        ax.set_xlabel("vertices (irregular torus)")
        ax.set_ylabel("wall time [s]" if unit == "s" else "peak memory [MB]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="upper left")
    fig.suptitle("meshdiff default profile and compare, 2 threads")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
