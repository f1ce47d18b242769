#!/usr/bin/env bash
# Issue 33: an output never destroys an input, nothing hangs, every failure
# leaves nothing behind. One check per case of the issue (numbered as there);
# each failed on edfd398.
# Usage: cli_reliability_test.sh MESHDIFF_BINARY DATA_DIR [MEMORY_LIMITS=yes|no]
# (no: leave out the cases run under ulimit -v, which AddressSanitizer cannot start under)
bin="$1"
data=$(cd "$2" && pwd)
memory_limits="${3:-yes}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

cd "$tmp" || exit 1
"$bin" generate sphere --subdivisions 3 a.ply >/dev/null
"$bin" generate noisy-sphere --frequency 10 b.ply >/dev/null
printf 'a.ply,b.ply,p1\n' >pairs.csv

# 1. batch --out onto a pair's own mesh: exit 2, the mesh untouched; onto a file
#    that is not a batch record file: exit 3, the file untouched.
cp b.ply b.keep
expect 2 batch pairs.csv --out b.ply -q && cmp -s b.ply b.keep && pass || fail "1: batch --out = an input changed it"
head -c 1000 "$data/fandisk.ply" >notrecords.ply  # a PLY cut in its binary body: no final newline
cp notrecords.ply notrecords.keep
expect 3 batch pairs.csv --out notrecords.ply -q && cmp -s notrecords.ply notrecords.keep && pass ||
    fail "1: batch --out = a non-record file changed it"
grep -q "left as it was" "$tmp/stderr" && pass || fail "1: the message says the file is left as it was"
# A torn last record (a killed run) is still cut off and the pair run again.
"$bin" batch pairs.csv --out torn.jsonl -q 2>/dev/null
printf '{"elapsed_seconds":0.1,"id":"p2","mea' >>torn.jsonl
printf 'a.ply,b.ply,p1\na.ply,a.ply,p2\n' >pairs2.csv
expect 0 batch pairs2.csv --out torn.jsonl -q && [ "$(grep -c '"status":"ok"' torn.jsonl)" = 2 ] && pass ||
    fail "1: a torn last record is dropped and its pair runs again"

# 3. Devices: --out /dev/full is a write error (exit 3) without reading it;
#    a pair list that is not a regular file is refused (exit 3).
expect_within 20 3 batch pairs.csv --out /dev/full -q
expect_within 20 0 batch pairs.csv --out /dev/null -q
expect_within 20 3 batch /dev/zero --out o.jsonl -q && grep -q "not a regular file" "$tmp/stderr" && pass ||
    fail "3: /dev/zero as a pair list"

# 4. A mesh compared with itself, both maps written: exit 0, all distances 0.
expect 0 compare a.ply a.ply --no-roughness --distance-maps self && [ -f self_original.ply ] &&
    [ -f self_processed.ply ] && pass || fail "4: self-compare maps"
printf 'a.ply,a.ply,self\n' >self.csv
expect 0 batch self.csv --out self.jsonl --maps-dir selfmaps -q && [ -f selfmaps/self_processed.ply ] && pass ||
    fail "4: batch --maps-dir of a self pair"

# 5. A failing run leaves none of its outputs (a --json into a missing folder fails last).
expect 3 smooth a.ply out.ply --json nodir/x.json && [ ! -e out.ply ] && pass || fail "5: smooth left out.ply"
expect 3 compare a.ply b.ply --distance-map m.ply --json nodir/x.json && [ ! -e m.ply ] && pass ||
    fail "5: compare left m.ply"
expect 3 profile a.ply --vertex-data v.ply --json nodir/x.json && [ ! -e v.ply ] && pass ||
    fail "5: profile left v.ply"
[ -z "$(ls -A . | grep '\.meshdiff-')" ] && pass || fail "5: temporary files left: $(ls -A | grep meshdiff-)"

# 6. Two outputs naming one file: exit 2 naming both options.
expect 2 compare a.ply b.ply --json X.out --distance-map X.out && grep -q -- "--json" "$tmp/stderr" &&
    grep -q -- "--distance-map" "$tmp/stderr" && pass || fail "6: --json = --distance-map"
expect 2 compare a.ply b.ply --samples-out S.ply --distance-map S.ply
expect 2 profile a.ply --vertex-data V.ply --json V.ply
[ ! -e X.out ] && [ ! -e S.ply ] && [ ! -e V.ply ] && pass || fail "6: a refused run wrote a file"

# 7. Outputs meshdiff would not read back are refused (exit 2), and not written.
expect 2 noise a.ply n.ply --amplitude 1e308 --distribution gaussian --unit absolute && [ ! -e n.ply ] && pass ||
    fail "7: noise 1e308"
expect 2 generate plane p.ply --spacing 1e308 && [ ! -e p.ply ] && pass || fail "7: plane spacing 1e308"
expect 2 generate heightfield h.ply --amplitude 1e308 && [ ! -e h.ply ] && pass || fail "7: heightfield 1e308"

