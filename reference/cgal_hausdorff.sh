#!/usr/bin/env bash
# Cross-check of meshdiff's certified Hausdorff distance against CGAL's
# bounded_error_Hausdorff_distance (issue 10), and the speed of both at a
# tolerance of 1e-6 of the original's bounding-box diagonal.
#
#   MESHDIFF=build/meshdiff BENCH=build/meshdiff_bench_hausdorff MESHES=../shared/data/meshes \
#       reference/cgal_hausdorff.sh
#
# Needs libcgal-dev (Debian, header-only; also libgmp-dev, libmpfr-dev), g++,
# OpenMesh-commandlineDecimater (libopenmesh-apps) for the igea decimation,
# and python3. Writes out/9_hausdorff/cgal.csv and cgal.md; the CGAL program
# and the decimated igea go to out/work/ (git-ignored).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${MESHDIFF:-build/meshdiff}
bench=${BENCH:-build/meshdiff_bench_hausdorff}
meshes=${MESHES:-../shared/data/meshes}
out=reference/out/9_hausdorff
work=reference/out/work
mkdir -p "$out" "$work"
if [[ ! -x $work/cgal_hausdorff || reference/cgal/cgal_hausdorff.cpp -nt $work/cgal_hausdorff ]]; then
    echo "building $work/cgal_hausdorff (CGAL $(dpkg-query -W -f='${Version}' libcgal-dev 2>/dev/null || echo '?'))"
    g++ -std=c++17 -O2 -DNDEBUG -DCGAL_NDEBUG -o "$work/cgal_hausdorff" reference/cgal/cgal_hausdorff.cpp -lgmp -lmpfr
fi
if [[ ! -s $work/igea_dec10.ply ]]; then
    OpenMesh-commandlineDecimater -M Q -n 0.1 -i "$meshes/igea.ply" -o "$work/igea_dec10.ply" > /dev/null
fi
python3 - "$bin" "$bench" "$work/cgal_hausdorff" "$out" \
    tests/data/bunny_res3.ply tests/data/bunny_res4_ascii.ply \
    tests/data/sphere_ico_2562.ply tests/data/sphere_irregular_3072.ply \
    tests/data/sphere_ico_2562.ply tests/data/ellipsoid_150_100_100.ply \
    tests/data/hemisphere.ply tests/data/sphere_ico_2562.ply \
    "$meshes/igea.ply" "$work/igea_dec10.ply" <<'PY'
import csv, json, re, subprocess, sys, time
meshdiff, bench, cgal, out = sys.argv[1:5]
files = sys.argv[5:]
pairs = list(zip(files[0::2], files[1::2]))
rows = []
for a, b in pairs:
    # The diagonal of the original's box, from a sampled-only run.
    j = json.loads(subprocess.run([meshdiff, a, b, "--no-roughness", "--hausdorff", "sampled", "--json", "-"],
                                  check=True, capture_output=True, text=True).stdout)
    diag = j["surface_distance"]["diagonal"]
    tol = 1e-6 * diag
    j = json.loads(subprocess.run([meshdiff, a, b, "--no-roughness", "--hausdorff-abs-tolerance", repr(tol), "--json",
                                   "-"], check=True, capture_output=True, text=True).stdout)
    c = subprocess.run([cgal, a, b, repr(tol)], check=True, capture_output=True, text=True).stdout.split("\n")
    cg = {line.split()[0]: (float(line.split()[1]), float(line.split()[2])) for line in c if line.strip()}
    # Both directions certified alone (index build included), median of 3.
    t = subprocess.run([bench, "--runs", "3", "--diag-tolerance", "1e-6", a, b], check=True, capture_output=True,
                       text=True).stdout
    alone = float(re.search(r"certified alone\s+([0-9.]+) s", t).group(1))
    for d in ("forward", "backward"):
        h = j["surface_distance"][d]["hausdorff"]
        value, seconds = cg[d]
        overlap = h["lower"] <= value + tol and value - tol <= h["upper"]
        rows.append({"original": a, "processed": b, "direction": d, "tolerance": tol,
                     "meshdiff_lower": h["lower"], "meshdiff_upper": h["upper"], "certified": h["certified"],
                     "sampled_max": j["surface_distance"][d]["max"], "cgal": value, "overlap": overlap,
                     "cgal_seconds": seconds, "meshdiff_seconds_both_directions": alone})
        print(f"{a} -> {b} {d}: meshdiff [{h['lower']:.10g}, {h['upper']:.10g}] cgal {value:.10g} +- {tol:.3g} "
              f"overlap {overlap}; cgal {seconds:.3f} s, meshdiff both directions {alone:.3f} s", flush=True)
with open(f"{out}/cgal.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
with open(f"{out}/cgal.md", "w") as f:
    f.write("| pair | direction | meshdiff [lower, upper] | CGAL (+- tol) | sampled max | overlap | CGAL s | meshdiff s (both) |\n")
    f.write("|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        name = f"{r['original'].split('/')[-1]} vs {r['processed'].split('/')[-1]}"
        f.write(f"| {name} | {r['direction']} | [{r['meshdiff_lower']:.10g}, {r['meshdiff_upper']:.10g}] | "
                f"{r['cgal']:.10g} (+- {r['tolerance']:.3g}) | {r['sampled_max']:.10g} | {r['overlap']} | "
                f"{r['cgal_seconds']:.3f} | {r['meshdiff_seconds_both_directions']:.3f} |\n")
    for a, b in pairs:
        both = [r for r in rows if r["original"] == a and r["processed"] == b]
        cg = sum(r["cgal_seconds"] for r in both)
        f.write(f"\n{a.split('/')[-1]} vs {b.split('/')[-1]}: CGAL {cg:.3f} s for both directions, meshdiff "
                f"{both[0]['meshdiff_seconds_both_directions']:.3f} s, ratio {cg / both[0]['meshdiff_seconds_both_directions']:.1f}\n")
sys.exit(0 if all(r["overlap"] and r["certified"] for r in rows) else 1)
PY
