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
RING = {}


def rule_count(d, key):
    """How often a robustness rule of the curvature fit fired (METHOD.md section 4), with its share of the vertices."""
    if not d:
        return "n/a"
    c = d.get("curvature", {})
    w = c.get(key)
    n = d.get("mesh", {}).get("vertices")
    if w is None or not n:
        return "n/a"
    return f"{w} ({100 * w / n:.2g}%)"


def widened(d):
    """2-ring widenings of the curvature fit."""
    return rule_count(d, "widened_to_2_ring")


def dropped(d):
    """Fits that left out a neighbour's normal rows (the 60-degree rule)."""
    return rule_count(d, "normal_rows_dropped")


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
        r += [widened(d), dropped(d)]
        rows.append(r)
    return rows


def head(with_exact=False):
    h = ["mesh", "s1", "s2", "s5", "s10", "s20", "sG", "sG/s1"]
    return h + (["exact s1 / sG", "H error RMS"] if with_exact else []) + ["2-ring widened", "normal rows dropped"]


print("# Numbers of the reference studies\n")
print("Written by `reference/summarize.py` from `reference/out/`. sigma values are on meshes scaled to mean vertex")
print("distance 1 from the centroid (METHOD.md section 2); sN = sigma at level N, sG = global level.\n")

print("## 1. Noise and stretching (Fig. 5)\n")
items = [(f"noise {n}", load("1_sphere_noise_stretch", f"noise_{n}.json")) for n in ("0", "0.005", "0.01", "0.02", "0.04", "0.14")]
table(head(True), profile_rows(items, True))
base = items[0][1]
rows = []
for name, d in items[1:]:
    if d and base:
        rows.append([name] + [f(sig(d, L) - sig(base, L)) for L in LV])
print("Increase over the clean geodesic sphere, sigma_L(noisy) - sigma_L(clean):\n")
table(["mesh", "d1", "d2", "d5", "d10", "d20", "dG"], rows)
print("What white noise in H averaged over a finite ring gives by itself (`analysis.py ringnoise`): for H noise")
print("with variance s^2 and no correlation between vertices, Var(H_i - mean over n others) = s^2 (1 + 1/n), so")
print("sigma_L/sigma_G = sqrt(mean_i(1 + 1/n_L(i)) / (1 + 1/(N-1))), with n_L(i) the ring sizes of this mesh.")
print("Measured = the same ratio from the estimated H; last columns: correlation of H between vertices one and")
print("exactly two edges apart.\n")
rows = []
for n in ("0.02", "0.04", "0.14"):
    r = load("1_sphere_noise_stretch", f"ringnoise_{n}.json")
    if r:
        rows.append([f"noise {n}"] + [f"{f(w, 4)} / {f(m, 4)}" for w, m in zip(r["white_noise_ratio"], r["measured_ratio"])]
                    + [f(r["h_correlation_1_ring"], 2), f(r.get("h_correlation_2_ring"), 2)])
        RING[n] = r
table(["mesh", "s1/sG white / measured", "s2/sG", "s5/sG", "s10/sG", "s20/sG", "H corr. 1 edge", "2 edges"], rows)
items = [(f"axes {a},1,1", load("1_sphere_noise_stretch", f"stretch_{a}.json")) for a in ("1", "1.2", "1.25", "1.5", "2", "3")]
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
table(head() + ["top-0.1% share of s1^2", "vertices"],
      [r + [f(d["level_details"][0]["top_share"], 2), d["mesh"]["vertices"]]
       for r, (_, d) in zip(profile_rows([it for it in items if it[1]]), [it for it in items if it[1]])])

methods = ("laplacian", "taubin", "bilaplacian", "mcf", "modified-mcf")
# Extra runs of the flows on the noisy scans: adaptive step control and implicit MCF.
flow_runs = ("mcf-adaptive", "modified-mcf-adaptive", "mcf-implicit")


def flow_cols(d):
    """Explicit flows: dt/S at the first iteration, the largest over the iterations (and the first
    iteration above 1), the flow time."""
    fl = d.get("flow")
    if not fl:
        return ["", ""]
    ratio = fl["stability_ratio"]
    first = next((k + 1 for k, r in enumerate(ratio) if r > 1), None)
    worst = f(ratio[0], 3) + " / " + f(max(ratio), 3) + (f" (>1 from it {first})" if first else "")
    return [worst, f(fl["time"][-1], 3)]


