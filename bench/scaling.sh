#!/usr/bin/env bash
# Time and peak memory of the default profile and the default compare against vertex count (issue 14): irregular
# tori (`meshdiff generate torus-irregular --minor 0.3`) of each size, the compare against a second torus of the
# same size made with another seed. Prints one table row per size (wall time: median of RUNS; peak memory: the
# largest of the runs) and writes the same as CSV for bench/scaling_plot.py. Not a timed test.
#
#   bench/scaling.sh BINARY [SIZES...]        (default sizes: 100000 300000 1000000 3000000 5000000)
#
# Environment: RUNS (default 3; sizes above 1M run once), OUT (CSV path, default scaling.csv), TMPDIR.
set -euo pipefail
bin=$1
shift
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(100000 300000 1000000 3000000 5000000)
runs=${RUNS:-3}
out=${OUT:-scaling.csv}
work=$(mktemp -d "${TMPDIR:-/tmp}/meshdiff-scaling.XXXXXX")
trap 'rm -rf "$work"' EXIT

# median wall time and largest peak memory (MB) of N runs of a command
measure() {
    local n=$1
    shift
    local t=() m=0
    for _ in $(seq "$n"); do
        /usr/bin/time -f '%e %M' -o "$work/time" "$@" > /dev/null 2> "$work/err" || {
            cat "$work/err" >&2
            return 1
        }
        read -r w k < "$work/time"
        t+=("$w")
        ((k > m)) && m=$k
    done
    printf '%s %d\n' "$(printf '%s\n' "${t[@]}" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')" \
        "$((m / 1024))"
}

echo "vertices,profile_s,profile_mb,compare_s,compare_mb,runs" > "$out"
printf '%10s %10s %10s %10s %10s %5s\n' vertices profile_s profile_MB compare_s compare_MB runs
for n in "${sizes[@]}"; do
    r=$runs
    ((n > 1000000)) && r=1
    "$bin" generate torus-irregular "$work/a.ply" --vertices "$n" --minor 0.3 --seed 1 > /dev/null
    "$bin" generate torus-irregular "$work/b.ply" --vertices "$n" --minor 0.3 --seed 2 > /dev/null
    read -r pt pm < <(measure "$r" "$bin" profile "$work/a.ply")
    read -r ct cm < <(measure "$r" "$bin" "$work/a.ply" "$work/b.ply")
    printf '%10s %10s %10s %10s %10s %5s\n' "$n" "$pt" "$pm" "$ct" "$cm" "$r"
    echo "$n,$pt,$pm,$ct,$cm,$r" >> "$out"
done
echo "$(nproc) cores; $(date -u +%Y-%m-%dT%H:%M:%SZ); CSV: $out"
