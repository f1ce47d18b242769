#!/usr/bin/env bash
# Regenerate the reference studies of the paper (Kushunapally, Razdan, Bridges 2007) with
# meshdiff's own commands: data (JSON from meshdiff, CSV from reference/json2csv.py) and
# gnuplot plots under reference/out/. See reference/README.md.
#
#   reference/studies.sh            # from the repository root
#   MESHDIFF=build/meshdiff MESHES=../shared/data/meshes reference/studies.sh
#
#   SECTIONS="7 8" reference/studies.sh   # only some sections (1-8, see below); the others'
#                                          # outputs stay; sections 5 and 6 need meshes that
#                                          # sections 1 and 3 left in out/work/
#
#   CURVATURE=jet OUT=/tmp/jet-studies SECTIONS="1 2 4 7" reference/studies.sh
#       # the same studies with another estimator, in another folder: CURVATURE (default
#       # goldfeather, the paper's) goes to every profile, compare and smooth that does not
#       # choose its own (sections 5 and 8 compare estimators and keep theirs)
#
# MESHDIFF and MESHES are taken relative to the current directory. Needs bash, python3 (standard
# library) for the data, and a python3 with numpy, scipy and matplotlib for the plots and two
# checks (PYNUM, default /usr/bin/python3). Large intermediate meshes go to reference/out/work/
# (not committed). About 8 minutes on 2 cores.
set -euo pipefail

MESHDIFF=${MESHDIFF:-build/meshdiff}
MESHES=${MESHES:-../shared/data/meshes}
MESHDIFF=$(cd "$(dirname "$MESHDIFF")" && pwd)/$(basename "$MESHDIFF")
MESHES=$(cd "$MESHES" && pwd)
REF=$(cd "$(dirname "$0")" && pwd)
OUT=${OUT:-$REF/out}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
WORK=$OUT/work
CURVATURE=${CURVATURE:-goldfeather}
[[ -x $MESHDIFF ]] || { echo "studies.sh: no meshdiff binary at $MESHDIFF (set MESHDIFF)" >&2; exit 2; }
[[ -f $MESHES/bunny_closed.ply ]] || { echo "studies.sh: no meshes in $MESHES (set MESHES)" >&2; exit 2; }
PYNUM=${PYNUM:-/usr/bin/python3}
"$PYNUM" -c 'import numpy, scipy, matplotlib' 2> /dev/null ||
    { echo "studies.sh: $PYNUM lacks numpy, scipy or matplotlib (set PYNUM)" >&2; exit 2; }
export PYNUM
SECTIONS=${SECTIONS:-1 2 3 4 5 6 7 8}
want() { [[ " $SECTIONS " == *" $1 "* ]]; }
need() {
    local f
    for f in "$@"; do
        [[ -f $f ]] || { echo "studies.sh: $f missing: run the section that makes it first" >&2; exit 2; }
    done
}

# meshdiff; profile, compare and smooth get --curvature $CURVATURE unless the call names its own.
md() {
    case $1 in
    profile | compare | smooth)
        if [[ " $* " != *" --curvature "* ]]; then
            "$MESHDIFF" "$@" --curvature "$CURVATURE"
            return
        fi
        ;;
    esac
    "$MESHDIFF" "$@"
}
PY="python3"
J2C="$PY $REF/json2csv.py"
PLOTP=$REF/plot_profiles.sh
PLOTS=$REF/plot_smoothing.sh
PLY="$PY $REF/plytool.py"
ANA="$PYNUM $REF/analysis.py"
PLOT="$PYNUM $REF/plot.py"

# The profile of the exact curvature beside the estimated one, when this meshdiff has it.
EXACT=()
if md profile --help 2>&1 | grep -q -- '--exact'; then EXACT=(--exact); fi

FREQ=${FREQ:-20}           # geodesic sphere frequency: 20 = 4,002 vertices, 8,000 triangles (the paper's size)
ITER=${ITER:-50}           # smoothing iterations
SHORT=${SHORT:-20}         # shorter smoothing of the real meshes, compared with the clean originals
NOISE_REAL=${NOISE_REAL:-0.5}   # noise on bunny and igea, times the mean edge length
DSAMPLES=${DSAMPLES:-100000}    # samples per direction of the distance to the input recorded while smoothing
METHODS="laplacian taubin bilaplacian mcf modified-mcf"

