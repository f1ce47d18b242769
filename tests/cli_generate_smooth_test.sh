#!/bin/sh
# End-to-end checks of `meshdiff generate` and `meshdiff smooth`.
# Usage: cli_generate_smooth_test.sh MESHDIFF_BINARY TEMP_DIR
bin="$1"
tmp="$2"
if [ -z "$bin" ] || [ -z "$tmp" ]; then
    echo "usage: $0 MESHDIFF_BINARY TEMP_DIR" >&2
    exit 2
fi
mkdir -p "$tmp" || exit 2

. "$(dirname "$0")/cli_lib.sh"

# PLY header check: the file exists, is a PLY and carries exact_H.
expect_ply_with_exact_h() {
    [ -s "$1" ] && pass || fail "$1 missing or empty"
    head -c 400 "$1" | grep -a -q "^ply" && pass || fail "$1 is not a PLY"
    head -c 600 "$1" | grep -a -q "property double exact_H" && pass || fail "$1 lacks exact_H"
}

# --- generate: every shape, defaults and with options ---------------------
expect 0 generate sphere "$tmp/sphere.ply" --subdivisions 2 --radius 2
expect_ply_with_exact_h "$tmp/sphere.ply"
head -c 400 "$tmp/sphere.ply" | grep -a -q "element vertex 162" && pass || fail "sphere: expected 162 vertices"
expect 0 generate noisy-sphere "$tmp/noisy.ply" --subdivisions 3 --noise 0.05 --seed 7
expect_ply_with_exact_h "$tmp/noisy.ply"
expect 0 generate noisy-sphere "$tmp/noisy2.ply" --subdivisions 3 --noise 0.05 --seed 7
cmp -s "$tmp/noisy.ply" "$tmp/noisy2.ply" && pass || fail "noisy-sphere: same seed, different file"
expect 0 generate noisy-sphere "$tmp/noisy3.ply" --subdivisions 3 --noise 0.05 --seed 8
if cmp -s "$tmp/noisy.ply" "$tmp/noisy3.ply"; then fail "noisy-sphere: different seeds, same file"; else pass; fi
expect 0 generate ellipsoid "$tmp/ellipsoid.ply" --subdivisions 3 --axes 1.5 1 1
expect_ply_with_exact_h "$tmp/ellipsoid.ply"
expect 0 generate torus "$tmp/torus.ply" --major 1 --minor 0.25 --n 48
expect_ply_with_exact_h "$tmp/torus.ply"
head -c 400 "$tmp/torus.ply" | grep -a -q "element vertex 576" && pass || fail "torus: expected 48 x 12 vertices"
expect 0 generate torus-irregular "$tmp/torus_irr.ply" --vertices 800 --seed 3
expect_ply_with_exact_h "$tmp/torus_irr.ply"
expect 0 generate heightfield "$tmp/hf.ply" --n 21 --amplitude 0.5
expect_ply_with_exact_h "$tmp/hf.ply"
expect 0 generate heightfield-irregular "$tmp/hf_irr.ply" --vertices 500 --seed 2
expect_ply_with_exact_h "$tmp/hf_irr.ply"
expect 0 generate plane "$tmp/plane.ply" --n 9 --spacing 0.5
expect_ply_with_exact_h "$tmp/plane.ply"
expect 0 generate sphere "$tmp/geo.ply" --frequency 20
head -c 400 "$tmp/geo.ply" | grep -a -q "element face 8000" && pass || fail "sphere --frequency 20: expected 8000 faces"
expect 0 generate ellipsoid "$tmp/geo_ell.ply" --frequency 5 --axes 1.5 1 1
head -c 400 "$tmp/geo_ell.ply" | grep -a -q "element vertex 252" && pass || fail "ellipsoid --frequency 5: 252 vertices"
expect 0 generate noisy-sphere "$tmp/geo_noisy.ply" --frequency 5 --noise 0.02 --seed 4
expect_ply_with_exact_h "$tmp/geo_noisy.ply"
expect 2 generate sphere "$tmp/bad.ply" --frequency 5 --subdivisions 2
expect 2 generate sphere "$tmp/bad.ply" --frequency 0
expect 2 generate torus "$tmp/bad.ply" --frequency 5
expect 0 generate sphere "$tmp/sphere.obj" --subdivisions 1
[ -s "$tmp/sphere.obj" ] && pass || fail "sphere.obj missing"

# --- generate: usage errors (exit 2) and unwritable output (exit 3) -------
expect 2 generate cube "$tmp/cube.ply"
expect 2 generate sphere "$tmp/bad.ply" --subdivisions 12
expect 2 generate sphere "$tmp/bad.ply" --noise 0.1
expect 2 generate torus "$tmp/bad.ply" --major 0.2 --minor 0.5
expect 2 generate ellipsoid "$tmp/bad.ply" --axes 1 0 1
expect 2 generate plane "$tmp/bad.ply" --n 1
expect 2 generate sphere
expect 3 generate sphere "$tmp/no/such/dir/s.ply"
[ ! -e "$tmp/bad.ply" ] && pass || fail "a rejected generate wrote a file"

