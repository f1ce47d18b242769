#!/usr/bin/env bash
# Resolution study of issue 15: ring levels against metric levels (--radii) on the same surface at several
# resolutions, and on decimations. Writes small JSON/CSV files to reference/out/7_radii/ and the meshes to
# reference/out/work/radii/ (git-ignored). About 5 minutes on 2 cores.
#
#   reference/radii.sh [BINARY]        (default build/meshdiff)
#
# Needs OpenMesh's decimater (Debian/Ubuntu: libopenmesh-apps, /usr/bin/OpenMesh-commandlineDecimater: quadric
# priority with aspect-ratio and normal-flip constraints, "-M Q -M AR:5 -M NF:30 -n FRACTION"; the plain quadric
# "-M Q" leaves slivers whose curvature fits explode, 0.1% of the vertices then make 98% of sigma^2 at every level
# and radius, see reference/README.md) and the meshes of ../shared/data/meshes beside the repository
# (PROVENANCE.md there).
#  1. torus: irregular tori R = 1, r = 0.25 of 10K and 160K vertices (meshdiff generate torus-irregular), profiles of
#     the estimated H and of the exact H (--exact), rings 1-20 and radii RADII.
#  2. bunny: bunny.ply (35K vertices) against its constrained quadric decimations to 50%, 25%, 10% and Stanford's lower
#     reconstructions bunny_res2/3/4; igea.ply (134K) against its decimations to 50%, 25%, 10%.
#     meshdiff ORIGINAL PROCESSED --no-distance --radii RADII: d_L and d_r with the relative change.
#  3. summary.csv: one row per (pair, kind, level or radius): sigma of each side, relative change, d.
#  4. decimation.png (gnuplot, if installed) and decimation.dat: relative change against the share of vertices kept.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=$(realpath "${1:-$here/../build/meshdiff}")
shared=$(realpath "$here/../../shared/data/meshes")
out=$here/out/7_radii
work=$here/out/work/radii
decimater=${DECIMATER:-OpenMesh-commandlineDecimater}
radii=${RADII:-default}
mkdir -p "$out" "$work"

# 1. tori
for n in 10000 160000; do
    [[ -f $work/torus_$n.ply ]] || "$bin" generate torus-irregular "$work/torus_$n.ply" --vertices $n --seed 1 > /dev/null
    "$bin" profile "$work/torus_$n.ply" --exact --radii "$radii" --curvature goldfeather --json "$out/torus_$n.json" > /dev/null
    echo "torus $n done"
done

# 2. decimations
decimate() {  # SRC FRACTION OUT
    [[ -f $3 ]] || "$decimater" -M Q -M AR:5 -M NF:30 -n "$2" -i "$1" -o "$3" > /dev/null 2>&1
}
for m in bunny igea; do
    for f in 50 25 10; do decimate "$shared/$m.ply" "0.$f" "$work/${m}_$f.ply"; done
done
pairs=()
for m in bunny igea; do
    for f in 50 25 10; do pairs+=("$m:$shared/$m.ply:$work/${m}_$f.ply:${m}_$f"); done
done
for r in res2 res3 res4_ascii; do pairs+=("bunny:$shared/bunny.ply:$shared/bunny_$r.ply:bunny_$r"); done
for p in "${pairs[@]}"; do
    IFS=: read -r _ a b name <<< "$p"
    "$bin" "$a" "$b" --no-distance --radii "$radii" --curvature goldfeather --json "$out/compare_$name.json" > /dev/null
    echo "$name done"
done

# 3. summary
python3 - "$out" <<'PY'
import csv, glob, json, os, sys
out = sys.argv[1]
rows = []
for path in sorted(glob.glob(os.path.join(out, "compare_*.json"))):
    j = json.load(open(path))
    name = os.path.basename(path)[8:-5]
    o, p, d = j["original"], j["processed"], j["roughness_distance"]
    for kind, keys, sa, sb, dist, rel in (
            ("ring", d["levels"], o["sigma"], p["sigma"], d["distance"], d["relative_change"]),
            ("radius", d["radii"], o["sigma_radii"], p["sigma_radii"], d["distance_radii"], d["relative_change_radii"])):
        for i, k in enumerate(keys):
            rows.append([name, p["mesh"]["vertices"], kind, k, sa[i], sb[i], rel[i], dist[i]])
for path in sorted(glob.glob(os.path.join(out, "torus_*.json"))):
    j = json.load(open(path))
    name = os.path.basename(path)[:-5]
    for kind, keys, s, se in (("ring", j["levels"], j["sigma"], j["exact"]["sigma"]),
                              ("radius", j["radii"], j["sigma_radii"], j["exact"]["sigma_radii"])):
        for i, k in enumerate(keys):
            rows.append([name, j["mesh"]["vertices"], kind, k, s[i], se[i], "", ""])
with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["pair", "vertices_processed", "kind", "level_or_radius", "sigma_original", "sigma_processed",
                "relative_change", "d"])
    w.writerows(rows)
print("rows:", len(rows))
PY
echo "wrote $out/summary.csv (torus rows: sigma_original = estimated H, sigma_processed = exact H)"

# 4. plot: relative change of sigma against the share of vertices kept, ring 1 / ring 20 / radius 0.1 / radius 0.2
python3 - "$out" > "$out/decimation.dat" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "summary.csv"))))
get = lambda p, kind, k: next(float(r["relative_change"]) for r in rows
                              if r["pair"] == p and r["kind"] == kind and r["level_or_radius"] == k)
for m in ("igea", "bunny"):
    print(f"# {m}: kept ring1 ring20 r0.1 r0.2")
    for f in (50, 25, 10):
        p = f"{m}_{f}"
        print(f, *(100 * get(p, *c) for c in (("ring", "1"), ("ring", "20"), ("radius", "0.1"), ("radius", "0.2"))))
    print("\n")
PY
if command -v gnuplot > /dev/null; then
    term=pngcairo
    gnuplot -e "set terminal" 2>&1 | grep -qw pngcairo || term=png
    gnuplot <<GP
set terminal $term size 900,460
set output "$out/decimation.png"
set multiplot layout 1,2 title "relative change of sigma, decimation vs original (reference/radii.sh)"
set xlabel "vertices kept (%)"; set ylabel "(sigma' - sigma) / sigma (%)"; set xrange [55:5]; set grid
set key below horizontal
do for [i=0:1] {
  set title (i == 0 ? "igea (134K)" : "bunny (35K)")
  plot "$out/decimation.dat" index i u 1:2 w lp t "ring 1", "" index i u 1:3 w lp t "ring 20", \
       "" index i u 1:4 w lp t "radius 0.1", "" index i u 1:5 w lp t "radius 0.2", 0 w l lc rgb "gray" notitle
}
unset multiplot
GP
    echo "wrote $out/decimation.png"
fi
