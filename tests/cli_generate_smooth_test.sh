#!/bin/sh
# End-to-end checks of `meshdiff generate` and `meshdiff smooth`.
# Usage: cli_generate_smooth_test.sh MESHDIFF_BINARY TEMP_DIR
set -e
bin="$1"
tmp="$2"
if [ -z "$bin" ] || [ -z "$tmp" ]; then
    echo "usage: $0 MESHDIFF_BINARY TEMP_DIR" >&2
    exit 2
fi
mkdir -p "$tmp"

. "$(dirname "$0")/cli_lib.sh"

# PLY header check: the file exists, is a PLY and carries exact_H.
expect_ply_with_exact_h() {
    [ -s "$1" ] || fail "$1 missing or empty"
    head -c 400 "$1" | grep -a -q "^ply" || fail "$1 is not a PLY"
    head -c 600 "$1" | grep -a -q "property double exact_H" || fail "$1 lacks exact_H"
}

# --- generate: every shape, defaults and with options ---------------------
expect_exit 0 generate sphere "$tmp/sphere.ply" --subdivisions 2 --radius 2
expect_ply_with_exact_h "$tmp/sphere.ply"
head -c 400 "$tmp/sphere.ply" | grep -a -q "element vertex 162" || fail "sphere: expected 162 vertices"
expect_exit 0 generate noisy-sphere "$tmp/noisy.ply" --subdivisions 3 --noise 0.05 --seed 7
expect_ply_with_exact_h "$tmp/noisy.ply"
expect_exit 0 generate noisy-sphere "$tmp/noisy2.ply" --subdivisions 3 --noise 0.05 --seed 7
cmp -s "$tmp/noisy.ply" "$tmp/noisy2.ply" || fail "noisy-sphere: same seed, different file"
expect_exit 0 generate noisy-sphere "$tmp/noisy3.ply" --subdivisions 3 --noise 0.05 --seed 8
if cmp -s "$tmp/noisy.ply" "$tmp/noisy3.ply"; then fail "noisy-sphere: different seeds, same file"; fi
expect_exit 0 generate ellipsoid "$tmp/ellipsoid.ply" --subdivisions 3 --axes 1.5 1 1
expect_ply_with_exact_h "$tmp/ellipsoid.ply"
expect_exit 0 generate torus "$tmp/torus.ply" --major 1 --minor 0.25 --n 48
expect_ply_with_exact_h "$tmp/torus.ply"
head -c 400 "$tmp/torus.ply" | grep -a -q "element vertex 576" || fail "torus: expected 48 x 12 vertices"
expect_exit 0 generate torus-irregular "$tmp/torus_irr.ply" --vertices 800 --seed 3
expect_ply_with_exact_h "$tmp/torus_irr.ply"
expect_exit 0 generate heightfield "$tmp/hf.ply" --n 21 --amplitude 0.5
expect_ply_with_exact_h "$tmp/hf.ply"
expect_exit 0 generate heightfield-irregular "$tmp/hf_irr.ply" --vertices 500 --seed 2
expect_ply_with_exact_h "$tmp/hf_irr.ply"
expect_exit 0 generate plane "$tmp/plane.ply" --n 9 --spacing 0.5
expect_ply_with_exact_h "$tmp/plane.ply"
expect_exit 0 generate sphere "$tmp/geo.ply" --frequency 20
head -c 400 "$tmp/geo.ply" | grep -a -q "element face 8000" || fail "sphere --frequency 20: expected 8000 faces"
expect_exit 0 generate ellipsoid "$tmp/geo_ell.ply" --frequency 5 --axes 1.5 1 1
head -c 400 "$tmp/geo_ell.ply" | grep -a -q "element vertex 252" || fail "ellipsoid --frequency 5: 252 vertices"
expect_exit 0 generate noisy-sphere "$tmp/geo_noisy.ply" --frequency 5 --noise 0.02 --seed 4
expect_ply_with_exact_h "$tmp/geo_noisy.ply"
expect_exit 2 generate sphere "$tmp/bad.ply" --frequency 5 --subdivisions 2
expect_exit 2 generate sphere "$tmp/bad.ply" --frequency 0
expect_exit 2 generate torus "$tmp/bad.ply" --frequency 5
expect_exit 0 generate sphere "$tmp/sphere.obj" --subdivisions 1
[ -s "$tmp/sphere.obj" ] || fail "sphere.obj missing"

# --- generate: usage errors (exit 2) and unwritable output (exit 3) -------
expect_exit 2 generate cube "$tmp/cube.ply"
expect_exit 2 generate sphere "$tmp/bad.ply" --subdivisions 12
expect_exit 2 generate sphere "$tmp/bad.ply" --noise 0.1
expect_exit 2 generate torus "$tmp/bad.ply" --major 0.2 --minor 0.5
expect_exit 2 generate ellipsoid "$tmp/bad.ply" --axes 1 0 1
expect_exit 2 generate plane "$tmp/bad.ply" --n 1
expect_exit 2 generate sphere
expect_exit 3 generate sphere "$tmp/no/such/dir/s.ply"
[ ! -e "$tmp/bad.ply" ] || fail "a rejected generate wrote a file"

