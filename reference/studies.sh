#!/usr/bin/env bash
# Regenerate the reference studies of the paper (Kushunapally, Razdan, Bridges 2007) with
# meshdiff's own commands: data (JSON from meshdiff, CSV from reference/json2csv.py) and
# gnuplot plots under reference/out/. See reference/README.md.
#
#   reference/studies.sh            # from the repository root
#   MESHDIFF=build/meshdiff MESHES=../shared/data/meshes reference/studies.sh
#
# MESHDIFF and MESHES are taken relative to the current directory. Needs bash, python3
# (standard library) and gnuplot. Large intermediate meshes go to reference/out/work/
# (not committed). A few minutes on 2 cores.
set -euo pipefail

MESHDIFF=${MESHDIFF:-build/meshdiff}
MESHES=${MESHES:-../shared/data/meshes}
MESHDIFF=$(cd "$(dirname "$MESHDIFF")" && pwd)/$(basename "$MESHDIFF")
MESHES=$(cd "$MESHES" && pwd)
REF=$(cd "$(dirname "$0")" && pwd)
OUT=$REF/out
WORK=$OUT/work
[[ -x $MESHDIFF ]] || { echo "studies.sh: no meshdiff binary at $MESHDIFF (set MESHDIFF)" >&2; exit 2; }
[[ -f $MESHES/bunny_closed.ply ]] || { echo "studies.sh: no meshes in $MESHES (set MESHES)" >&2; exit 2; }
command -v gnuplot > /dev/null || { echo "studies.sh: gnuplot not found" >&2; exit 2; }

md() { "$MESHDIFF" "$@"; }
PY="python3"
J2C="$PY $REF/json2csv.py"
PLOTP=$REF/plot_profiles.sh
PLOTS=$REF/plot_smoothing.sh
PLY="$PY $REF/plytool.py"

# The profile of the exact curvature beside the estimated one, when this meshdiff has it.
EXACT=()
if md profile --help 2>&1 | grep -q -- '--exact'; then EXACT=(--exact); fi

FREQ=${FREQ:-20}           # geodesic sphere frequency: 20 = 4,002 vertices, 8,000 triangles (the paper's size)
ITER=${ITER:-50}           # smoothing iterations
SHORT=${SHORT:-20}         # shorter smoothing of the real meshes, compared with the clean originals
NOISE_REAL=${NOISE_REAL:-0.5}   # noise on bunny and igea, times the mean edge length
DSAMPLES=${DSAMPLES:-100000}    # samples per direction of the distance to the input recorded while smoothing

mkdir -p "$OUT" "$WORK"
rm -f "$OUT/timing.txt"
start_all=$SECONDS
section() {
    if [[ -n ${section_name:-} ]]; then
        echo "$section_name: $((SECONDS - section_start)) s" >> "$OUT/timing.txt"
    fi
    section_name=$1
    section_start=$SECONDS
    echo "== $1" >&2
}
# prof NAME MESH OUT.json [options...]: profile at levels 1-20 and global.
prof() {
    local mesh=$1 json=$2
    shift 2
    md profile "$mesh" --levels 1-20 --json "$json" "$@" > /dev/null
}

# ---------------------------------------------------------------------------------------------
section "1 noise and stretching (Fig. 5)"
d=$OUT/1_sphere_noise_stretch
rm -rf "$d"
mkdir -p "$d"
args=()
for n in 0 0.005 0.01 0.02 0.04; do
    md generate noisy-sphere "$WORK/sphere_noise_$n.ply" --frequency "$FREQ" --noise "$n" --seed 1 > /dev/null
    x=()
    [[ $n == 0 ]] && x=("${EXACT[@]}")
    prof "$WORK/sphere_noise_$n.ply" "$d/noise_$n.json" "${x[@]}"
    args+=("noise $n=$d/noise_$n.json")