def vs_clean_cols(c):
    if not c:
        return ["n/a"] * 6
    rd, sd = c["roughness_distance"], c["surface_distance"]
    rc = dict(zip(rd["levels"], rd["relative_change"]))
    return [f(rc.get(1), 3), f(rc.get(20), 3), f(rd["global"]["relative_change"], 3),
            f(sd["forward"]["relative"]["rms"], 3), widened(c["processed"]), dropped(c["processed"])]


VSH = ["vs clean: s1 change", "s20 change", "sG change", "RMS dist / diag", "2-ring widened (final mesh)",
       "normal rows dropped (final mesh)"]
SMOOTH = {}  # (dir, mesh, update, method) -> smoothing report, for the verdicts
VSC = {}     # (dir, mesh, update or "short" or "input", method) -> compare report against the clean mesh


def smoothing_tables(sub, meshes, with_short=False):
    for mesh in meshes:
        rows = []
        c = load(sub, f"{mesh}_input_vs_clean.json")
        VSC[(sub, mesh, "input", None)] = c
        if c:
            rows.append(["input (not smoothed)", 0, f(c["processed"]["sigma"][0], 3), "", "", "", "", ""]
                        + vs_clean_cols(c) + ["", ""])
        for u in ("post", "pre"):
            for m in methods + flow_runs:
                d = load(sub, f"{mesh}_{u}_{m}.json")
                if d is None:
                    continue
                SMOOTH[(sub, mesh, u, m)] = d
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
                c = load(sub, f"{mesh}_{u}_{m}_vs_clean.json")
                VSC[(sub, mesh, u, m)] = c
                r += vs_clean_cols(c)
                r += flow_cols(d)
                rows.append(r)
        if rows:
            print(f"### {mesh}\n")
            table(["run", "iterations", "s1 start", "s1 end/start", "s5 end/start", "s20 end/start", "sG end/start",
                   "min s1/start @ it"] + VSH + ["dt/S first / max", "flow time / e^2"], rows)
        best = best_method_by_iteration(sub, mesh)
        if best:
            print(f"Lowest sigma_1 among the five post-updating methods, per recorded iteration: {best}\n")
        if not with_short:
            continue
        rows = []
        for m in methods:
            c = load(sub, f"{mesh}_short_{m}_vs_clean.json")
            VSC[(sub, mesh, "short", m)] = c
            if c:
                rows.append([m] + vs_clean_cols(c))
        if rows:
            print(f"{mesh} after the shorter post-updating run, against the clean mesh:\n")
            table(["method"] + VSH, rows)


def best_method_by_iteration(sub, mesh):
    runs = {m: SMOOTH.get((sub, mesh, "post", m)) for m in methods}
    if not all(runs.values()):
        return None
    its = runs["laplacian"]["iterations"]
    out = []
    for k, it in enumerate(its):
        if it == 0:
            continue
        vals = {m: d["sigma"][k][0] for m, d in runs.items() if k < len(d["sigma"]) and d["sigma"][k][0] is not None}
        out.append(f"{it}: {min(vals, key=vals.get)}")
    return ", ".join(out)


def laplacian_best_until(sub, mesh):
    """Last recorded iteration up to which Laplacian has the lowest sigma_1 of the five methods (post)."""
    runs = {m: SMOOTH.get((sub, mesh, "post", m)) for m in methods}
    if not all(runs.values()):
        return None
    last = None
    for k, it in enumerate(runs["laplacian"]["iterations"]):
        if it == 0:
            continue
        vals = {m: d["sigma"][k][0] for m, d in runs.items()}
        if min(vals, key=vals.get) == "laplacian":
            last = it
        else:
            break
    return last


