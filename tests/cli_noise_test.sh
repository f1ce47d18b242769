#!/bin/sh
# End-to-end checks of `meshdiff noise`.
# Usage: cli_noise_test.sh MESHDIFF_BINARY TEMP_DIR
bin="$1"
tmp="$2"
if [ -z "$bin" ] || [ -z "$tmp" ]; then
    echo "usage: $0 MESHDIFF_BINARY TEMP_DIR" >&2
    exit 2
fi
mkdir -p "$tmp" || exit 2
rm -f "$tmp"/*.ply "$tmp"/*.off

. "$(dirname "$0")/cli_lib.sh"

expect 0 generate sphere "$tmp/sphere.ply" --subdivisions 3
expect 0 generate plane "$tmp/plane.ply" --n 9

# --- noise: output, determinism, seeds -------------------------------------
expect 0 noise "$tmp/sphere.ply" "$tmp/n1.ply" --amplitude 0.3 --seed 5
[ -s "$tmp/n1.ply" ] && pass || fail "noise: no output"
head -c 400 "$tmp/n1.ply" | grep -a -q "^ply" && pass || fail "noise: output is not a PLY"
head -c 400 "$tmp/n1.ply" | grep -a -q "element vertex 642" && pass || fail "noise: expected 642 vertices"
head -c 600 "$tmp/n1.ply" | grep -a -q "comment meshdiff noise: .*seed 5" && pass || fail "noise: no PLY comment"
grep -q "n1.ply: 642 vertices moved, 0 skipped" "$tmp/stdout" && pass || fail "noise: summary line: $(cat "$tmp/stdout")"
grep -q "mean edge length" "$tmp/stdout" && pass || fail "noise: the unit value is not printed"
if cmp -s "$tmp/sphere.ply" "$tmp/n1.ply"; then fail "noise: output equals input"; else pass; fi
expect 0 noise "$tmp/sphere.ply" "$tmp/n2.ply" --amplitude 0.3 --seed 5
cmp -s "$tmp/n1.ply" "$tmp/n2.ply" && pass || fail "noise: same seed, different files"
expect 0 noise "$tmp/sphere.ply" "$tmp/n3.ply" --amplitude 0.3 --seed 6
if cmp -s "$tmp/n1.ply" "$tmp/n3.ply"; then fail "noise: different seeds, same file"; else pass; fi

# --- noise: every unit, direction and distribution; other formats --------
for unit in edge diagonal absolute; do
    for direction in normal random; do
        for distribution in uniform gaussian; do
            out="$tmp/n_${unit}_${direction}_${distribution}.ply"
            expect 0 noise "$tmp/sphere.ply" "$out" --amplitude 0.01 --unit "$unit" --direction "$direction" \
                --distribution "$distribution" --seed 3
            [ -s "$out" ] && pass || fail "noise $unit $direction $distribution: no output"
        done
    done
done
grep -q "in mesh units" "$tmp/stdout" && pass || fail "noise --unit absolute: not reported"
expect 0 noise "$tmp/sphere.ply" "$tmp/n.off" --amplitude 0.2
[ -s "$tmp/n.off" ] && pass || fail "noise to .off: no output"
expect 0 noise "$tmp/n.off" "$tmp/from_off.ply" --amplitude 0.2
[ -s "$tmp/from_off.ply" ] && pass || fail "noise from .off: no output"

# --- noise: the boundary of an open mesh --------------------------------
expect 0 noise "$tmp/plane.ply" "$tmp/p1.ply" --amplitude 0.3
grep -q "49 vertices moved, 32 skipped (32 boundary" "$tmp/stdout" && pass || fail "noise: plane boundary: $(cat "$tmp/stdout")"
expect 0 noise "$tmp/plane.ply" "$tmp/p2.ply" --amplitude 0.3 --move-boundary
grep -q "81 vertices moved, 0 skipped" "$tmp/stdout" && pass || fail "noise --move-boundary: $(cat "$tmp/stdout")"

# --- noise: usage errors (exit 2), missing input (exit 3) ----------------
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude -1
grep -q "amplitude" "$tmp/stderr" && pass || fail "noise --amplitude -1: the message does not name amplitude"
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude nan
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude abc
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply"
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude 0.1 --unit meters
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude 0.1 --direction up
expect 2 noise "$tmp/sphere.ply" "$tmp/bad.ply" --amplitude 0.1 --distribution poisson
expect 2 noise "$tmp/sphere.ply" --amplitude 0.1
expect 3 noise "$tmp/does_not_exist.ply" "$tmp/bad.ply" --amplitude 0.1
expect 3 noise "$tmp/sphere.ply" "$tmp/no/such/dir/n.ply" --amplitude 0.1
[ ! -e "$tmp/bad.ply" ] && pass || fail "a rejected noise wrote a file"

finish