done
"$PLOTP" "$d/noise.png" "Geodesic sphere (frequency $FREQ, 8000 triangles) with uniform radial noise (fraction of the radius)" "${args[@]}" > /dev/null
LOGY=1 "$PLOTP" "$d/noise_log.png" "Geodesic sphere with radial noise (log scale)" "${args[@]}" > /dev/null
args=()
for a in 1 1.25 1.5 2 3; do
    md generate ellipsoid "$WORK/ellipsoid_$a.ply" --frequency "$FREQ" --axes "$a" 1 1 > /dev/null
    prof "$WORK/ellipsoid_$a.ply" "$d/stretch_$a.json" "${EXACT[@]}"
    args+=("axes $a x 1 x 1=$d/stretch_$a.json")
done
"$PLOTP" "$d/stretch.png" "Geodesic sphere stretched along x to semi-axes (a, 1, 1)" "${args[@]}" > /dev/null

# ---------------------------------------------------------------------------------------------
section "2 real models (Figs. 1, 4)"
d=$OUT/2_models
rm -rf "$d"
mkdir -p "$d"
args=()
for m in bunny_closed igea rocker_arm fandisk; do
    prof "$MESHES/$m.ply" "$d/$m.json"
    args+=("$m=$d/$m.json")
done
"$PLOTP" "$d/models.png" "Roughness profiles of real models (goldfeather)" "${args[@]}" > /dev/null
LOGY=1 "$PLOTP" "$d/models_log.png" "Roughness profiles of real models (goldfeather, log scale)" "${args[@]}" > /dev/null

# ---------------------------------------------------------------------------------------------
section "3 smoothing (Figs. 6-9, 11-12)"
d=$OUT/3_smoothing
rm -rf "$d"
mkdir -p "$d"
md generate noisy-sphere "$WORK/s3_noisy_sphere.ply" --frequency "$FREQ" --noise 0.02 --seed 1 > /dev/null
md generate ellipsoid "$WORK/s3_ellipsoid.ply" --frequency "$FREQ" --axes 1.5 1 1 > /dev/null
# Noise along the vertex normals, uniform in +-NOISE_REAL mean edge lengths (meshdiff noise; plytool.py
# is the stand-in for a meshdiff without that command).
noise() {
    if md noise --help > /dev/null 2>&1; then
        md noise "$1" "$2" --amplitude "$NOISE_REAL" --seed 1 > /dev/null
    else
        $PLY noise "$1" "$2" --amplitude "$NOISE_REAL" --seed 1 > /dev/null
    fi
}
noise "$MESHES/bunny_closed.ply" "$WORK/s3_bunny_noisy.ply"
noise "$MESHES/igea.ply" "$WORK/s3_igea_noisy.ply"
METHODS="laplacian taubin bilaplacian mcf modified-mcf"
for mesh in noisy_sphere ellipsoid bunny_noisy igea_noisy; do
    every=5
    [[ $mesh == igea_noisy ]] && every=10
    args=()
    for m in $METHODS; do
        md smooth "$WORK/s3_$mesh.ply" "$WORK/s3_${mesh}_post_$m.ply" --method "$m" --update post --distance-samples "$DSAMPLES" \
            --iterations "$ITER" --profile-every "$every" --json "$d/${mesh}_post_$m.json" > /dev/null
        args+=("$m=$d/${mesh}_post_$m.json")
    done
    "$PLOTS" "$d/${mesh}_post.png" "$mesh: five methods, post-updating, sigma against iterations" "${args[@]}" > /dev/null
done
# The explicit flows with the paper's fixed step exceed their stability bound on the noisy scans
# (see README): the same flows with adaptive step control, and implicit MCF, beside them.
for mesh in bunny_noisy igea_noisy; do
    every=5
    [[ $mesh == igea_noisy ]] && every=10
    args=()
    for run in mcf modified-mcf mcf-adaptive modified-mcf-adaptive mcf-implicit; do
        opts=(--method "${run%%-adaptive}")
        case $run in
            *-adaptive) opts+=(--step-control adaptive) ;;
            mcf-implicit) opts=(--method mcf --implicit --step 0.1) ;;
        esac
        if [[ $run != mcf && $run != modified-mcf ]]; then
            md smooth "$WORK/s3_$mesh.ply" "$WORK/s3_${mesh}_post_$run.ply" "${opts[@]}" --update post --distance-samples "$DSAMPLES" \
                --iterations "$ITER" --profile-every "$every" --json "$d/${mesh}_post_$run.json" > /dev/null
        fi
        args+=("$run=$d/${mesh}_post_$run.json")
    done
    "$PLOTS" "$d/${mesh}_flows.png" "$mesh: explicit flows with fixed and adaptive steps, and implicit MCF" \
        "${args[@]}" > /dev/null