print("## 3. Smoothing, extra: noisy inputs (Figs. 6-9, 11)\n")
print("Not the paper's inputs (see section 7 and the README's deviations table): 2% noise on the sphere, the")
print("ellipsoid (1.5, 1, 1), and noise of +-0.5 mean edge lengths on bunny_closed and igea.\n")
print("Per run: sigma_1 at the start, the ratio end/start of sigma at levels 1, 5, 20 and global after the")
print("last iteration, the smallest sigma_1 over the recorded iterations (ratio to the start, and where), and the")
print("final mesh against the *clean* surface (noise-free sphere; the ellipsoid itself; bunny_closed; igea):")
print("signed relative change of sigma_1, sigma_20 and sigma_G ((result - clean)/clean), the forward RMS surface")
print("distance relative to the clean mesh's bounding-box diagonal, and the counts of curvature fits widened to")
print("the 2-ring and of fits that dropped a neighbour's normal rows (60-degree rule) on the final mesh. Explicit")
print("flows: dt/S (step over the stability bound) at the first iteration and the largest.\n")
smoothing_tables("3_smoothing", ("noisy_sphere", "ellipsoid", "bunny_noisy", "igea_noisy"), with_short=True)

print("## 7. Smoothing on the paper's inputs (Figs. 6-12)\n")
print("Geodesic sphere with 4% radial noise, ellipsoid (1.2, 1, 1), bunny_closed without noise, igea with")
print("uniform noise of +-0.004% of its bounding-box diagonal along the normals, rocker_arm (clean). Columns as")
print("in section 3; the clean surface is the noise-free sphere, igea, and the input itself for the others.\n")
smoothing_tables("7_smoothing_paper", ("sphere4", "ellipsoid12", "bunny", "igea", "rocker_arm"))
rows = []
for m in ("none",) + methods:
    v = load("7_smoothing_paper", f"ellipsoid_{m}_by_valence.json")
    if v is None:
        continue
    b = v["by_valence"]
    d3, H = b["D_3"], b["H"]
    r5, r6 = d3.get("5", {}).get("rms"), d3.get("6", {}).get("rms")
    rows.append([m, f(r5, 3), f(r6, 3), f(r5 / r6 if r5 and r6 else None, 3),
                 f(H.get("5", {}).get("mean_abs"), 4), f(H.get("6", {}).get("mean_abs"), 4)])
if rows:
    print("Bumps on the paper's ellipsoid (1.2, 1, 1) after the post-updating runs (as section 6):\n")
    table(["smoothing", "RMS D_3 valence 5", "RMS D_3 valence 6", "ratio", "mean H valence 5", "mean H valence 6"], rows)

print("## 4. Regular against irregular sampling (Figs. 13-14)\n")
items = []
for s in ("torus", "heightfield"):
    for r in ("regular", "irregular"):
        items.append((f"{s} {r}", load("4_sampling", f"{s}_{r}.json")))
items += [(m, load("4_sampling", m + ".json")) for m in ("sphere_ico_2562", "sphere_ico_10242", "sphere_irregular_3072",
                                                         "bunny_closed", "bunny_adaptive", "bunny")]
table(head(True), profile_rows(items, True))

print("## 5. Goldfeather against Meyer on static spheres (Fig. 3, extra)\n")
items = []
for mesh, label in (("smoothed_sphere", "noisy sphere + 10 Laplacian"), ("sphere_noise_0", "clean geodesic sphere"),
                    ("sphere_irregular_3072", "sphere_irregular_3072")):
    for c in ("goldfeather", "quadric", "meyer"):
        items.append((f"{label}, {c}", load("5_curvature", f"{mesh}_{c}.json")))
table(head(), profile_rows(items))

print("## 6. Bumps on a smoothed ellipsoid (1.5, 1, 1) (Fig. 10, extra input)\n")
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

print("## 8. Fig. 3 as the paper ran it\n")
print("A clean geodesic sphere (frequency 20, 4,002 vertices) smoothed with pre-updating Laplacian and MCF (step")
print("0.1). Per recorded iteration: sigma_1 and sigma_G with the cubic fit (goldfeather) and Meyer on the smoothed")
print("mesh; the same with the vertices projected radially onto the sphere of their mean radius (same sampling,")
print("exact H constant, so what an estimator reports there is its error for that sampling); the radius spread")
print("r_i/r_mean - 1; and sigma_G of r_mean/r_i, the H of the sphere through each vertex (the zeroth-order")
print("geometric part).\n")
F3 = load("8_fig3", "fig3.json")
if F3:
    for m, r in F3.items():
        rows = []
        for k, it in enumerate(r["iterations"]):
            g, me = r["goldfeather"], r["meyer"]
            sp = r["radius_spread"][k]
            rows.append([it, f(g["sigma_1"][k], 3), f(me["sigma_1"][k], 3), f(g["sigma_1_projected"][k], 3),
                         f(me["sigma_1_projected"][k], 3), f(g["sigma_global"][k], 3), f(me["sigma_global"][k], 3),
                         f(g["sigma_global_projected"][k], 3), f(me["sigma_global_projected"][k], 3),
                         f"{100 * sp['min']:.2f} .. {100 * sp['max']:.2f}", f(r["inverse_radius_sigma_global"][k], 3)])
        print(f"### {m}, pre-updating\n")
        table(["iteration", "s1 cubic", "s1 Meyer", "s1 cubic, projected", "s1 Meyer, projected", "sG cubic", "sG Meyer",
               "sG cubic, projected", "sG Meyer, projected", "radius spread %", "sG of r_mean/r_i"], rows)

