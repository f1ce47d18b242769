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
            if exact(d, 1) is not None:
                r.append(" / ".join(f(exact(d, L), 3) for L in (1, "G")))
                r.append(f(d["exact"].get("h_error", {}).get("rms"), 3))
            else:
                r += ["n/a", "n/a"]
        rows.append(r)
    return rows


def head(with_exact=False):
    h = ["mesh", "s1", "s2", "s5", "s10", "s20", "sG", "sG/s1"]
    return h + (["exact s1 / sG", "H error RMS"] if with_exact else [])


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
print("Increase over the clean geodesic sphere, sigma_L(noisy) - sigma_L(clean):\n")
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
print("Per run: sigma_1 at the start, the ratio end/start of sigma at levels 1, 5, 20 and global after the")
print("last iteration, the smallest sigma_1 over the recorded iterations (ratio to the start, and where), and the")
print("final mesh against the *clean* surface (noise-free sphere; the ellipsoid itself; bunny_closed; igea):")
print("signed relative change of sigma_20 and sigma_G ((result - clean)/clean), and the forward RMS surface")
print("distance relative to the clean mesh's bounding-box diagonal.\n")
methods = ("laplacian", "taubin", "bilaplacian", "mcf", "modified-mcf")
# Extra runs of the flows on the noisy scans: adaptive step control and implicit MCF.
flow_runs = ("mcf-adaptive", "modified-mcf-adaptive", "mcf-implicit")


def flow_cols(d):
    """Explicit flows: the largest dt/S over the iterations, the first iteration above 1, the flow time."""
    fl = d.get("flow")
    if not fl:
        return ["", ""]
    ratio = fl["stability_ratio"]
    first = next((k + 1 for k, r in enumerate(ratio) if r > 1), None)
    worst = f(max(ratio), 3) + (f" (>1 from it {first})" if first else "")
    return [worst, f(fl["time"][-1], 3)]


def vs_clean_cols(c):
    if not c:
        return ["n/a"] * 4
    rd, sd = c["roughness_distance"], c["surface_distance"]
    rc = dict(zip(rd["levels"], rd["relative_change"]))
    return [f(rc.get(1), 3), f(rc.get(20), 3), f(rd["global"]["relative_change"], 3),
            f(sd["forward"]["relative"]["rms"], 3)]


VSH = ["vs clean: s1 change", "s20 change", "sG change", "RMS dist / diag"]
for mesh in ("noisy_sphere", "ellipsoid", "bunny_noisy", "igea_noisy"):
    rows = []
    c = load("3_smoothing", f"{mesh}_input_vs_clean.json")
    if c:
        rows.append(["input (not smoothed)", 0, "", "", "", "", "", ""] + vs_clean_cols(c) + ["", ""])
    for u in ("post", "pre"):
        for m in methods + flow_runs:
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
            r.append(f(g1 / g0 if g0 else None, 3))
            kmin = min(range(len(d["iterations"])), key=lambda k: d["sigma"][k][0])
            r.append(f"{f(d['sigma'][kmin][0] / s0[0], 3)} @ {d['iterations'][kmin]}")
            r += vs_clean_cols(load("3_smoothing", f"{mesh}_{u}_{m}_vs_clean.json"))
            r += flow_cols(d)
            rows.append(r)
    if rows:
        print(f"### {mesh}\n")
        table(["run", "iterations", "s1 start", "s1 end/start", "s5 end/start", "s20 end/start", "sG end/start",
               "min s1/start @ it"] + VSH + ["max dt/S", "flow time / e^2"], rows)
    rows = []
    for m in methods:
        c = load("3_smoothing", f"{mesh}_short_{m}_vs_clean.json")
        if c:
            rows.append([m] + vs_clean_cols(c))
    if rows:
        print(f"{mesh} after the shorter post-updating run, against the clean mesh:\n")
        table(["method"] + VSH, rows)

print("## 4. Regular against irregular sampling (Figs. 13-14)\n")
items = []
for s in ("torus", "heightfield"):
    for r in ("regular", "irregular"):
        items.append((f"{s} {r}", load("4_sampling", f"{s}_{r}.json")))
items += [(m, load("4_sampling", m + ".json")) for m in ("sphere_ico_2562", "sphere_irregular_3072")]
table(head(True), profile_rows(items, True))

print("## 5. Goldfeather against Meyer (Fig. 3)\n")
items = []
for mesh, label in (("smoothed_sphere", "noisy sphere + 10 Laplacian"), ("sphere_noise_0", "clean geodesic sphere"),
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