mkdir -p "$OUT" "$WORK"
start_all=$SECONDS
TIMES=$WORK/timing.new
rm -f "$TIMES"
section() {
    if [[ -n ${section_name:-} ]]; then
        echo "$section_name: $((SECONDS - section_start)) s" >> "$TIMES"
    fi
    section_name=$1
    section_start=$SECONDS
    [[ $1 == done ]] || echo "== $1" >&2
}
# prof NAME MESH OUT.json [options...]: profile at levels 1-20 and global.
prof() {
    local mesh=$1 json=$2
    shift 2
    md profile "$mesh" --levels 1-20 --json "$json" "$@" > /dev/null
}

# ---------------------------------------------------------------------------------------------
if want 1; then
section "1 noise and stretching (Figs. 1a, 5)"
d=$OUT/1_sphere_noise_stretch
rm -rf "$d"
mkdir -p "$d"
args=()
# 0.14 is the noise of the paper's Fig. 1a (14% of the radius); 0-0.04 those of Fig. 5.
for n in 0 0.005 0.01 0.02 0.04 0.14; do
    md generate noisy-sphere "$WORK/sphere_noise_$n.ply" --frequency "$FREQ" --noise "$n" --seed 1 > /dev/null
    x=()
    [[ $n == 0 ]] && x=("${EXACT[@]}")
    prof "$WORK/sphere_noise_$n.ply" "$d/noise_$n.json" "${x[@]}" --vertex-data "$WORK/s1_vd_noise_$n.ply"
    [[ $n == 0.14 ]] || args+=("noise $n=$d/noise_$n.json")
done
"$PLOTP" "$d/noise.png" "Geodesic sphere (frequency $FREQ, 8000 triangles) with uniform radial noise (fraction of the radius)" "${args[@]}" > /dev/null
LOGY=1 "$PLOTP" "$d/noise_log.png" "Geodesic sphere with radial noise (log scale)" "${args[@]}" "noise 0.14 (paper Fig. 1a)=$d/noise_0.14.json" > /dev/null
# What uncorrelated noise in H averaged over a finite ring gives by itself (README, Fig. 1a).
for n in 0.02 0.04 0.14; do
    $ANA ringnoise "$WORK/s1_vd_noise_$n.ply" --levels 1,2,5,10,20 > "$d/ringnoise_$n.json"
done
args=()
for a in 1 1.2 1.25 1.5 2 3; do
    md generate ellipsoid "$WORK/ellipsoid_$a.ply" --frequency "$FREQ" --axes "$a" 1 1 > /dev/null
    prof "$WORK/ellipsoid_$a.ply" "$d/stretch_$a.json" "${EXACT[@]}"
    args+=("axes $a x 1 x 1=$d/stretch_$a.json")
done
"$PLOTP" "$d/stretch.png" "Geodesic sphere stretched along x to semi-axes (a, 1, 1)" "${args[@]}" > /dev/null
fi

# ---------------------------------------------------------------------------------------------
if want 2; then
section "2 real models (Figs. 1b, 4)"
d=$OUT/2_models
rm -rf "$d"
mkdir -p "$d"
args=()
for m in bunny_closed igea rocker_arm fandisk; do
    prof "$MESHES/$m.ply" "$d/$m.json" --vertex-data "$WORK/s2_vd_$m.ply"
    args+=("$m=$d/$m.json")
done
"$PLOTP" "$d/models.png" "Roughness profiles of real models (goldfeather)" "${args[@]}" > /dev/null
LOGY=1 "$PLOTP" "$d/models_log.png" "Roughness profiles of real models (goldfeather, log scale)" "${args[@]}" > /dev/null
# Paper Fig. 4a,b: mean curvature maps of the Venus stand-in (igea) and the Rocker arm.
$PLOT hmap "$d/igea_H.png" "igea (stand-in for the paper's Venus, 134,345 vertices): H" "$WORK/s2_vd_igea.ply" \
    --view 0,0,1 --up 0,1,0 > /dev/null
$PLOT hmap "$d/rocker_arm_H.png" "rocker_arm (10,044 vertices): H" "$WORK/s2_vd_rocker_arm.ply" \
    --view ${ROCKER_VIEW:-1,0,0} --up ${ROCKER_UP:-0,1,0} > /dev/null
