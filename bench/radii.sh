#!/usr/bin/env bash
# Prints the wall time (median of RUNS) of the metric profile (--radii, issue 15) beside that of the ring profile,
# on the meshes given (default: igea, bunny and rocker_arm from ../shared/data/meshes beside the repository). Not a
# timed test: figures for docs/performance.md.
#
#   bench/radii.sh BINARY [MESH ...]
#
# Environment: RUNS (default 3), RADII (default "default"), THREADS (default 0: all cores).
# ring:   meshdiff profile MESH                                  (levels 1-20 and global, the default)
# metric: meshdiff profile MESH --levels '' --radii RADII        (the global level as well)
# both:   meshdiff profile MESH --radii RADII                    (rings, global and radii in one run)
set -euo pipefail
bin=$1
shift
runs=${RUNS:-3}
radii=${RADII:-default}
threads=${THREADS:-0}
here=$(cd "$(dirname "$0")" && pwd)
data=$here/../../shared/data/meshes
meshes=("$@")
[[ ${#meshes[@]} -gt 0 ]] || meshes=("$data/igea.ply" "$data/bunny.ply" "$data/rocker_arm.ply")

# median of RUNS wall times of one command, in seconds
median() {
    local t=()
    for _ in $(seq "$runs"); do
        local s e
        s=$(date +%s.%N)
        "$@" > /dev/null
        e=$(date +%s.%N)
        t+=("$(echo "$e - $s" | bc -l)")
    done
    printf '%s\n' "${t[@]}" | sort -g | awk '{a[NR] = $1} END {printf "%.2f", a[int((NR + 1) / 2)]}'
}

printf '%-16s %9s %10s %10s %10s %8s\n' mesh vertices ring_s metric_s both_s ratio
for m in "${meshes[@]}"; do
    nv=$("$bin" profile "$m" --levels 1 --no-global --json - | python3 -c 'import json,sys; print(json.load(sys.stdin)["mesh"]["vertices"])')
    ring=$(median "$bin" profile "$m" --threads "$threads")
    metric=$(median "$bin" profile "$m" --threads "$threads" --levels '' --radii "$radii")
    both=$(median "$bin" profile "$m" --threads "$threads" --radii "$radii")
    printf '%-16s %9s %10s %10s %10s %8.2f\n' "$(basename "$m" .ply)" "$nv" "$ring" "$metric" "$both" \
        "$(echo "$metric / $ring" | bc -l)"
done
echo "radii: $radii; runs: $runs (median); threads: $threads (0 = all); $(nproc) cores; $(date -u +%FT%TZ)"
