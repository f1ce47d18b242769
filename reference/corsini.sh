#!/usr/bin/env bash
# Paper Fig. 1e,f: Corsini et al.'s multi-scale roughness (METHOD.md section 6a, `profile --measure
# corsini`) of the noisy sphere of Fig. 1a and of the bunny, beside the paper's sigma_L: does Corsini's
# measure give the noisy sphere global > local, as the paper says? Writes reference/out/10_corsini/.
#
#   reference/corsini.sh            # from the repository root
#   MESHDIFF=build/meshdiff MESHES=../shared/data/meshes reference/corsini.sh
#
# Inputs as studies.sh section 1 and 2: geodesic sphere of frequency 20 (4,002 vertices) with uniform
# radial noise of 14% (the paper's Fig. 1a), 2% and 0 (seed 1), and bunny_closed. About 30 s on 2 cores.
set -euo pipefail

MESHDIFF=${MESHDIFF:-build/meshdiff}
MESHES=${MESHES:-../shared/data/meshes}
MESHDIFF=$(cd "$(dirname "$MESHDIFF")" && pwd)/$(basename "$MESHDIFF")
MESHES=$(cd "$MESHES" && pwd)
REF=$(cd "$(dirname "$0")" && pwd)
OUT=$REF/out
WORK=$OUT/work
d=$OUT/10_corsini
PYNUM=${PYNUM:-/usr/bin/python3}
[[ -x $MESHDIFF ]] || { echo "corsini.sh: no meshdiff binary at $MESHDIFF (set MESHDIFF)" >&2; exit 2; }
[[ -f $MESHES/bunny_closed.ply ]] || { echo "corsini.sh: no meshes in $MESHES (set MESHES)" >&2; exit 2; }
md() { "$MESHDIFF" "$@"; }
rm -rf "$d"
mkdir -p "$d" "$WORK"
start=$SECONDS

inputs=()
for n in 0 0.02 0.14; do
    md generate noisy-sphere "$WORK/c10_sphere_noise_$n.ply" --frequency 20 --noise "$n" --seed 1 > /dev/null
    inputs+=("sphere_noise_$n=$WORK/c10_sphere_noise_$n.ply")
done
inputs+=("bunny_closed=$MESHES/bunny_closed.ply")
names=()
for item in "${inputs[@]}"; do
    name=${item%%=*}
    mesh=${item#*=}
    md profile "$mesh" --measure corsini --levels 1-20 --json "$d/${name}_corsini.json" > /dev/null
    md profile "$mesh" --measure corsini --levels 1-20 --unbiased-variance --json "$d/${name}_corsini_unbiased.json" > /dev/null
    md profile "$mesh" --levels 1-20 --curvature goldfeather --json "$d/${name}_sigma.json" > /dev/null
    names+=("$name=$d/$name")
done
# The comparison score R(M, M') of the noisy spheres against the clean one.
for n in 0.02 0.14; do
    md compare "$WORK/c10_sphere_noise_0.ply" "$WORK/c10_sphere_noise_$n.ply" --measure corsini --levels 1-20 \
        --no-distance --json "$d/sphere_clean_vs_noise_${n}_corsini.json" > /dev/null
done

# One table: per mesh, R_1, R_5, R_20, R_G and R_L / R_G, for both variances; sigma likewise.
python3 - "$d" "${names[@]}" > "$d/corsini.csv" <<'PY'
import json, sys
d = sys.argv[1]
print("mesh,measure,L1,L2,L5,L10,L20,global,L1/global,L20/global,multiscale")
for item in sys.argv[2:]:
    name, stem = item.split("=", 1)
    for kind in ("corsini", "corsini_unbiased", "sigma"):
        j = json.load(open(f"{stem}_{kind}.json"))
        if kind == "sigma":
            lv, v, g, ms = j["levels"], j["sigma"], j["sigma_global"], ""
        else:
            c = j["corsini"]
            lv, v, g, ms = c["levels"], c["roughness"], c["roughness_global"], f"{c['multiscale']:.6g}"
        at = dict(zip(lv, v))
        print(",".join([name, kind] + [f"{at[L]:.6g}" for L in (1, 2, 5, 10, 20)] + [f"{g:.6g}", f"{at[1] / g:.4f}",
                        f"{at[20] / g:.4f}", ms]))
PY
"$PYNUM" "$REF/plot.py" corsini "$d/corsini.png" "${names[@]}" > /dev/null
echo "corsini.sh: $((SECONDS - start)) s, $(md --version | head -1), $(date -u +%Y-%m-%d)" > "$d/timing.txt"
cat "$d/corsini.csv"