# ---------------------------------------------------------------------------------------------
# One line of numbers per verdict of reference/README.md.
V = []


def pct(x):
    return "n/a" if x is None else f"{100 * x:+.1f}%"


def rc(c, L):
    """Signed relative change of sigma_L (L = 'G' for global) of a compare report."""
    if not c:
        return None
    rd = c["roughness_distance"]
    if L == "G":
        return rd["global"]["relative_change"]
    return dict(zip(rd["levels"], rd["relative_change"])).get(L)


def ratio_end(d, L):
    if not d:
        return None
    if L == "G":
        return d["sigma_global"][-1] / d["sigma_global"][0]
    k = d["levels"].index(L)
    return d["sigma"][-1][k] / d["sigma"][0][k]


def rise_after_min(d, L=1):
    """Iteration of the smallest recorded sigma_L (L = 'G' for global) and sigma at the end over that minimum."""
    s = d["sigma_global"] if L == "G" else [r[d["levels"].index(L)] for r in d["sigma"]]
    k = min(range(len(s)), key=lambda i: s[i])
    return d["iterations"][k], s[-1] / s[k]


def at_it(d, it, L=1):
    if not d or it not in d["iterations"]:
        return None
    k = d["iterations"].index(it)
    if L == "G":
        return d["sigma_global"][k] / d["sigma_global"][0]
    return d["sigma"][k][d["levels"].index(L)] / d["sigma"][0][d["levels"].index(L)]


n2, n14 = load("1_sphere_noise_stretch", "noise_0.02.json"), load("1_sphere_noise_stretch", "noise_0.14.json")
if n2 and n14 and RING:
    V.append(("Fig. 1a noisy sphere rougher locally",
              f"2%: s1 {f(sig(n2, 1), 3)}, sG {f(sig(n2, 'G'), 3)}, s1/sG {f(sig(n2, 1) / sig(n2, 'G'), 3)}; "
              f"14% (paper): s1 {f(sig(n14, 1), 3)}, sG {f(sig(n14, 'G'), 3)}, s1/sG {f(sig(n14, 1) / sig(n14, 'G'), 3)}; "
              f"white-noise ring average alone: {f(RING['0.02']['white_noise_ratio'][0], 3)} at L1, "
              f"{f(RING['0.02']['white_noise_ratio'][1], 3)} at L2 (measured 2%: {f(RING['0.02']['measured_ratio'][1], 3)})"))
b = load("2_models", "bunny_closed.json")
if b:
    V.append(("Fig. 1b bunny rougher globally",
              f"bunny_closed s1 {f(sig(b, 1), 3)}, s20 {f(sig(b, 20), 3)}, sG {f(sig(b, 'G'), 3)} (sG/s1 {f(sig(b, 'G') / sig(b, 1), 3)})"))
ig, ro = load("2_models", "igea.json"), load("2_models", "rocker_arm.json")
if ig and ro:
    all_levels = list(range(1, 21)) + ["G"]
    rougher = [str(L) for L in all_levels if sig(ro, L) > sig(ig, L)]
    smoother = [f"{L} ({f(sig(ro, L), 3)} vs {f(sig(ig, L), 3)})" for L in all_levels if sig(ro, L) <= sig(ig, L)]
    V.append(("Fig. 4 the Rocker arm smoother than Venus (igea) at every level",
              f"s1 rocker_arm {f(sig(ro, 1), 3)} vs igea {f(sig(ig, 1), 3)}; sG {f(sig(ro, 'G'), 3)} vs {f(sig(ig, 'G'), 3)}; "
              f"rocker_arm rougher at {len(rougher)} of {len(all_levels)} levels: {', '.join(rougher) or 'none'}; "
              f"smoother at {len(smoother)}: {', '.join(smoother) or 'none'}; vertices {ro['mesh']['vertices']} vs "
              f"{ig['mesh']['vertices']} (igea x{ig['mesh']['vertices'] / ro['mesh']['vertices']:.1f})"))