fi

# ---------------------------------------------------------------------------------------------
# Extra (not the paper's inputs, see section 7 for those): noise on every smoothing input.
if want 3; then
section "3 smoothing, extra: noisy inputs (Figs. 6-9, 11)"
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
# Each final result against the clean surface (the noise-free sphere, the ellipsoid itself, the
# original bunny and igea): roughness distance per level and Metro-style surface distance.
md generate noisy-sphere "$WORK/s3_sphere_clean.ply" --frequency "$FREQ" --noise 0 > /dev/null
clean_of() {
    case $1 in
        noisy_sphere) echo "$WORK/s3_sphere_clean.ply" ;;
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
done
for mesh in noisy_sphere ellipsoid bunny_noisy igea_noisy; do
    export CLEAN_REF=$d/${mesh}_input_vs_clean.json#original
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
# The explicit flows with the fixed step 0.1 e^2 (our choice; the paper gives no step) exceed their stability
# bound on the noisy scans (see README): the same flows with adaptive step control, and implicit MCF, beside them.
for mesh in bunny_noisy igea_noisy; do
    export CLEAN_REF=$d/${mesh}_input_vs_clean.json#original
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
    export CLEAN_REF=$d/${mesh}_input_vs_clean.json#original
    args=()
    for m in laplacian mcf modified-mcf; do
        md smooth "$WORK/s3_$mesh.ply" "$WORK/s3_${mesh}_pre_$m.ply" --method "$m" --update pre --distance-samples "$DSAMPLES" \
            --iterations "$ITER" --profile-every 5 --json "$d/${mesh}_pre_$m.json" > /dev/null
        args+=("$m post=$d/${mesh}_post_$m.json" "$m pre=$d/${mesh}_pre_$m.json")
    done
    "$PLOTS" "$d/${mesh}_pre_post.png" "$mesh: pre- against post-updating" "${args[@]}" > /dev/null
done
unset CLEAN_REF
for mesh in noisy_sphere ellipsoid bunny_noisy igea_noisy; do
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

fi

# ---------------------------------------------------------------------------------------------
if want 4; then
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
        # The same with the jet fit (issue 28): how much of the irregular excess is estimator noise.
        prof "$WORK/${s}_$r.ply" "$d/${s}_${r}_jet.json" "${EXACT[@]}" --curvature jet
    done
    "$PLOTP" "$d/$s.png" "$s: regular against irregular sampling" \
        "regular=$d/${s}_regular.json" "irregular=$d/${s}_irregular.json" > /dev/null
done
prof "$MESHES/sphere_ico_2562.ply" "$d/sphere_ico_2562.json"
prof "$MESHES/sphere_irregular_3072.ply" "$d/sphere_irregular_3072.json"
prof "$MESHES/sphere_ico_2562.ply" "$d/sphere_ico_2562_jet.json" --curvature jet
prof "$MESHES/sphere_irregular_3072.ply" "$d/sphere_irregular_3072_jet.json" --curvature jet
"$PLOTP" "$d/sphere.png" "Unit sphere: regular icosphere against irregular sampling" \
    "sphere_ico_2562=$d/sphere_ico_2562.json" "sphere_irregular_3072=$d/sphere_irregular_3072.json" > /dev/null
# "Global roughness does not depend on the mesh": one surface, several meshes.
for m in bunny_closed bunny_adaptive bunny sphere_ico_10242; do
    prof "$MESHES/$m.ply" "$d/$m.json"
done
"$PLOTP" "$d/bunny_meshes.png" "The bunny meshed three ways: closed (34,835 v.), adaptive remesh (5,884), open scan (34,834)" \
    "bunny_closed=$d/bunny_closed.json" "bunny_adaptive=$d/bunny_adaptive.json" "bunny (scan)=$d/bunny.json" > /dev/null

fi

# ---------------------------------------------------------------------------------------------
# Estimators on static spheres (the smoothed sphere here is the noisy one of section 3; section 8
# runs Fig. 3 as the paper did).
if want 5; then
need "$WORK/s3_noisy_sphere.ply" "$WORK/sphere_noise_0.ply"
section "5 goldfeather against meyer on static spheres (Fig. 3, extra)"
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

