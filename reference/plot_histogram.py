#!/usr/bin/env python3
"""Histogram of the surface distances of both directions, from a meshdiff compare JSON
(matplotlib; run with a python3 that has numpy and matplotlib, e.g. /usr/bin/python3).

  plot_histogram.py OUT.png COMPARE.json [--title TITLE] [--relative] [--logy]

COMPARE.json is a meshdiff.compare/2 report written with --histogram N, e.g.
  meshdiff original.ply processed.ply --histogram 50 --json compare.json
or one line of `meshdiff batch` (its "result" is used). Each direction's counts are drawn as
a step line over its own bin edges ([0, max of that direction], N equal bins; every vertex, edge
and face sample counted once), forward (samples on the original, distances to the processed
surface) and backward; the sample counts are normalised to shares so the directions compare.
--relative divides the distances by surface_distance.diagonal (the original's bounding-box
diagonal); --logy draws the shares on a log axis. The area-weighted means and the sampled
maxima are marked with vertical lines. The legend is placed outside the axes.
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(path):
    with open(path) as f:
        text = f.read()
    try:
        d = json.loads(text)
    except ValueError:  # a batch JSONL file: its last ok line
        lines = [json.loads(line) for line in text.splitlines() if line.strip()]
        ok = [r for r in lines if r.get("status") == "ok"]
        if not ok:
            raise SystemExit(f"plot_histogram: {path}: no ok line")
        d = ok[-1]
    if "result" in d:
        d = d["result"]
    if not str(d.get("schema", "")).startswith("meshdiff.compare/"):
        raise SystemExit(f"plot_histogram: {path}: not a meshdiff.compare report (schema {d.get('schema')!r})")
    sd = d.get("surface_distance")
    if not sd:
        raise SystemExit(f"plot_histogram: {path}: no surface_distance (compared with --no-distance?)")
    for side in ("forward", "backward"):
        if "histogram" not in sd[side]:
            raise SystemExit(f"plot_histogram: {path}: no {side} histogram; run meshdiff with --histogram N")
    return sd


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("report")
    ap.add_argument("--title", default=None)
    ap.add_argument("--relative", action="store_true")
    ap.add_argument("--logy", action="store_true")
    a = ap.parse_args(argv)
    sd = load(a.report)
    scale = 1.0 / sd["diagonal"] if a.relative else 1.0
    fig, ax = plt.subplots(figsize=(8, 4.5))
    names = {"forward": "forward (original -> processed)", "backward": "backward (processed -> original)"}
    for side, color in (("forward", "C0"), ("backward", "C3")):
        s = sd[side]
        edges = np.asarray(s["histogram"]["edges"], dtype=float) * scale
        counts = np.asarray(s["histogram"]["counts"], dtype=float)
        share = counts / max(counts.sum(), 1.0)
        ax.stairs(share, edges, color=color, linewidth=1.5, label=f"{names[side]}, {int(counts.sum())} samples")
        aw = s.get("area_weighted")
        if aw:
            ax.axvline(aw["mean"] * scale, color=color, linestyle="--", linewidth=1,
                       label=f"{side} area-weighted mean {aw['mean'] * scale:.4g}")
        ax.axvline(s["max"] * scale, color=color, linestyle=":", linewidth=1, label=f"{side} max {s['max'] * scale:.4g}")
    if a.logy:
        ax.set_yscale("log")
    ax.set_xlabel("distance / bounding-box diagonal of the original" if a.relative else "distance (mesh units)")
    ax.set_ylabel("share of the samples")
    ax.set_xlim(left=0)
    ax.set_title(a.title or "meshdiff surface distance histogram")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120, bbox_inches="tight")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