n0 = load("1_sphere_noise_stretch", "noise_0.json")
m0 = load("5_curvature", "sphere_noise_0_meyer.json")
if n0:
    V.append(("Fig. 5a clean sphere rises with level",
              f"cubic s1 {f(sig(n0, 1), 3)} -> s10 {f(sig(n0, 10), 3)} -> sG {f(sig(n0, 'G'), 3)} (x{sig(n0, 'G') / sig(n0, 1):.2g}); "
              f"exact-H profile 0; H error RMS {f(n0['exact']['h_error']['rms'], 3)}"
              + (f"; Meyer s1 {f(sig(m0, 1), 3)}, sG {f(sig(m0, 'G'), 3)}" if m0 else "")))
n4 = load("1_sphere_noise_stretch", "noise_0.04.json")
if n0 and n2 and n4:
    V.append(("noise raises all levels, most at low levels",
              "increase L1 / L5 / G: " + "; ".join(
                  f"{nm} +{f(sig(d, 1) - sig(n0, 1), 3)} / +{f(sig(d, 5) - sig(n0, 5), 3)} / +{f(sig(d, 'G') - sig(n0, 'G'), 3)}"
                  f" (L1/G x{(sig(d, 1) - sig(n0, 1)) / (sig(d, 'G') - sig(n0, 'G')):.3g})"
                  for nm, d in (("2%", n2), ("4%", n4), ("14%", n14)))))
e12, e15 = load("1_sphere_noise_stretch", "stretch_1.2.json"), load("1_sphere_noise_stretch", "stretch_1.5.json")
if n0 and e12 and e15:
    V.append(("stretching raises high levels most",
              "; ".join(f"({a},1,1): +{f(sig(d, 1) - sig(n0, 1), 2)} L1, +{f(sig(d, 5) - sig(n0, 5), 2)} L5, "
                        f"+{f(sig(d, 20) - sig(n0, 20), 2)} L20, +{f(sig(d, 'G') - sig(n0, 'G'), 2)} G"
                        for a, d in (("1.2", e12), ("1.5", e15)))))
tr, ti = load("4_sampling", "torus_regular.json"), load("4_sampling", "torus_irregular.json")
hr, hi = load("4_sampling", "heightfield_regular.json"), load("4_sampling", "heightfield_irregular.json")
sr, si = load("4_sampling", "sphere_ico_2562.json"), load("4_sampling", "sphere_irregular_3072.json")
if tr and ti and hr and hi and sr and si:
    V.append(("irregular sampling raises local, not global roughness",
              "; ".join(f"{nm}: s1 {f(sig(a, 1), 2)} -> {f(sig(c, 1), 2)}, sG {f(sig(a, 'G'), 3)} -> {f(sig(c, 'G'), 3)} "
                        f"({pct(sig(c, 'G') / sig(a, 'G') - 1)})"
                        for nm, a, c in (("torus", tr, ti), ("height field", hr, hi), ("sphere", sr, si)))))
bc, ba, bs = load("4_sampling", "bunny_closed.json"), load("4_sampling", "bunny_adaptive.json"), load("4_sampling", "bunny.json")
s10 = load("4_sampling", "sphere_ico_10242.json")
if bc and ba and bs:
    V.append(("global roughness does not depend on the mesh",
              f"bunny sG closed {f(sig(bc, 'G'), 3)}, adaptive remesh {f(sig(ba, 'G'), 3)} ({pct(sig(ba, 'G') / sig(bc, 'G') - 1)}), "
              f"open scan {f(sig(bs, 'G'), 3)} ({pct(sig(bs, 'G') / sig(bc, 'G') - 1)}); s1 {f(sig(bc, 1), 3)} / "
              f"{f(sig(ba, 1), 3)} / {f(sig(bs, 1), 3)}; torus and height field as above"
              + (f"; unit sphere sG ico 2562 {f(sig(sr, 'G'), 2)}, ico 10242 {f(sig(s10, 'G'), 2)}, irregular {f(sig(si, 'G'), 2)}"
                 if s10 and sr and si else "")))
