#!/usr/bin/env python3
"""Print the numbers behind reference/README.md from the JSON files that studies.sh wrote.

  summarize.py reference/out > reference/out/summary.md

Standard library only. Every number here is read from a meshdiff report (or from
plytool.py valence-stats output), nothing is computed from meshes.
"""
import json
import os
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "out")


def load(*parts):
    p = os.path.join(OUT, *parts)
    if not os.path.exists(p):
        return None
    with open(p) as f:
        return json.load(f)


def sig(d, L):
    if d is None:
        return None
    if L == "G":
        return d["sigma_global"]
    return dict(zip(d["levels"], d["sigma"])).get(L)


def exact(d, L):
    ex = d.get("exact") if d else None
    if not isinstance(ex, dict):
        return None
    if L == "G":
        return ex.get("sigma_global")
    return dict(zip(ex.get("levels", d["levels"]), ex["sigma"])).get(L)


def f(x, nd=4):
    if x is None:
        return "n/a"
    return f"{x:.{nd}g}"


def table(header, rows):
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(str(c) for c in r) + " |")
    print()


LV = [1, 2, 5, 10, 20, "G"]


def profile_rows(items, with_exact=False):
    rows = []
    for name, d in items:
        if d is None:
            continue
        r = [name] + [f(sig(d, L)) for L in LV] + [f(sig(d, "G") / sig(d, 1) if sig(d, 1) else None, 3)]
        if with_exact:
            r.append(" / ".join(f(exact(d, L), 3) for L in (1, "G")) if exact(d, 1) is not None else "n/a")
        rows.append(r)
    return rows


def head(with_exact=False):
    h = ["mesh", "s1", "s2", "s5", "s10", "s20", "sG", "sG/s1"]
    return h + (["exact s1 / sG"] if with_exact else [])


print("# Numbers of the reference studies\n")
print("Written by `reference/summarize.py` from `reference/out/`. sigma values are on meshes scaled to mean vertex")
print("distance 1 from the centroid (METHOD.md section 2); sN = sigma at level N, sG = global level.\n")

print("## 1. Noise and stretching (Fig. 5)\n")
items = [(f"noise {n}", load("1_sphere_noise_stretch", f"noise_{n}.json")) for n in ("0", "0.005", "0.01", "0.02", "0.04")]
table(head(True), profile_rows(items, True))
base = items[0][1]
rows = []
for name, d in items[1:]:
    if d and base:
        rows.append([name] + [f(sig(d, L) - sig(base, L)) for L in LV])
print("Increase over the clean icosphere, sigma_L(noisy) - sigma_L(clean):\n")
table(["mesh", "d1", "d2", "d5", "d10", "d20", "dG"], rows)
items = [(f"axes {a},1,1", load("1_sphere_noise_stretch", f"stretch_{a}.json")) for a in ("1", "1.25", "1.5", "2", "3")]
table(head(True), profile_rows(items, True))
base = items[0][1]
rows = []
for name, d in items[1:]:
    if d and base:
        rows.append([name] + [f(sig(d, L) - sig(base, L)) for L in LV])
print("Increase over the sphere (a = 1), sigma_L(ellipsoid) - sigma_L(sphere):\n")
table(["mesh", "d1", "d2", "d5", "d10", "d20", "dG"], rows)

print("## 2. Real models (Figs. 1, 4)\n")
items = [(m, load("2_models", m + ".json")) for m in ("bunny_closed", "igea", "rocker_arm", "fandisk")]
table(head() + ["top-0.1% share of s1^2"], [r + [f(d["level_details"][0]["top_share"], 2)]
                                             for r, (_, d) in zip(profile_rows(items), items) if d])

print("## 3. Smoothing (Figs. 6-9, 11-12)\n")
print("Ratio final/initial of sigma at levels 1, 5, 20 and global after the last iteration, and how far the")
print("result moved from its input (forward RMS surface distance and Hausdorff, relative to the input's")
print("bounding-box diagonal; bunny_noisy and igea_noisy: igea has no distance run).\n")
methods = ("laplacian", "taubin", "bilaplacian", "mcf", "modified-mcf")
for mesh in ("noisy_sphere", "ellipsoid", "bunny_noisy", "igea_noisy"):
    rows = []
    for u in ("post", "pre"):
        for m in methods:
            d = load("3_smoothing", f"{mesh}_{u}_{m}.json")
            if d is None:
                continue
            lv = d["levels"]
            s0, s1 = d["sigma"][0], d["sigma"][-1]
            r = [f"{m} {u}", d["iterations"][-1], f(s0[0], 3)]
            for L in (1, 5, 20):
                k = lv.index(L) if L in lv else None
                r.append(f(s1[k] / s0[k], 3) if k is not None and s0[k] else "n/a")
            g0, g1 = d["sigma_global"][0], d["sigma_global"][-1]
            r.append(f(g0, 3))
            r.append(f(g1 / g0 if g0 else None, 3))
            c = load("3_smoothing", f"{mesh}_{u}_{m}_distance.json")
            if c:
                sd = c["surface_distance"]
                r += [f(sd["forward"]["relative"]["rms"], 3), f(sd["hausdorff_relative"], 3)]
            else:
                r += ["n/a", "n/a"]
            rows.append(r)
    if rows:
        print(f"### {mesh}\n")
        table(["method", "iterations", "s1 start", "s1 end/start", "s5 end/start", "s20 end/start", "sG start",
               "sG end/start", "RMS dist / diag", "Hausdorff / diag"], rows)

print("## 4. Regular against irregular sampling (Figs. 13-14)\n")
items = []
for s in ("torus", "heightfield"):
    for r in ("regular", "irregular"):
        items.append((f"{s} {r}", load("4_sampling", f"{s}_{r}.json")))
items += [(m, load("4_sampling", m + ".json")) for m in ("sphere_ico_2562", "sphere_irregular_3072")]
table(head(True), profile_rows(items, True))

print("## 5. Goldfeather against Meyer (Fig. 3)\n")
items = []
for mesh, label in (("smoothed_sphere", "noisy sphere + 10 Laplacian"), ("sphere_noise_0", "clean icosphere"),
                    ("sphere_irregular_3072", "sphere_irregular_3072")):
    for c in ("goldfeather", "quadric", "meyer"):
        items.append((f"{label}, {c}", load("5_curvature", f"{mesh}_{c}.json")))
table(head(), profile_rows(items))

print("## 6. Bumps on a smoothed ellipsoid (Fig. 10)\n")
print("Per valence class: RMS of D_3 (H minus its 3-ring mean) and mean H, on the scaled mesh.\n")
rows = []
for m in ("none",) + methods:
    v = load("6_bumps", f"ellipsoid_{m}_by_valence.json")
    if v is None:
        continue
    b = v["by_valence"]
    d3, H = b["D_3"], b["H"]
    r5, r6 = d3.get("5", {}).get("rms"), d3.get("6", {}).get("rms")
    rows.append([m, f(r5, 3), f(r6, 3), f(r5 / r6 if r5 and r6 else None, 3),
                 f(H.get("5", {}).get("mean_abs"), 4), f(H.get("6", {}).get("mean_abs"), 4)])
table(["smoothing", "RMS D_3 valence 5", "RMS D_3 valence 6", "ratio", "mean H valence 5", "mean H valence 6"], rows)

t = os.path.join(OUT, "timing.txt")
if os.path.exists(t):
    print("## Run time\n")
    print("```")
    print(open(t).read().rstrip())
    print("```")