fi

# ---------------------------------------------------------------------------------------------
if want 6; then
need "$WORK/s3_ellipsoid.ply"
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
fi

# ---------------------------------------------------------------------------------------------
# The smoothing studies on the paper's inputs: a geodesic sphere with 4% radial noise, the
# ellipsoid (1.2, 1, 1), the bunny without noise (bunny_closed), the Venus stand-in (igea) with
# 0.004% noise (of the bounding-box diagonal: an assumption, see README) and the Rocker arm.
if want 7; then
section "7 smoothing on the paper's inputs (Figs. 6-12)"
d=$OUT/7_smoothing_paper
rm -rf "$d"
mkdir -p "$d"
md generate noisy-sphere "$WORK/s7_sphere4.ply" --frequency "$FREQ" --noise 0.04 --seed 1 > /dev/null
md generate noisy-sphere "$WORK/s7_sphere_clean.ply" --frequency "$FREQ" --noise 0 > /dev/null
md generate ellipsoid "$WORK/s7_ellipsoid12.ply" --frequency "$FREQ" --axes 1.2 1 1 > /dev/null
md noise "$MESHES/igea.ply" "$WORK/s7_igea.ply" --amplitude 0.00004 --unit diagonal --seed 1 > /dev/null
cp "$MESHES/bunny_closed.ply" "$WORK/s7_bunny.ply"
cp "$MESHES/rocker_arm.ply" "$WORK/s7_rocker_arm.ply"
clean7() {
    case $1 in
        sphere4) echo "$WORK/s7_sphere_clean.ply" ;;
        igea) echo "$MESHES/igea.ply" ;;
        *) echo "$WORK/s7_$1.ply" ;;
    esac
}
MESHES7="sphere4 ellipsoid12 bunny igea rocker_arm"
for mesh in $MESHES7; do
    md compare "$(clean7 $mesh)" "$WORK/s7_$mesh.ply" --levels 1,5,10,20 --samples 200000 \
        --json "$d/${mesh}_input_vs_clean.json" > /dev/null
done
for mesh in $MESHES7; do
    export CLEAN_REF=$d/${mesh}_input_vs_clean.json#original
    every=5
    [[ $mesh == igea ]] && every=10
    updates="post"
    [[ $mesh == sphere4 || $mesh == ellipsoid12 || $mesh == bunny ]] && updates="post pre"
    for u in $updates; do
        methods=$METHODS
        [[ $u == pre ]] && methods="laplacian mcf modified-mcf"
        args=()
        for m in $methods; do
            md smooth "$WORK/s7_$mesh.ply" "$WORK/s7_${mesh}_${u}_$m.ply" --method "$m" --update "$u" \
                --distance-samples "$DSAMPLES" --iterations "$ITER" --profile-every "$every" \
                --json "$d/${mesh}_${u}_$m.json" > /dev/null 2> "$WORK/s7_${mesh}_${u}_$m.log"
            md compare "$(clean7 $mesh)" "$WORK/s7_${mesh}_${u}_$m.ply" --levels 1,5,10,20 --samples 200000 \
                --json "$d/${mesh}_${u}_${m}_vs_clean.json" > /dev/null
            args+=("$m=$d/${mesh}_${u}_$m.json")
        done
        "$PLOTS" "$d/${mesh}_$u.png" "$mesh: five methods, $u-updating, sigma against iterations" "${args[@]}" > /dev/null
    done
    if [[ $updates == "post pre" ]]; then
        args=()
        for m in laplacian mcf modified-mcf; do
            args+=("$m post=$d/${mesh}_post_$m.json" "$m pre=$d/${mesh}_pre_$m.json")
        done
        "$PLOTS" "$d/${mesh}_pre_post.png" "$mesh: pre- (dashed) against post-updating (solid)" "${args[@]}" > /dev/null
    fi
    # Paper Fig. 12 (and 11): the profiles after smoothing beside the clean mesh.
    args=("clean=$d/${mesh}_input_vs_clean.json#original")
    [[ $mesh == sphere4 || $mesh == igea ]] && args+=("noisy input=$d/${mesh}_input_vs_clean.json#processed")
    for m in $METHODS; do args+=("$m=$d/${mesh}_post_${m}_vs_clean.json#processed"); done
    LOGY=1 "$PLOTP" "$d/${mesh}_profiles.png" "$mesh: profiles after $ITER post-updating iterations" \
        "${args[@]}" > /dev/null