P7 = "7_smoothing_paper"
parts = []
for mesh in ("sphere4", "bunny", "igea", "rocker_arm"):
    xs = [f"{m} x{f(ratio_end(SMOOTH.get((P7, mesh, 'post', m)), 1), 2)}" for m in methods
          if SMOOTH.get((P7, mesh, "post", m))]
    if xs:
        parts.append(f"{mesh}: " + ", ".join(xs))
if parts:
    V.append(("Laplacian, MCF, modified MCF remove local roughness (s1 end/start, 50 post it., paper inputs)", "; ".join(parts)))
parts = []
for sub, mesh in ((P7, "sphere4"), (P7, "ellipsoid12"), (P7, "bunny"), (P7, "igea"), (P7, "rocker_arm"),
                  ("3_smoothing", "bunny_noisy"), ("3_smoothing", "igea_noisy")):
    if "sphere" in mesh:  # the clean sphere has sG ~ 0: its relative change says nothing; surface distance
        xs = [f"{m} {f(VSC[(sub, mesh, 'post', m)]['surface_distance']['forward']['relative']['rms'], 2)}" for m in methods
              if VSC.get((sub, mesh, "post", m))]
        if xs:
            parts.append(f"{mesh} (RMS distance / diag): " + ", ".join(xs))
        continue
    xs = [f"{m} {pct(rc(VSC.get((sub, mesh, 'post', m)), 'G'))}" for m in methods if VSC.get((sub, mesh, "post", m))]
    if xs:
        parts.append(f"{mesh}: " + ", ".join(xs))
    if sub == "3_smoothing":
        xs = [f"{m} {pct(rc(VSC.get((sub, mesh, 'short', m)), 'G'))}" for m in methods if VSC.get((sub, mesh, "short", m))]
        if xs:
            parts.append(f"{mesh} after 20: " + ", ".join(xs))
if parts:
    V.append(("Taubin and bilaplacian keep global features (sG after 50 post it. vs the clean mesh)", "; ".join(parts)))
parts = []
for sub, nm in (("6_bumps", "(1.5,1,1)"), (P7, "(1.2,1,1)")):
    xs = []
    for m in methods:
        v = load(sub, f"ellipsoid_{m}_by_valence.json")
        if v:
            d3 = v["by_valence"]["D_3"]
            xs.append(f"{m} {f(d3['5']['rms'], 2)}/{f(d3['6']['rms'], 2)} (x{d3['5']['rms'] / d3['6']['rms']:.2g})")
    if xs:
        parts.append(f"{nm}: " + ", ".join(xs))
if parts:
    V.append(("Laplacian and Taubin create bumps at valence-5 vertices (RMS D_3 valence 5 / 6)", "; ".join(parts)))
parts = []
for sub, mesh in ((P7, "sphere4"), (P7, "ellipsoid12"), (P7, "bunny"), ("3_smoothing", "noisy_sphere"),
                  ("3_smoothing", "ellipsoid"), ("3_smoothing", "bunny_noisy")):
    xs = []
    for m in ("laplacian", "mcf", "modified-mcf"):
        a, c = VSC.get((sub, mesh, "post", m)), VSC.get((sub, mesh, "pre", m))
        if a and c and "sphere" in mesh:
            xs.append(f"{m} sG {f(a['processed']['sigma_global'], 2)} / {f(c['processed']['sigma_global'], 2)}, dist "
                      f"{f(a['surface_distance']['forward']['relative']['rms'], 2)} / "
                      f"{f(c['surface_distance']['forward']['relative']['rms'], 2)}")
        elif a and c:
            xs.append(f"{m} sG {pct(rc(a, 'G'))} / {pct(rc(c, 'G'))}, dist "
                      f"{f(a['surface_distance']['forward']['relative']['rms'], 2)} / "
                      f"{f(c['surface_distance']['forward']['relative']['rms'], 2)}")
    if xs:
        parts.append(f"{mesh} (post / pre): " + "; ".join(xs))
if parts:
    V.append(("post-updating keeps global features better (sG vs clean and RMS distance / diag, 50 it.)", " | ".join(parts)))
