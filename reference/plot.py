#!/usr/bin/env python3
"""Plots of the reference studies (matplotlib). Called by plot_profiles.sh, plot_smoothing.sh,
plot_bumps.sh and studies.sh; run with a python3 that has numpy and matplotlib (PYNUM, default
/usr/bin/python3).

  plot.py profiles OUT.png TITLE NAME=PROFILE.json[#member] ... [--logy]
      sigma against level. Markers at the measured levels, lines only between consecutive
      measured levels; the global level G is a separate marker at the right, never joined by a
      line. An exact-H profile in a report (profile --exact) is drawn dashed in the same colour.
      A NAME "clean" is drawn as a dashed black reference line.
  plot.py smoothing OUT.png TITLE NAME=SMOOTHING.json ... [--ref PROFILE.json[#member]] [--clip F] [--linear]
      One panel per recorded level (global last), sigma against iterations. Runs "X post" and
      "X pre" of one method share a colour (post solid, pre dashed). --ref: dashed black line
      at the clean mesh's sigma in every panel. The y range ignores values above F times the
      largest starting sigma of the panel (default 10); runs cut off by it are named in the
      panel ("off scale").
  plot.py bumps OUT.png TITLE DIR NAME ... [--cb 0.3]
      Ellipsoid front halves coloured by D_3 (DIR/ellipsoid_NAME_vertices.dat), valence-5 circled.
  plot.py hmap OUT.png TITLE VERTEXDATA.ply [--prop H] [--view x,y,z] [--up x,y,z] [--pct 2]
      Mesh rendered in orthographic projection (painter's algorithm), faces coloured by the
      mean of a vertex property, symmetric colour range at the PCT/100-PCT percentiles.
  plot.py fig3 OUT.png DIR
      Paper Fig. 3 from DIR/fig3.json (written by summarize-side code in studies.sh).
  plot.py corsini OUT.png NAME=DIR/NAME ...
      Paper Fig. 1e,f: per mesh, Corsini's roughness R_L and the paper's sigma_L, each divided by
      its global value (left and right panel), from NAME_corsini.json and NAME_sigma.json
      (reference/corsini.sh); the unbiased-variance variant dashed.

Legends are placed outside the axes (never over data).
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation, ScalarFormatter  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

COLORS = plt.rcParams["axes.prop_cycle"].by_key()["color"] + ["#444444", "#b8860b", "#2f4f4f"]


def load(path):
    key = None
    if "#" in path:
        path, key = path.rsplit("#", 1)
    with open(path) as f:
        d = json.load(f)
    return d[key] if key else d


def split_arg(arg):
    if "=" in arg:
        return arg.split("=", 1)
    return os.path.basename(arg).rsplit(".", 1)[0], arg


def short(y, _pos=None):
    """Tick label: at most 3 significant digits, exponent form for small and large values."""
    if y == 0:
        return "0"
    t = f"{y:.3g}"
    if "e" in t:
        m, e = t.split("e")
        m = "" if m == "1" else m + "·"
        return f"{m}1e{int(e)}" if m == "" else f"{m}1e{int(e)}".replace("·1e", "e")
    return t


def log_ticks(ax):
    """Call after the y range is set: short labels; minor ticks labelled only within one decade."""
    from matplotlib.ticker import FuncFormatter, NullFormatter
    lo, hi = ax.get_ylim()
    ax.yaxis.set_major_formatter(FuncFormatter(short))
    if lo > 0 and hi / lo < 30:
        ax.yaxis.set_minor_formatter(FuncFormatter(short))
    else:
        ax.yaxis.set_minor_formatter(NullFormatter())


def tidy_axis(ax, logy):
    if logy:
        ax.set_yscale("log")
        ax.yaxis.set_major_formatter(LogFormatterSciNotation())
    else:
        f = ScalarFormatter(useMathText=True)
        f.set_powerlimits((-3, 4))
        ax.yaxis.set_major_formatter(f)
    ax.grid(True, alpha=0.3)


def profiles(a):
    fig, ax = plt.subplots(figsize=(10, 5.6))
    lmax = 1
    series = []
    for arg in a.items:
        name, path = split_arg(arg)
        d = load(path)
        lv = [L for L, s in zip(d["levels"], d["sigma"]) if s is not None]
        sg = [s for s in d["sigma"] if s is not None]
        ex = d.get("exact") if isinstance(d.get("exact"), dict) else None
        series.append((name, lv, sg, d.get("sigma_global"), ex))
        lmax = max([lmax] + lv)
    gx = lmax + max(1, lmax // 10) + 1
    k = 0
    for name, lv, sg, g, ex in series:
        if name == "clean":
            col, ls, mk = "black", "--", "s"
        else:
            col, ls, mk = COLORS[k % len(COLORS)], "-", "o"
            k += 1
        ax.plot(lv, sg, ls, color=col, marker=mk, ms=4, lw=1.8, label=name)
        if g is not None:
            ax.plot([gx], [g], mk, color=col, ms=6)
        if ex:
            el = ex.get("levels", lv)
            es = ex["sigma"]
            pts = [(L, s) for L, s in zip(el, es) if s is not None and (s > 1e-12 or not a.logy)]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], ":", color=col, lw=1.5,
                        label=f"{name} (exact H)")
            else:
                ax.plot([], [], ":", color=col, lw=1.5, label=f"{name} (exact H: 0, off the log axis)")
            eg = ex.get("sigma_global")
            if eg is not None and (eg > 1e-12 or not a.logy):
                ax.plot([gx], [eg], "x", color=col, ms=7)
    has_exact = any(ex for *_, ex in series)
    ax.set_xlabel("level L (rings); G = global" + (" (x: exact H)" if has_exact else ""))
    ax.set_ylabel("sigma_L (scaled mesh, 1/length)")
    step = 1 if lmax <= 12 else 2
    ticks = list(range(0, lmax + 1, step))
    ax.set_xticks(ticks + [gx])
    ax.set_xticklabels([str(t) for t in ticks] + ["G"])
    ax.set_xlim(0.5, gx + 0.5)
    tidy_axis(ax, a.logy)
    if not a.logy:
        ax.set_ylim(bottom=0)
    else:
        log_ticks(ax)
    ax.set_title(a.title, fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print(a.out)


def method_of(name):
    for suf in (" post", " pre"):
        if name.endswith(suf):
            return name[: -len(suf)], suf.strip()
    return name, None


def smoothing(a):
    runs = []
    for arg in a.items:
        name, path = split_arg(arg)
        d = load(path)
        runs.append((name, d))
    keys = list(runs[0][1]["levels"]) + (["global"] if runs[0][1].get("sigma_global") else [])
    ref = None
    if a.ref:
        r = load(a.ref)
        ref = dict(zip(r["levels"], r["sigma"]))
        ref["global"] = r.get("sigma_global")
    ncol = 3
    nrow = math.ceil(len(keys) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol, 3.5 * nrow + 0.6), squeeze=False)
    colour = {}
    for name, _ in runs:
        m, _u = method_of(name)
        if m not in colour:
            colour[m] = COLORS[len(colour) % len(COLORS)]
    handles = {}
    for p, key in enumerate(keys):
        ax = axes[p // ncol][p % ncol]
        starts, off = [], []
        allv = []
        for name, d in runs:
            if key == "global":
                ys = d["sigma_global"]
            else:
                k = d["levels"].index(key)
                ys = [row[k] for row in d["sigma"]]
            xs = d["iterations"]
            pts = [(x, y) for x, y in zip(xs, ys) if y is not None]
            if not pts:
                continue
            starts.append(pts[0][1])
            allv.append((name, pts))
        cap = a.clip * max(starts + ([ref[key]] if ref and ref.get(key) else []))
        lo = []
        for name, pts in allv:
            m, u = method_of(name)
            ls = "--" if u == "pre" else "-"
            h, = ax.plot([x for x, _ in pts], [y for _, y in pts], ls, color=colour[m], marker="o", ms=2.5,
                         lw=1.6, label=name)
            handles.setdefault(name, h)
            if max(y for _, y in pts) > cap:
                off.append(name)
            lo += [y for _, y in pts if y <= cap and y > 0]
        if ref and ref.get(key) is not None:
            h = ax.axhline(ref[key], color="black", ls="--", lw=1.2, label="clean mesh")
            handles.setdefault("clean mesh", h)
            lo.append(ref[key])
        tidy_axis(ax, not a.linear)
        if lo:
            if a.linear:
                ax.set_ylim(0, cap * 1.02)
            else:
                ax.set_ylim(min(lo) / 1.5, min(cap, max(lo)) * 1.5)
        if not a.linear:
            log_ticks(ax)
        title = "level %s" % key if key != "global" else "global level"
        ax.set_title(title, fontsize=10)
        if off:  # named under the title, outside the data area
            ax.set_title(title + "\n", fontsize=10)
            ax.text(0.5, 1.01, "clipped at %gx the start: %s off scale" % (a.clip, ", ".join(off)),
                    transform=ax.transAxes, ha="center", va="bottom", fontsize=7, color="#a00000")
        ax.set_xlabel("iteration")
        ax.set_ylabel("sigma")
    for p in range(len(keys), nrow * ncol):
        axes[p // ncol][p % ncol].axis("off")
    free = len(keys) < nrow * ncol
    if free:
        lax = axes[-1][-1]
        lax.legend(list(handles.values()), list(handles.keys()), loc="center", fontsize=9, frameon=False)
    else:
        fig.legend(list(handles.values()), list(handles.keys()), loc="lower center", ncol=min(6, len(handles)),
                   fontsize=8, frameon=False)
    fig.suptitle(a.title, fontsize=11)
    fig.tight_layout(rect=(0, 0 if free else 0.06, 1, 0.96))
    fig.savefig(a.out, dpi=100)
    print(a.out)


def bumps(a):
    n = len(a.names)
    ncol = 3
    nrow = math.ceil(n / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.8 * ncol, 3.6 * nrow + 0.5), squeeze=False)
    sc = None
    for p, m in enumerate(a.names):
        ax = axes[p // ncol][p % ncol]
        d = np.loadtxt(os.path.join(a.dir, f"ellipsoid_{m}_vertices.dat"))
        front = d[:, 2] > -0.05
        d = d[front][np.argsort(d[front][:, 2])]
        sc = ax.scatter(d[:, 0], d[:, 1], c=d[:, 5], cmap="RdBu_r", vmin=-a.cb, vmax=a.cb, s=5)
        v5 = d[d[:, 3] == 5]
        ax.scatter(v5[:, 0], v5[:, 1], s=90, facecolors="none", edgecolors="black", lw=1.2)
        ax.set_aspect("equal")
        ax.set_title("not smoothed" if m == "none" else m, fontsize=10)
        ax.set_xlabel("x (scaled)")
        ax.set_ylabel("y (scaled)")
    for p in range(n, nrow * ncol):
        axes[p // ncol][p % ncol].axis("off")
    d0 = np.loadtxt(os.path.join(a.dir, f"ellipsoid_{a.names[0]}_vertices.dat"))
    ratio = np.ptp(d0[:, 0]) / np.ptp(d0[:, 1])
    fig.suptitle(a.title.replace("Ellipsoid", f"Ellipsoid ({ratio:.2g}, 1, 1)", 1), fontsize=11)
    fig.tight_layout(rect=(0, 0, 0.92, 0.95))
    cax = fig.add_axes((0.93, 0.15, 0.015, 0.7))
    cb = fig.colorbar(sc, cax=cax, extend="both")
    cb.set_label("D_3 = H - mean H over the 3-ring (colour clipped at +-%g)" % a.cb)
    fig.savefig(a.out, dpi=100)
    print(a.out)


def hmap(a):
    import plytool
    names, verts, faces, _ = plytool.read_ply(a.input)
    v = np.asarray(verts, dtype=float)
    tri = np.asarray([f for f in faces if len(f) == 3], dtype=np.int64)
    P = v[:, :3]
    val = v[:, names.index(a.prop)]
    view = np.array([float(x) for x in a.view.split(",")])
    view /= np.linalg.norm(view)
    up = np.array([float(x) for x in a.up.split(",")])
    right = np.cross(up, view)
    right /= np.linalg.norm(right)
    up = np.cross(view, right)
    x, y, z = P @ right, P @ up, P @ view
    t = tri
    n = np.cross(P[t[:, 1]] - P[t[:, 0]], P[t[:, 2]] - P[t[:, 0]])
    front = n @ view > 0
    t = t[front]
    order = np.argsort(z[t].mean(axis=1))
    t = t[order]
    fv = np.nanmean(val[t], axis=1)
    good = np.isfinite(val)
    lim = np.percentile(np.abs(val[good]), 100 - a.pct)
    from matplotlib.collections import PolyCollection
    asp = (y.max() - y.min()) / (x.max() - x.min())
    fig, ax = plt.subplots(figsize=(8.5, min(9.0, max(3.2, 6.8 * asp + 0.9))))
    polys = np.stack([np.stack([x[t[:, k]], y[t[:, k]]], axis=1) for k in range(3)], axis=1)
    pc = PolyCollection(polys, array=fv, cmap="RdBu_r", edgecolors="none", antialiaseds=False)
    pc.set_clim(-lim, lim)
    ax.add_collection(pc)
    ax.set_xlim(x.min(), x.max())
    ax.set_ylim(y.min(), y.max())
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    cb = fig.colorbar(pc, ax=ax, shrink=0.8, extend="both")
    cb.set_label(f"{a.prop} (scaled mesh, 1/length)")
    ax.set_title(a.title + f"\ncolour clipped at +-{lim:.3g}, the {100 - a.pct:g}th percentile of |{a.prop}|", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(a.out)


def fig3(a):
    d = load(os.path.join(a.dir, "fig3.json"))
    methods = list(d.keys())
    fig, axes = plt.subplots(2, len(methods), figsize=(6.2 * len(methods), 8.4), squeeze=False)
    style = {"goldfeather": ("#1f77b4", "o"), "meyer": ("#d62728", "s")}
    for c, m in enumerate(methods):
        r = d[m]
        it = r["iterations"]
        for row, key in enumerate(("sigma_1", "sigma_global")):
            ax = axes[row][c]
            for est in ("goldfeather", "meyer"):
                col, mk = style[est]
                ax.plot(it, r[est][key], "-", color=col, marker=mk, ms=3, label=f"{est}, smoothed mesh")
                ax.plot(it, r[est][key + "_projected"], "--", color=col, marker=mk, ms=3, mfc="none",
                        label=f"{est}, same vertices projected onto the sphere (estimator error only)")
            if key == "sigma_global":
                ir = [x if x > 1e-12 else float("nan") for x in r["inverse_radius_sigma_global"]]
                ax.plot(it, ir, ":", color="black", lw=2,
                        label="sigma_G of r_mean/r_i (sphere through each vertex: geometry, zeroth order)")
            ax.set_yscale("log")
            ax.set_ylim(1e-8, 1)
            log_ticks(ax)
            ax.grid(True, alpha=0.3)
            ax.set_xlabel("iteration")
            ax.set_ylabel("sigma_1" if key == "sigma_1" else "sigma_G")
            ax.set_title(f"clean sphere, {m} pre-updating: {'level 1' if key == 'sigma_1' else 'global level'}",
                         fontsize=10)
            ax2 = ax.twinx()
            sp = r["radius_spread"]
            ax2.fill_between(it, [100 * s["min"] for s in sp], [100 * s["max"] for s in sp], color="grey",
                             alpha=0.15, label="radius spread r_i/r_mean - 1 (min..max, right axis)")
            ax2.set_ylabel("radius spread, %")
    # one legend below all panels
    h1, l1 = axes[1][0].get_legend_handles_labels()
    h2, l2 = axes[1][0].figure.axes[-1].get_legend_handles_labels()
    fig.legend(h1 + h2, l1 + l2, loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle("Paper Fig. 3: a clean geodesic sphere (4,002 vertices) smoothed with pre-updating; "
                 "Meyer against the cubic fit", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 0.96))
    fig.savefig(a.out, dpi=100)
    print(a.out)


def corsini(a):
    fig, axes = plt.subplots(1, 2, figsize=(12.5, 5.2))
    for k, item in enumerate(a.items):
        name, stem = split_arg(item)
        col = COLORS[k % len(COLORS)]
        c = load(stem + "_corsini.json")["corsini"]
        u = load(stem + "_corsini_unbiased.json")["corsini"]
        sg = load(stem + "_sigma.json")
        for d, ls, lab in ((c, "-", name), (u, "--", name + " (variance with n - 1)")):
            axes[0].plot(d["levels"], [r / d["roughness_global"] for r in d["roughness"]], ls, color=col, marker="o",
                         ms=3, label=lab)
        axes[1].plot(sg["levels"], [s / sg["sigma_global"] for s in sg["sigma"]], "-", color=col, marker="o", ms=3,
                     label=name)
    for ax, what, title in ((axes[0], "R_L / R_G", "Corsini et al.: dihedral-angle variance R_L"),
                            (axes[1], "sigma_L / sigma_G", "the paper: curvature deviation sigma_L")):
        ax.axhline(1.0, color="black", lw=1, ls=":")
        ax.set_xlabel("level L (rings)")
        ax.set_ylabel(what)
        ax.set_xticks(range(0, 21, 2))
        ax.set_xlim(0.5, 20.5)
        ax.grid(True, alpha=0.3)
        ax.set_title(title, fontsize=10)
    h, lab = axes[0].get_legend_handles_labels()
    fig.legend(h, lab, loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.suptitle("Paper Fig. 1e,f: roughness at level L over the global roughness (above 1: rougher locally than "
                 "globally)", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 0.95))
    fig.savefig(a.out, dpi=100)
    print(a.out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    s = p.add_subparsers(dest="cmd", required=True)
    q = s.add_parser("profiles")
    q.add_argument("out"); q.add_argument("title"); q.add_argument("items", nargs="+")
    q.add_argument("--logy", action="store_true")
    q.set_defaults(func=profiles)
    q = s.add_parser("smoothing")
    q.add_argument("out"); q.add_argument("title"); q.add_argument("items", nargs="+")
    q.add_argument("--ref"); q.add_argument("--clip", type=float, default=10.0)
    q.add_argument("--linear", action="store_true")
    q.set_defaults(func=smoothing)
    q = s.add_parser("bumps")
    q.add_argument("out"); q.add_argument("title"); q.add_argument("dir"); q.add_argument("names", nargs="+")
    q.add_argument("--cb", type=float, default=0.3)
    q.set_defaults(func=bumps)
    q = s.add_parser("hmap")
    q.add_argument("out"); q.add_argument("title"); q.add_argument("input")
    q.add_argument("--prop", default="H"); q.add_argument("--view", default="0,0,1")
    q.add_argument("--up", default="0,1,0"); q.add_argument("--pct", type=float, default=2.0)
    q.set_defaults(func=hmap)
    q = s.add_parser("fig3")
    q.add_argument("out"); q.add_argument("dir")
    q.set_defaults(func=fig3)
    q = s.add_parser("corsini")
    q.add_argument("out"); q.add_argument("items", nargs="+")
    q.set_defaults(func=corsini)
    a = p.parse_args()
    a.func(a)


if __name__ == "__main__":
    main()