# --- smooth: every method with both update schemes ------------------------
for method in laplacian taubin bilaplacian mcf modified-mcf; do
    for update in post pre; do
        out="$tmp/smooth_${method}_${update}.ply"
        expect_exit 0 smooth "$tmp/noisy.ply" "$out" --method "$method" --update "$update" --iterations 5
        [ -s "$out" ] || fail "smooth $method $update: no output"
    done
done
expect_exit 0 smooth "$tmp/hf.ply" "$tmp/hf_smooth.off" --method taubin --lambda 0.6 --mu -0.65 --iterations 3
[ -s "$tmp/hf_smooth.off" ] || fail "smooth to .off: no output"
expect_exit 0 smooth "$tmp/torus_irr.ply" "$tmp/t_mcf.ply" --method mcf --step 0.05 --iterations 3
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/implicit.ply" --method mcf --implicit --step 20 --iterations 2
[ -s "$tmp/implicit.ply" ] || fail "smooth --implicit: no output"
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/bilap.ply" --method bilaplacian --damping 0.5 --iterations 2
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/zero.ply" --iterations 0
if cmp -s "$tmp/noisy.ply" "$tmp/smooth_laplacian_post.ply"; then fail "smooth changed nothing"; fi

# --- smooth: roughness profiles recorded during smoothing -----------------
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/prof.ply" --method taubin --iterations 4 --profile-every 2 \
    --json "$tmp/prof.json"
[ -s "$tmp/prof.json" ] || fail "smooth --json: no JSON"
grep -q '"schema": "meshdiff.smoothing/1"' "$tmp/prof.json" || fail "smooth --json: schema missing"
tr -d ' \n' <"$tmp/prof.json" | grep -q '"iterations":\[0,2,4\]' || fail "smooth --json: iterations not 0,2,4"
tr -d ' \n' <"$tmp/prof.json" | grep -q '"levels":\[1,5,10,20\]' || fail "smooth --json: default levels"
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/prof2.ply" --iterations 3 --json - --levels 1,2
grep -q '"sigma_global"' "$tmp/stdout" || fail "smooth --json -: no JSON on stdout"
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --profile-every 2
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --json "$tmp/bad.json" --levels 0

# --- smooth: stability of the explicit flows ----------------------------
# Step 1.5 is three times the stability bound of a good mesh: warned, recorded, and avoided by adaptive control.
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/unstable.ply" --method mcf --step 1.5 --iterations 3 --json "$tmp/unstable.json"
grep -q "exceeded the stability bound" "$tmp/stderr" || fail "smooth: no stability warning for step 1.5"
grep -q "noisy.ply" "$tmp/stderr" || fail "smooth: the stability warning does not name the input"
tr -d ' \n' <"$tmp/unstable.json" | grep -q '"unstable_iterations":3' || fail "smooth --json: unstable_iterations"
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/stable.ply" --method mcf --step 1.5 --iterations 3 --step-control adaptive \
    --json "$tmp/stable.json"
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: adaptive control still warns"; fi
grep -q "flow time" "$tmp/stdout" || fail "smooth: no flow time reported"
tr -d ' \n' <"$tmp/stable.json" | grep -q '"unstable_iterations":0' || fail "smooth --json: adaptive unstable"
tr -d ' \n' <"$tmp/stable.json" | grep -q '"step_control":"adaptive"' || fail "smooth --json: step_control"
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/small.ply" --method modified-mcf --step 0.05 --iterations 2
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: warning for a stable step"; fi
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/ds.ply" --iterations 2 --json "$tmp/ds.json" --distance-samples 5000
tr -d ' \n' <"$tmp/ds.json" | grep -Eq '"samples":(49[5-9][0-9]|50[0-4][0-9])[,}]' || fail "smooth --distance-samples: not about 5000 samples"
expect_exit 0 smooth "$tmp/noisy.ply" "$tmp/imp2.ply" --method mcf --implicit --step 0.5 --iterations 2
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: implicit mcf warned about stability"; fi
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step-control sometimes
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step-control adaptive --stability 1.5

# --- smooth: usage errors (exit 2), missing input (exit 3) ----------------
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method gauss
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --update sideways
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --iterations -1
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method taubin --mu -0.1
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step 0
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method taubin --implicit
expect_exit 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --implicit --update pre
expect_exit 2 smooth "$tmp/noisy.ply"
expect_exit 3 smooth "$tmp/does_not_exist.ply" "$tmp/bad.ply"
[ ! -e "$tmp/bad.ply" ] || fail "a rejected smooth wrote a file"

echo "cli_generate_smooth_test: all checks passed"