if F3:
    xs = []
    for m, r in F3.items():
        k = len(r["iterations"]) - 1
        g, me = r["goldfeather"], r["meyer"]
        sp = r["radius_spread"][k]
        xs.append(f"{m} pre, {r['iterations'][k]} it.: s1 cubic {f(g['sigma_1'][0], 2)} -> {f(g['sigma_1'][k], 2)}, Meyer "
                  f"{f(me['sigma_1'][0], 2)} -> {f(me['sigma_1'][k], 2)}; sG cubic {f(g['sigma_global'][k], 2)}, Meyer "
                  f"{f(me['sigma_global'][k], 2)}; projected (estimator error) sG cubic {f(g['sigma_global_projected'][k], 2)}, "
                  f"Meyer {f(me['sigma_global_projected'][k], 2)}; radius spread {100 * sp['min']:.2f}%..{100 * sp['max']:+.2f}%")
    V.append(("Fig. 3 Meyer makes a smoothed sphere rougher, the cubic fit does not", " | ".join(xs)))
parts = []
for sub, mesh in ((P7, "sphere4"), (P7, "bunny"), (P7, "igea"), (P7, "rocker_arm"), ("3_smoothing", "noisy_sphere"),
                  ("3_smoothing", "bunny_noisy"), ("3_smoothing", "igea_noisy")):
    last = laplacian_best_until(sub, mesh)
    if (sub, mesh, "post", "laplacian") in SMOOTH:
        parts.append(f"{mesh}: {'never' if last is None else 'up to ' + str(last)}")
if parts:
    V.append(("Fig. 8 Laplacian removes local roughness best (lowest s1 of the five, post)", "; ".join(parts)))
parts = []
for sub, mesh in ((P7, "sphere4"), (P7, "bunny"), (P7, "igea"), (P7, "rocker_arm"), ("3_smoothing", "noisy_sphere"),
                  ("3_smoothing", "bunny_noisy"), ("3_smoothing", "igea_noisy")):
    xs = []
    for m in ("taubin", "bilaplacian", "laplacian"):
        d = SMOOTH.get((sub, mesh, "post", m))
        if d:
            (i1, r1), (iG, rG) = rise_after_min(d, 1), rise_after_min(d, "G")
            xs.append(f"{m} s1 min @{i1} end/min {r1:.3f}, sG min @{iG} end/min {rG:.3f}")
    if xs:
        parts.append(f"{mesh}: " + ", ".join(xs))
if parts:
    V.append(("Fig. 8 Taubin and bilaplacian re-roughen (post, 50 it.: iteration of the smallest sigma, end / smallest)",
              "; ".join(parts)))
parts = []
for sub, mesh, nm in ((P7, "ellipsoid12", "(1.2,1,1)"), ("3_smoothing", "ellipsoid", "(1.5,1,1)")):
    for u in ("post", "pre"):
        xs = [f"{m} x{f(ratio_end(SMOOTH.get((sub, mesh, u, m)), 1), 3)}" for m in methods if SMOOTH.get((sub, mesh, u, m))]
        if xs:
            parts.append(f"{nm} {u}: " + ", ".join(xs))
if parts:
    V.append(("Fig. 9 smoothing raises the ellipsoid's local roughness (s1 end/start, 50 it.)", "; ".join(parts)))
st = [(nm, SMOOTH.get(("3_smoothing", mesh, "post", "mcf"))) for nm, mesh in (("bunny", "bunny_noisy"), ("igea", "igea_noisy"))]
st += [(nm + " (paper input)", SMOOTH.get((P7, mesh, "post", "mcf")))
       for nm, mesh in (("bunny", "bunny"), ("igea", "igea"), ("rocker_arm", "rocker_arm"), ("sphere 4%", "sphere4"))]
st += [("sphere 2% (extra)", SMOOTH.get(("3_smoothing", "noisy_sphere", "post", "mcf")))]
xs = [f"{nm}: first {f(d['flow']['stability_ratio'][0], 3)}, max {f(max(d['flow']['stability_ratio']), 3)}"
      for nm, d in st if d and d.get("flow")]
if xs:
    V.append(("explicit MCF step 0.1 against the stability bound S (dt/S)", "; ".join(xs)))

print("## Verdict numbers\n")
print("The numbers quoted by each verdict line of reference/README.md, read from the reports above.\n")
table(["observation", "numbers"], V)

t = os.path.join(OUT, "timing.txt")
if os.path.exists(t):
    print("## Run time\n")
    print("```")
    print(open(t).read().rstrip())
    print("```")