done
for mesh in noisy_sphere ellipsoid bunny_noisy; do
    args=()
    for m in laplacian mcf modified-mcf; do
        md smooth "$WORK/s3_$mesh.ply" "$WORK/s3_${mesh}_pre_$m.ply" --method "$m" --update pre --distance-samples "$DSAMPLES" \
            --iterations "$ITER" --profile-every 5 --json "$d/${mesh}_pre_$m.json" > /dev/null
        args+=("$m post=$d/${mesh}_post_$m.json" "$m pre=$d/${mesh}_pre_$m.json")
    done
    "$PLOTS" "$d/${mesh}_pre_post.png" "$mesh: pre- against post-updating" "${args[@]}" > /dev/null
done
# Each final result against the clean surface (the noise-free sphere, the ellipsoid itself, the
# original bunny and igea): roughness distance per level and Metro-style surface distance.
clean_of() {
    case $1 in
        noisy_sphere) echo "$WORK/sphere_noise_0.ply" ;;
        ellipsoid) echo "$WORK/s3_ellipsoid.ply" ;;
        bunny_noisy) echo "$MESHES/bunny_closed.ply" ;;
        igea_noisy) echo "$MESHES/igea.ply" ;;
    esac
}
vs_clean() { # MESH RESULT.ply OUT.json
    md compare "$(clean_of "$1")" "$2" --levels 1,5,10,20 --samples 200000 --json "$3" > /dev/null
}
for mesh in noisy_sphere ellipsoid bunny_noisy igea_noisy; do
    vs_clean "$mesh" "$WORK/s3_$mesh.ply" "$d/${mesh}_input_vs_clean.json"
    for u in post pre; do
        for m in $METHODS mcf-adaptive modified-mcf-adaptive mcf-implicit; do
            f=$WORK/s3_${mesh}_${u}_$m.ply
            [[ -f $f ]] && vs_clean "$mesh" "$f" "$d/${mesh}_${u}_${m}_vs_clean.json"
        done
    done
    # Explicit MCF runs away on the noisy real meshes after about 25 iterations (see README), so the
    # real meshes are also compared after SHORT iterations.
    if [[ $mesh == *_noisy ]]; then
        for m in $METHODS; do
            md smooth "$WORK/s3_$mesh.ply" "$WORK/s3_${mesh}_short_$m.ply" --method "$m" --update post \
                --iterations "$SHORT" > /dev/null
            vs_clean "$mesh" "$WORK/s3_${mesh}_short_$m.ply" "$d/${mesh}_short_${m}_vs_clean.json"
        done
        args=("clean=$d/${mesh}_input_vs_clean.json#original" "noisy input=$d/${mesh}_input_vs_clean.json#processed")
        for m in $METHODS; do args+=("$m=$d/${mesh}_short_${m}_vs_clean.json#processed"); done
        LOGY=1 "$PLOTP" "$d/${mesh}_short_profiles.png" \
            "$mesh: profiles after $SHORT post-updating iterations, beside the clean and the noisy mesh" \
            "${args[@]}" > /dev/null
    fi
done

# ---------------------------------------------------------------------------------------------
section "4 regular against irregular sampling (Figs. 13-14)"
d=$OUT/4_sampling
rm -rf "$d"
mkdir -p "$d"
md generate torus "$WORK/torus_regular.ply" --n 96 > /dev/null
md generate torus-irregular "$WORK/torus_irregular.ply" --vertices 2304 --seed 1 > /dev/null
md generate heightfield "$WORK/heightfield_regular.ply" > /dev/null
md generate heightfield-irregular "$WORK/heightfield_irregular.ply" --seed 1 > /dev/null
for s in torus heightfield; do
    for r in regular irregular; do
        prof "$WORK/${s}_$r.ply" "$d/${s}_$r.json" "${EXACT[@]}"
    done
    "$PLOTP" "$d/$s.png" "$s: regular against irregular sampling" \
        "regular=$d/${s}_regular.json" "irregular=$d/${s}_irregular.json" > /dev/null