# --- smooth: every method with both update schemes ------------------------
for method in laplacian taubin bilaplacian mcf modified-mcf; do
    for update in post pre; do
        out="$tmp/smooth_${method}_${update}.ply"
        expect 0 smooth "$tmp/noisy.ply" "$out" --method "$method" --update "$update" --iterations 5
        [ -s "$out" ] && pass || fail "smooth $method $update: no output"
    done
done
expect 0 smooth "$tmp/hf.ply" "$tmp/hf_smooth.off" --method taubin --lambda 0.6 --mu -0.65 --iterations 3
[ -s "$tmp/hf_smooth.off" ] && pass || fail "smooth to .off: no output"
expect 0 smooth "$tmp/torus_irr.ply" "$tmp/t_mcf.ply" --method mcf --step 0.05 --iterations 3
expect 0 smooth "$tmp/noisy.ply" "$tmp/implicit.ply" --method mcf --implicit --step 20 --iterations 2
[ -s "$tmp/implicit.ply" ] && pass || fail "smooth --implicit: no output"
expect 0 smooth "$tmp/noisy.ply" "$tmp/bilap.ply" --method bilaplacian --damping 0.5 --iterations 2
expect 0 smooth "$tmp/noisy.ply" "$tmp/zero.ply" --iterations 0
if cmp -s "$tmp/noisy.ply" "$tmp/smooth_laplacian_post.ply"; then fail "smooth changed nothing"; else pass; fi

# --- smooth: roughness profiles recorded during smoothing -----------------
expect 0 smooth "$tmp/noisy.ply" "$tmp/prof.ply" --method taubin --iterations 4 --profile-every 2 \
    --json "$tmp/prof.json"
[ -s "$tmp/prof.json" ] && pass || fail "smooth --json: no JSON"
grep -q '"schema": "meshdiff.smoothing/1"' "$tmp/prof.json" && pass || fail "smooth --json: schema missing"
tr -d ' \n' <"$tmp/prof.json" | grep -q '"iterations":\[0,2,4\]' && pass || fail "smooth --json: iterations not 0,2,4"
tr -d ' \n' <"$tmp/prof.json" | grep -q '"levels":\[1,5,10,20\]' && pass || fail "smooth --json: default levels"
expect 0 smooth "$tmp/noisy.ply" "$tmp/prof2.ply" --iterations 3 --json - --levels 1,2
grep -q '"sigma_global"' "$tmp/stdout" && pass || fail "smooth --json -: no JSON on stdout"
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --profile-every 2
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --json "$tmp/bad.json" --levels 0

# --- smooth: stability of the explicit flows ----------------------------
# Step 1.5 is three times the stability bound of a good mesh: warned, recorded, and avoided by adaptive control.
expect 0 smooth "$tmp/noisy.ply" "$tmp/unstable.ply" --method mcf --step 1.5 --iterations 3 --json "$tmp/unstable.json"
grep -q "exceeded the stability bound" "$tmp/stderr" && pass || fail "smooth: no stability warning for step 1.5"
grep -q "noisy.ply" "$tmp/stderr" && pass || fail "smooth: the stability warning does not name the input"
tr -d ' \n' <"$tmp/unstable.json" | grep -q '"unstable_iterations":3' && pass || fail "smooth --json: unstable_iterations"
expect 0 smooth "$tmp/noisy.ply" "$tmp/stable.ply" --method mcf --step 1.5 --iterations 3 --step-control adaptive \
    --json "$tmp/stable.json"
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: adaptive control still warns"; else pass; fi
grep -q "flow time" "$tmp/stdout" && pass || fail "smooth: no flow time reported"
tr -d ' \n' <"$tmp/stable.json" | grep -q '"unstable_iterations":0' && pass || fail "smooth --json: adaptive unstable"
tr -d ' \n' <"$tmp/stable.json" | grep -q '"step_control":"adaptive"' && pass || fail "smooth --json: step_control"
expect 0 smooth "$tmp/noisy.ply" "$tmp/small.ply" --method modified-mcf --step 0.05 --iterations 2
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: warning for a stable step"; else pass; fi
expect 0 smooth "$tmp/noisy.ply" "$tmp/ds.ply" --iterations 2 --json "$tmp/ds.json" --distance-samples 5000
tr -d ' \n' <"$tmp/ds.json" | grep -Eq '"samples":(49[5-9][0-9]|50[0-4][0-9])[,}]' && pass || fail "smooth --distance-samples: not about 5000 samples"
expect 0 smooth "$tmp/noisy.ply" "$tmp/imp2.ply" --method mcf --implicit --step 0.5 --iterations 2
if grep -q "exceeded the stability bound" "$tmp/stderr"; then fail "smooth: implicit mcf warned about stability"; else pass; fi
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step-control sometimes
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step-control adaptive --stability 1.5

# --- smooth: usage errors (exit 2), missing input (exit 3) ----------------
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method gauss
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --update sideways
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --iterations -1
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method taubin --mu -0.1
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --step 0
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method taubin --implicit
expect 2 smooth "$tmp/noisy.ply" "$tmp/bad.ply" --method mcf --implicit --update pre
expect 2 smooth "$tmp/noisy.ply"
expect 3 smooth "$tmp/does_not_exist.ply" "$tmp/bad.ply"
[ ! -e "$tmp/bad.ply" ] && pass || fail "a rejected smooth wrote a file"

finish