# 8. A point cloud without extent compared with itself: exit 4 in the text and the JSON run alike.
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n' >one.ply
expect 4 compare one.ply one.ply && grep -q "no extent" "$tmp/stderr" && pass || fail "8: one-point cloud"
expect 4 compare one.ply one.ply --json -
grep -q "nan\|inf" "$tmp/stdout" && fail "8: NaN or inf printed" || pass
# ... and a mesh without extent (coordinates that underflow the diagonal) as the original: exit 4, text and
# JSON alike (was exit 2, "relative_to: diagonal must be ..."); as the processed mesh it is a valid input
# (its index build read out of bounds: subnormal coordinates, scripts/fuzz_arrays.py trial 143).
sub="$data/hostile/off_subnormal.off"
expect 4 compare "$sub" "$sub" --no-roughness && grep -q "no extent" "$tmp/stderr" && pass || fail "8: mesh without extent"
expect 4 compare "$sub" "$sub" --no-roughness --json -
expect 0 compare a.ply "$sub" --no-roughness --json sub.json &&
    python3 -c "import json,sys; j=json.load(open('sub.json')); h = j['surface_distance']['hausdorff']; sys.exit(0 if 0.99 < h['lower'] <= h['upper'] < 1.01 else 1)" &&
    pass || fail "8: a processed mesh of subnormal coordinates"

# 9. More threads than the system can start (a memory limit): a warning and fewer threads, the same
#    numbers; not libgomp's exit 1 from inside the library.
if [ "$memory_limits" = yes ]; then
"$bin" compare a.ply b.ply --threads 1 --json t1.json >/dev/null
(ulimit -v 3000000 && "$bin" compare a.ply b.ply --threads 1000 --json t1000.json >/dev/null 2>"$tmp/stderr")
got=$?
[ "$got" -eq 0 ] && grep -q "warning: --threads: only" "$tmp/stderr" && cmp -s t1.json t1000.json && pass ||
    fail "9: --threads 1000 under a memory limit exited $got: $(cat "$tmp/stderr")"
fi

# 10. kill -9 of batch: the running pair's process dies with it.
"$bin" generate sphere --subdivisions 6 big.ply >/dev/null
printf 'big.ply,big.ply,slow\n' >slow.csv
"$bin" batch slow.csv --out slow.jsonl -q --threads 1 2>/dev/null &
batch_pid=$!
child=""
for _ in $(seq 1 100); do
    child=$(pgrep -P "$batch_pid" | head -1)
    [ -n "$child" ] && break
    sleep 0.05
done
if [ -n "$child" ]; then
    kill -9 "$batch_pid"
    wait "$batch_pid" 2>/dev/null
    gone=no
    for _ in $(seq 1 50); do
        kill -0 "$child" 2>/dev/null || { gone=yes; break; }
        sleep 0.05
    done
    [ "$gone" = yes ] && pass || { fail "10: the pair's process outlived kill -9 of batch"; kill -9 "$child"; }
else
    fail "10: batch started no child"
fi

# 11. A FIFO as the pair list: refused at once (exit 3), no block.
mkfifo fifo.csv
expect_within 5 3 batch fifo.csv --out f.jsonl -q

# 12. A pair list's fields are file names, whatever their first character.
cp b.ply ./-x.ply
cp b.ply ./#x.ply
printf 'a.ply,-x.ply,dash\na.ply,"#x.ply",hash\n' >odd.csv
expect 0 batch odd.csv --out odd.jsonl -q && [ "$(grep -c '"status":"ok"' odd.jsonl)" = 2 ] && pass ||
    fail "12: names starting with - or #: $(cat odd.jsonl | head -c 300)"

# 14. Out of memory has its own exit code (7), not the internal error's (70).
if [ "$memory_limits" = yes ]; then
(ulimit -v 1500000 && "$bin" compare a.ply b.ply --no-roughness -n 200000000 >"$tmp/stdout" 2>"$tmp/stderr")
got=$?
[ "$got" -eq 7 ] && grep -q "out of memory" "$tmp/stderr" && pass || fail "14: out of memory exited $got: $(cat "$tmp/stderr")"
fi

# 15. An empty value is refused, not taken as "none" or 0.
expect 2 compare a.ply b.ply --threads ''
expect 2 compare a.ply b.ply --json ''
expect 2 noise a.ply n2.ply --amplitude ''
[ ! -e n2.ply ] && pass || fail "15: noise wrote with an empty amplitude"

# 16. A radius whose balls hold (nearly) the whole mesh is refused up front, with the reason: the work
#     of the metric levels stays proportional to the mesh (--radii 1000 took minutes at 200K vertices).
"$bin" generate sphere --subdivisions 7 s7.ply >/dev/null
expect_within 120 2 profile s7.ply --radii 1000 && grep -q -- "--radii: radius 1000 holds about" "$tmp/stderr" &&
    pass || fail "16: --radii 1000 on 164K vertices"
expect_within 120 0 profile s7.ply --levels 1 --no-global --radii 0.2

finish