done
unset CLEAN_REF
# Fig. 10 on the paper's ellipsoid (1.2, 1, 1).
for m in none $METHODS; do
    f=$WORK/s7_ellipsoid12_post_$m.ply
    [[ $m == none ]] && f=$WORK/s7_ellipsoid12.ply
    md profile "$f" --levels 1,3,5 --json "$d/bumps_ellipsoid_$m.json" --vertex-data "$WORK/s7_vd_$m.ply" > /dev/null
    $PLY valence-stats "$WORK/s7_vd_$m.ply" --prop H --prop D_1 --prop D_3 > "$d/ellipsoid_${m}_by_valence.json"
    $PLY points "$WORK/s7_vd_$m.ply" "$d/ellipsoid_${m}_vertices.dat" --prop H --prop D_3
done
CB=0.15 "$REF/plot_bumps.sh" "$d/bumps.png" "$d" none $METHODS > /dev/null
fi

# ---------------------------------------------------------------------------------------------
# Paper Fig. 3 as the paper ran it: a clean sphere smoothed with pre-updating Laplacian and MCF,
# sigma against iterations with Meyer and with the cubic fit. Beside each: the radius spread of the
# smoothed mesh, the profile of r_mean/r_i (the sphere through each vertex), and both estimators on
# the same vertices projected radially onto the sphere of the mean radius (exact H constant: all
# they report there is estimation error of that sampling).
if want 8; then
section "8 Fig. 3 as the paper ran it"
d=$OUT/8_fig3
rm -rf "$d"
mkdir -p "$d"
md generate noisy-sphere "$WORK/s8_sphere.ply" --frequency "$FREQ" --noise 0 > /dev/null
for m in laplacian mcf; do
    for c in goldfeather meyer; do
        md smooth "$WORK/s8_sphere.ply" "$WORK/s8_${m}_$c.ply" --method "$m" --update pre --iterations "$ITER" \
            --profile-every 5 --curvature "$c" --no-distance --json "$d/${m}_pre_$c.json" > /dev/null 2>&1
    done
    for ((k = 0; k <= ITER; k += 5)); do
        md smooth "$WORK/s8_sphere.ply" "$WORK/s8_${m}_$k.ply" --method "$m" --update pre --iterations "$k" > /dev/null 2>&1
        $ANA sphere-geometry "$WORK/s8_${m}_$k.ply" "$WORK/s8_${m}_${k}_proj.ply" > "$d/${m}_${k}_geometry.json"
        for c in goldfeather meyer; do
            md profile "$WORK/s8_${m}_${k}_proj.ply" --levels 1,5,10,20 --curvature "$c" \
                --json "$d/${m}_${k}_projected_$c.json" > /dev/null 2>&1
        done
    done
done
$ANA fig3 "$d" "$ITER" > "$d/fig3.json"
$PLOT fig3 "$d/fig3.png" "$d" > /dev/null
fi

section done
# timing.txt: one line per section (a partial run replaces only its sections' lines).
{
    if [[ -f $OUT/timing.txt && $SECTIONS != "1 2 3 4 5 6 7 8" ]]; then
        grep -E '^[0-9] ' "$OUT/timing.txt" | while IFS= read -r line; do
            grep -q "^${line%% *} " "$TIMES" || echo "$line"
        done
    fi
    cat "$TIMES"
} | sort -n > "$WORK/timing.merged"
{
    cat "$WORK/timing.merged"
    echo "total of the sections above: $(awk '{ t += $(NF - 1) } END { print t }' "$WORK/timing.merged") s"
    echo "last run: sections $SECTIONS, $((SECONDS - start_all)) s, $(date -u +%Y-%m-%d)"
    echo "machine: $(uname -sm), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
    echo "meshdiff: $("$MESHDIFF" --version 2>&1 | head -1); exact profiles: ${EXACT[*]:-not available}; curvature: $CURVATURE"
} > "$OUT/timing.txt"
$PY "$REF/summarize.py" "$OUT" > "$OUT/summary.md"
echo "studies.sh: done in $((SECONDS - start_all)) s; see $OUT/summary.md" >&2
