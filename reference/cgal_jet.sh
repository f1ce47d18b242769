#!/usr/bin/env bash
# Cross-check of meshdiff's jet curvature estimator (`--curvature jet`, issue 28)
# against CGAL's Monge_via_jet_fitting (d_fitting 3, d_monge 2) on the same
# neighbourhoods (2-ring, 3-ring below 15 neighbours), on analytic meshes with
# exact H under refinement (4x vertices per step), on two real meshes, and on
# a smoothed real mesh and a noisy torus (where the two fits part).
#
#   MESHDIFF=build/meshdiff MESHES=../shared/data/meshes reference/cgal_jet.sh
#
# Needs libcgal-dev (Debian, header-only; it pulls libgmp-dev, libmpfr-dev) and
# libeigen3-dev (CGAL's SVD), g++, and python3 (standard library only). Both
# tools work on the identical mesh: meshdiff profile --vertex-data writes the
# normalised mesh (scaled to mean vertex distance 1 from the centroid) with its
# per-vertex H, and the CGAL program reads that file. The exact H on the scaled
# mesh is the generator's exact_H times the profile's normalization scale (a
# sphere of radius 2 has exact_H 0.5, scale 2, and H 1 once scaled: the first
# row checks this and the sign). Writes out/10_jet_cgal/cgal_jet.csv and
# cgal_jet.md; the CGAL program and the meshes go to out/work/ (git-ignored).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${MESHDIFF:-build/meshdiff}
meshes=${MESHES:-../shared/data/meshes}
out=reference/out/10_jet_cgal
work=reference/out/work
mkdir -p "$out" "$work/jet_cgal"
if [[ ! -x $work/cgal_jet || reference/cgal/cgal_jet.cpp -nt $work/cgal_jet ]]; then
    echo "building $work/cgal_jet (CGAL $(dpkg-query -W -f='${Version}' libcgal-dev 2>/dev/null || echo '?'))"
    g++ -std=c++17 -O2 -DNDEBUG -DCGAL_NDEBUG -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 \
        -o "$work/cgal_jet" reference/cgal/cgal_jet.cpp -lgmp -lmpfr
fi
python3 - "$bin" "$work/cgal_jet" "$work/jet_cgal" "$out" "$meshes" <<'PY'
import csv, json, math, os, subprocess, sys
sys.path.insert(0, "reference")
from plytool import read_ply

meshdiff, cgal, work, out, meshes = sys.argv[1:6]

# (family, generate arguments); each family is refined by 4x vertices per step.
analytic = [("sphere r=2 (sign and scale check)", ["sphere", "--subdivisions", "5", "--radius", "2"])]
for n in (4000, 16000, 64000):
    analytic.append(("torus-irregular", ["torus-irregular", "--vertices", str(n)]))
for n in (4000, 16000, 64000):
    analytic.append(("heightfield-irregular", ["heightfield-irregular", "--vertices", str(n)]))
for s in (4, 5, 6):
    analytic.append(("ellipsoid 1.5:1:1", ["ellipsoid", "--subdivisions", str(s)]))


def profile(mesh, method, stem):
    vd, js = f"{work}/{stem}_{method}_vd.ply", f"{work}/{stem}_{method}.json"
    subprocess.run([meshdiff, "profile", mesh, "--curvature", method, "--levels", "1", "--no-global", "--threads", "1",
                    "-q", "--vertex-data", vd, "--json", js], check=True, stdout=subprocess.DEVNULL)
    names, verts, faces, _ = read_ply(vd)
    with open(js) as f:
        j = json.load(f)
    return vd, [v[names.index("H")] for v in verts], faces, j["mesh"]["normalization"]["scale"]


def interior(nverts, faces):
    """Vertices on no boundary edge (an edge of exactly one face)."""
    count = {}
    for f in faces:
        for a, b in zip(f, f[1:] + f[:1]):
            e = (min(a, b), max(a, b))
            count[e] = count.get(e, 0) + 1
    on = set()
    for (a, b), c in count.items():
        if c == 1:
            on.update((a, b))
    return [i for i in range(nverts) if i not in on]