done
prof "$MESHES/sphere_ico_2562.ply" "$d/sphere_ico_2562.json"
prof "$MESHES/sphere_irregular_3072.ply" "$d/sphere_irregular_3072.json"
"$PLOTP" "$d/sphere.png" "Unit sphere: regular icosphere against irregular sampling" \
    "sphere_ico_2562=$d/sphere_ico_2562.json" "sphere_irregular_3072=$d/sphere_irregular_3072.json" > /dev/null

# ---------------------------------------------------------------------------------------------
section "5 goldfeather against meyer (Fig. 3)"
d=$OUT/5_curvature
rm -rf "$d"
mkdir -p "$d"
md smooth "$WORK/s3_noisy_sphere.ply" "$WORK/s5_smoothed_sphere.ply" --method laplacian --iterations 10 > /dev/null
args=()
for mesh in s5_smoothed_sphere sphere_noise_0; do
    for c in goldfeather quadric meyer; do
        prof "$WORK/$mesh.ply" "$d/${mesh#s5_}_$c.json" --curvature "$c"
    done
done
for c in goldfeather meyer; do
    prof "$MESHES/sphere_irregular_3072.ply" "$d/sphere_irregular_3072_$c.json" --curvature "$c"
done
LOGY=1 "$PLOTP" "$d/curvature.png" "Goldfeather against Meyer curvature on spheres (log scale)" \
    "smoothed noisy sphere, goldfeather=$d/smoothed_sphere_goldfeather.json" \
    "smoothed noisy sphere, quadric=$d/smoothed_sphere_quadric.json" \
    "smoothed noisy sphere, meyer=$d/smoothed_sphere_meyer.json" \
    "clean geodesic sphere, goldfeather=$d/sphere_noise_0_goldfeather.json" \
    "clean geodesic sphere, meyer=$d/sphere_noise_0_meyer.json" \
    "irregular sphere, goldfeather=$d/sphere_irregular_3072_goldfeather.json" \
    "irregular sphere, meyer=$d/sphere_irregular_3072_meyer.json" > /dev/null

# ---------------------------------------------------------------------------------------------
section "6 bumps on a smoothed ellipsoid (Fig. 10)"
d=$OUT/6_bumps
rm -rf "$d"
mkdir -p "$d"
cp "$WORK/s3_ellipsoid.ply" "$WORK/s6_ellipsoid_none.ply"
for m in none $METHODS; do
    f=$WORK/s6_ellipsoid_$m.ply
    [[ $m == none ]] || f=$WORK/s3_ellipsoid_post_$m.ply
    md profile "$f" --levels 1,3,5 --json "$d/ellipsoid_$m.json" --vertex-data "$WORK/s6_vd_$m.ply" > /dev/null
    $PLY valence-stats "$WORK/s6_vd_$m.ply" --prop H --prop D_1 --prop D_3 > "$d/ellipsoid_${m}_by_valence.json"
    $PLY points "$WORK/s6_vd_$m.ply" "$d/ellipsoid_${m}_vertices.dat" --prop H --prop D_3
done
"$REF/plot_bumps.sh" "$d/bumps.png" "$d" none $METHODS > /dev/null

section done
{
    echo "total: $((SECONDS - start_all)) s"
    echo "machine: $(uname -sm), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
    echo "meshdiff: $("$MESHDIFF" --version 2>&1 | head -1); exact profiles: ${EXACT[*]:-not available}"
} >> "$OUT/timing.txt"
$PY "$REF/summarize.py" "$OUT" > "$OUT/summary.md"
echo "studies.sh: done in $((SECONDS - start_all)) s; see $OUT/summary.md" >&2
