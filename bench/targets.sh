#!/usr/bin/env bash
# The figures of issue 14's targets, for one or two binaries run alternately (old and new in the same run, so that
# the machine's load weighs on both alike): wall time (median of RUNS), CPU time (median) and peak memory (largest
# run) of each workload, beside the target. Not a timed test: figures for README.md and docs/performance.md.
#
#   bench/targets.sh NEW_BINARY [OLD_BINARY]
#
# Workloads (default options, all cores):
#   igea profile         meshdiff profile igea.ply                      (../shared/data/meshes beside the repository)
#   1M profile           meshdiff profile A1M.ply                       (generated: torus-irregular, 1,000,000 vertices)
#   1M compare           meshdiff A1M.ply B1M.ply                       (B: the same with --seed 2)
#   10M profile/compare  meshdiff profile T5M.ply; meshdiff T5M.ply T5M_DEC.ply  (only when T5M and T5M_DEC are set:
#                        a 5M-vertex torus-irregular and its 10% decimation, see docs/performance.md; one run each)
#
# Environment: RUNS (default 3), MESHES (default ../shared/data/meshes), WORK (where the 1M tori are made or found,
# default /tmp/meshdiff-targets), T5M, T5M_DEC.
set -euo pipefail
new=$1
old=${2:-}
runs=${RUNS:-3}
here=$(cd "$(dirname "$0")" && pwd)
meshes=${MESHES:-$here/../../shared/data/meshes}
work=${WORK:-/tmp/meshdiff-targets}
mkdir -p "$work"
[[ -f $work/a1m.ply ]] || "$new" generate torus-irregular "$work/a1m.ply" --vertices 1000000 --minor 0.3 --seed 1 > /dev/null
[[ -f $work/b1m.ply ]] || "$new" generate torus-irregular "$work/b1m.ply" --vertices 1000000 --minor 0.3 --seed 2 > /dev/null

bins=("$new")
[[ -n $old ]] && bins=("$old" "$new")

# One workload: RUNS rounds, each running every binary once; prints a row per binary.
row() {
    local name=$1 target=$2 n=$3
    shift 3
    local b
    declare -A wall cpu mem
    for _ in $(seq "$n"); do
        for b in "${bins[@]}"; do
            /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$b" "$@" > /dev/null 2> "$work/err" || {
                echo "failed: $b $*" >&2
                cat "$work/err" >&2
                return 1
            }
            read -r w u s k < "$work/time"
            wall[$b]+="$w "
            cpu[$b]+="$(echo "$u + $s" | bc -l) "
            ((k > ${mem[$b]:-0})) && mem[$b]=$k
        done
    done
    for b in "${bins[@]}"; do
        local label=new
        [[ -n $old && $b == "$old" ]] && label=old
        printf '%-14s %-4s %9s %9s %9d %s\n' "$name" "$label" \
            "$(tr ' ' '\n' <<< "${wall[$b]}" | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')" \
            "$(tr ' ' '\n' <<< "${cpu[$b]}" | grep . | sort -g | awk '{a[NR] = $1} END {printf "%.2f", a[int((NR + 1) / 2)]}')" \
            "$((mem[$b] / 1024))" "$target"
    done
}

printf '%-14s %-4s %9s %9s %9s %s\n' workload bin wall_s cpu_s peak_MB target
row "igea profile" "<= 0.5 s" "$runs" profile "$meshes/igea.ply"
row "1M profile" "<= 3 s, <= 400 MB" "$runs" profile "$work/a1m.ply"
row "1M compare" "<= 12 s, <= 1 GB" "$runs" "$work/a1m.ply" "$work/b1m.ply"
if [[ -n ${T5M:-} && -n ${T5M_DEC:-} ]]; then
    row "10M profile" "<= 40 s" 1 profile "$T5M"
    row "10M compare" "<= 180 s, <= 8 GB" 1 "$T5M" "$T5M_DEC"
fi
echo "$(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%Y-%m-%dT%H:%M:%SZ)"