def stats(a, b, ids):
    d = [abs(a[i] - b[i]) for i in ids if math.isfinite(a[i]) and math.isfinite(b[i])]
    return math.sqrt(sum(x * x for x in d) / len(d)), max(d), len(ids) - len(d)


def run_cgal(vd):
    r = subprocess.run([cgal, vd], check=True, capture_output=True, text=True)
    return [float(x) for x in r.stdout.split()]


rows = []
for family, args in analytic:
    stem = "_".join(a.lstrip("-") for a in args)
    mesh = f"{work}/{stem}.ply"
    if not os.path.exists(mesh):
        subprocess.run([meshdiff, "generate", args[0], mesh] + args[1:], check=True, stdout=subprocess.DEVNULL)
    names, verts, _, _ = read_ply(mesh)
    exact_unscaled = [v[names.index("exact_H")] for v in verts]
    vd, jet, faces, scale = profile(mesh, "jet", stem)
    _, gf, _, scale_gf = profile(mesh, "goldfeather", stem)
    assert len(jet) == len(exact_unscaled) == len(gf) and scale == scale_gf, "vertex data does not match the input"
    exact = [h * scale for h in exact_unscaled]  # H scales as 1/length: the mesh is divided by scale
    cg = run_cgal(vd)
    ids = interior(len(jet), faces)
    r = {"mesh": family, "generate": " ".join(args), "vertices": len(jet), "interior": len(ids), "scale": scale,
         "rms_exact_H": math.sqrt(sum(exact[i] ** 2 for i in ids) / len(ids))}
    for key, a, b in (("jet_exact", jet, exact), ("cgal_exact", cg, exact), ("jet_cgal", jet, cg),
                      ("goldfeather_exact", gf, exact)):
        r[f"{key}_rms"], r[f"{key}_max"], r[f"{key}_nan"] = stats(a, b, ids)
    rows.append(r)
    print(f"{family} {r['vertices']}: |jet-exact| {r['jet_exact_rms']:.3g}/{r['jet_exact_max']:.3g}, "
          f"|cgal-exact| {r['cgal_exact_rms']:.3g}/{r['cgal_exact_max']:.3g}, "
          f"|jet-cgal| {r['jet_cgal_rms']:.3g}/{r['jet_cgal_max']:.3g}, "
          f"|goldfeather-exact| {r['goldfeather_exact_rms']:.3g}/{r['goldfeather_exact_max']:.3g}", flush=True)

# Without exact H: two real meshes; then where the two fits part: bunny_closed before and after 10 Taubin
# iterations, and the 16,000-vertex torus with noise along the vertex normals (uniform in [-A, A) edge lengths).
second = [("bunny.ply", f"{meshes}/bunny.ply"), ("fandisk.ply", f"{meshes}/fandisk.ply"),
          ("bunny_closed.ply", f"{meshes}/bunny_closed.ply"),
          ("bunny_closed.ply, Taubin 10", f"{work}/bunny_closed_taubin10.ply")]
if not os.path.exists(second[-1][1]):
    subprocess.run([meshdiff, "smooth", second[-2][1], second[-1][1], "--method", "taubin", "--iterations", "10",
                    "--no-distance"], check=True, stdout=subprocess.DEVNULL)
torus = f"{work}/torus-irregular_vertices_16000.ply"
second.append(("torus-irregular 16000", torus))
for a in ("0.002", "0.01", "0.05"):
    noisy = f"{work}/torus-irregular_vertices_16000_noise_{a}.ply"
    if not os.path.exists(noisy):
        subprocess.run([meshdiff, "noise", torus, noisy, "--amplitude", a], check=True, stdout=subprocess.DEVNULL)
    second.append((f"torus-irregular 16000, noise {a}", noisy))

