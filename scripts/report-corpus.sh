#!/usr/bin/env bash
# Writes every kind of report and output file meshdiff makes, on the bundled meshes, into OUTDIR: the corpus
# that a refactoring must leave bitwise unchanged. Run it with the binary before and after, then compare:
#
#   scripts/report-corpus.sh OLD_BINARY /tmp/corpus-old
#   scripts/report-corpus.sh build/meshdiff /tmp/corpus-new
#   scripts/report-corpus.sh --compare /tmp/corpus-old /tmp/corpus-new
#
# --compare lists the files that differ (cmp), after replacing the version string "meshdiff X.Y.Z" and the
# JSON "meshdiff_version" of each side by a placeholder (and the batch records' "elapsed_seconds"), and exits 1
# if any differs or is missing.
# About a minute on 2 cores.
set -euo pipefail

if [[ "${1:-}" == "--compare" ]]; then
    old=$2 new=$3 bad=0 n=0
    norm() { sed -E 's/meshdiff [0-9]+\.[0-9]+\.[0-9]+/meshdiff VERSION/g; s/"meshdiff_version": ?"[^"]*"/"meshdiff_version":"VERSION"/g; s/"elapsed_seconds": ?[0-9.e+-]+/"elapsed_seconds":T/g' "$1"; }
    while IFS= read -r f; do
        n=$((n + 1))
        if [[ ! -f "$new/$f" ]]; then
            echo "missing: $f"
            bad=1
        elif ! cmp -s <(norm "$old/$f") <(norm "$new/$f"); then
            echo "differs: $f"
            bad=1
        fi
    done < <(cd "$old" && find . -type f | sort)
    echo "report-corpus: $n files compared, $([[ $bad == 0 ]] && echo "all identical" || echo "some differ")"
    exit $bad
fi

bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$2
data=$(cd "$(dirname "$0")/../tests/data" && pwd)
rm -rf "$out"
mkdir -p "$out"
cd "$out"
# run NAME ARGS...: stdout, stderr and the exit code of one command.
run() {
    local name=$1
    shift
    set +e
    "$bin" "$@" > "$name.stdout" 2> "$name.stderr"
    echo $? > "$name.exit"
    set -e
}

for m in fandisk bunny_res3 hemisphere torus_R1_r025 ellipsoid_150_100_100; do
    run "profile_$m" profile "$data/$m.ply" --json "profile_$m.json"
done
run profile_teapot profile "$data/teapot.obj" --json profile_teapot.json
run profile_meyer profile "$data/sphere_irregular_3072.ply" --curvature meyer --json profile_meyer.json
run profile_quadric profile "$data/sphere_irregular_3072.ply" --curvature quadric --weighting inverse-square \
    --levels 1,3,7 --json profile_quadric.json
run profile_noglobal profile "$data/fandisk.ply" --no-global --levels 1-5 --json -
run profile_radii profile "$data/bunny_res3.ply" --radii default --json profile_radii.json
run profile_radii_only profile "$data/fandisk.ply" --levels '' --radii 0.05,0.1,0.3 --json profile_radii_only.json
run profile_vertexdata profile "$data/hemisphere.ply" --levels 1,2 --vertex-data vertexdata.ply
run profile_vertexdata_range profile "$data/fandisk.ply" --levels 2 --vertex-data vertexdata_range.ply \
    --color-range 3

run compare_default "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --json compare_default.json
run compare_mc "$data/sphere_ico_2562.ply" "$data/sphere_irregular_3072.ply" --face-sampling montecarlo --seed 7 \
    --levels 1,2,5 --json compare_mc.json
run compare_density "$data/torus_R1_r025.ply" "$data/torus_R1_r025.ply" --density 2000 --no-roughness \
    --json compare_density.json
run compare_noedges "$data/fandisk.ply" "$data/hemisphere.ply" --no-edge-samples --no-vertex-samples -n 5000 \
    --no-roughness --json compare_noedges.json
run compare_nodist "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-distance --curvature meyer \
    --json compare_nodist.json
run compare_radii "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1,4 --radii default \
    --json compare_radii.json
run compare_stdout "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1,4 --json -
run compare_map "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1 --distance-map map.ply
run compare_map_range "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness \
    --distance-map map_range.ply --color-range 0 0.001

printf 'original,processed,id\n%s,%s,bunny\n%s,%s,broken\n' "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" \
    "$data/fandisk.ply" "$out/missing.ply" > "$out.pairs.csv"
run batch batch "$out.pairs.csv" --out batch.jsonl --levels 1,2 -n 20000

for shape in sphere noisy-sphere ellipsoid torus torus-irregular heightfield heightfield-irregular plane; do
    run "generate_$shape" generate "$shape" "gen_$shape.ply"
done
run generate_geodesic generate noisy-sphere gen_geodesic.ply --frequency 6 --noise 0.03 --seed 3
run generate_obj generate torus gen_torus.obj --n 24
run profile_exact profile gen_torus-irregular.ply --exact --levels 1,2,5 --json profile_exact.json

for method in laplacian taubin bilaplacian mcf modified-mcf; do
    for update in post pre; do
        run "smooth_${method}_$update" smooth "$data/hemisphere.ply" "smooth_${method}_$update.ply" \
            --method "$method" --update "$update" --iterations 4 --profile-every 2 --levels 1,3 \
            --distance-samples 5000 --json "smooth_${method}_$update.json"
    done
done
run smooth_implicit smooth gen_noisy-sphere.ply smooth_implicit.ply --method mcf --implicit --step 5 \
    --iterations 3 --json smooth_implicit.json --no-distance
run smooth_adaptive smooth gen_noisy-sphere.ply smooth_adaptive.off --method modified-mcf --step 2 \
    --step-control adaptive --iterations 3 --json smooth_adaptive.json
run smooth_plain smooth "$data/bunny_res3.ply" smooth_plain.obj --iterations 2
run smooth_diverge smooth gen_noisy-sphere.ply smooth_diverge.ply --method mcf --step 9 --iterations 3

for dir in normal random; do
    for dist in uniform gaussian; do
        run "noise_${dir}_$dist" noise "$data/hemisphere.ply" "noise_${dir}_$dist.ply" --amplitude 0.3 \
            --direction "$dir" --distribution "$dist" --seed 5
    done
done
run noise_diag noise "$data/fandisk.ply" noise_diag.stl --amplitude 0.001 --unit diagonal --move-boundary
run noise_abs noise "$data/fandisk.ply" noise_abs.off --amplitude 0.01 --unit absolute

# Errors: the exit code and the message.
run err_missing profile "$out/missing.ply"
run err_levels profile "$data/fandisk.ply" --levels 0
run err_k "$data/fandisk.ply" "$data/fandisk.ply" -k 0
run err_method smooth "$data/fandisk.ply" x.ply --method nope
run err_lambda smooth "$data/fandisk.ply" x.ply --lambda 2
# Paths of this run's directory are not part of the comparison (binary files too: LC_ALL=C).
find . -type f -print0 | LC_ALL=C xargs -0 sed -i "s#$out#OUT#g; s#$data#DATA#g"
echo "report-corpus: $(find . -type f | wc -l) files in $out"