real_rows = []
for label, mesh in second:
    stem = os.path.splitext(os.path.basename(mesh))[0]
    vd, jet, faces, scale = profile(mesh, "jet", stem)
    cg = run_cgal(vd)
    ids = [i for i in interior(len(jet), faces) if math.isfinite(jet[i]) and math.isfinite(cg[i])]
    n = len(ids)
    rms_diff = math.sqrt(sum((jet[i] - cg[i]) ** 2 for i in ids) / n)
    rms_h = math.sqrt(sum(jet[i] ** 2 for i in ids) / n)
    ma, mb = sum(jet[i] for i in ids) / n, sum(cg[i] for i in ids) / n
    cov = sum((jet[i] - ma) * (cg[i] - mb) for i in ids)
    corr = cov / math.sqrt(sum((jet[i] - ma) ** 2 for i in ids) * sum((cg[i] - mb) ** 2 for i in ids))
    d = sorted(abs(jet[i] - cg[i]) for i in ids)
    rr = {"mesh": label, "vertices": len(jet), "interior": n, "scale": scale, "rms_H_jet": rms_h,
          "rms_H_cgal": math.sqrt(sum(cg[i] ** 2 for i in ids) / n), "rms_jet_cgal": rms_diff,
          "relative": rms_diff / rms_h, "median_abs_jet_cgal": d[n // 2], "max_abs_jet_cgal": d[-1],
          "correlation": corr}
    real_rows.append(rr)
    print(f"{rr['mesh']}: RMS H {rms_h:.4g}, RMS |jet-cgal| {rms_diff:.4g} ({rr['relative']:.3f}), "
          f"correlation {corr:.4f}", flush=True)

with open(f"{out}/cgal_jet.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=["kind"] + list(rows[0]) + [k for k in real_rows[0] if k not in rows[0]])
    w.writeheader()
    for r in rows:
        w.writerow({"kind": "analytic", **r})
    for r in real_rows:
        w.writerow({"kind": "real", **r})


def order(r, key):
    prev = [p for p in rows if p["mesh"] == r["mesh"] and p["vertices"] < r["vertices"]]
    if not prev:
        return ""
    p = prev[-1]
    # h ~ vertices^(-1/2): the order in h per step is log(e_prev / e) / log(sqrt(n / n_prev)).
    return f" ({math.log(p[key] / r[key]) / math.log(math.sqrt(r['vertices'] / p['vertices'])):.1f})"


with open(f"{out}/cgal_jet.md", "w") as f:
    f.write("H on the scaled mesh (mean vertex distance 1 from the centroid); RMS / max of |difference| over the "
            "vertices on no boundary edge (closed meshes: all); in parentheses the order in h = "
            "vertices^(-1/2) from the row above (RMS).\n\n")
    f.write("| mesh | vertices | RMS exact H | jet - exact | CGAL - exact | jet - CGAL | goldfeather - exact |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for r in rows:
        cells = [f"{r[k + '_rms']:.3g}{order(r, k + '_rms')} / {r[k + '_max']:.3g}"
                 for k in ("jet_exact", "cgal_exact", "jet_cgal", "goldfeather_exact")]
        f.write(f"| {r['mesh']} | {r['vertices']} | {r['rms_exact_H']:.3g} | " + " | ".join(cells) + " |\n")
    nan = sum(r[k] for r in rows for k in r if k.endswith("_nan"))
    f.write(f"\nVertices without an estimate (left out above): {nan}.\n\n")
    f.write("Without exact H (same vertices; noise: uniform in [-A, A) mean edge lengths along the vertex normals, "
            "`meshdiff noise`):\n\n")
    f.write("| mesh | vertices | used | RMS H jet | RMS H CGAL | RMS jet - CGAL | relative to RMS H jet | median abs | "
            "max abs | correlation |\n|---|---|---|---|---|---|---|---|---|---|\n")
    for r in real_rows:
        f.write(f"| {r['mesh']} | {r['vertices']} | {r['interior']} | {r['rms_H_jet']:.4g} | {r['rms_H_cgal']:.4g} | "
                f"{r['rms_jet_cgal']:.4g} | "
                f"{r['relative']:.3f} | {r['median_abs_jet_cgal']:.3g} | {r['max_abs_jet_cgal']:.3g} | "
                f"{r['correlation']:.4f} |\n")
PY
