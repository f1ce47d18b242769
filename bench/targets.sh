#!/usr/bin/env bash
# The figures of issue 30's targets (and issue 14's before them), for one or two binaries run alternately (old and
# new in the same run, so that the machine's load weighs on both alike): wall time (median of RUNS), CPU time
# (median) and peak memory (largest run) of each workload, the target beside it, and new/old ratios. Not a timed
# test: figures for README.md and docs/performance.md.
#
#   bench/targets.sh NEW_BINARY [OLD_BINARY]
#
# Issue 30 states its targets as figures of the machine it was measured on, beside edfd398's there; machines differ
# (page faults cost 4x more on some), so with OLD_BINARY = a build of edfd398 the ratio column is the measure that
# travels: new wall / old wall against the target's ratio (target / edfd398's figure in the issue).
#
# Workloads (default options, all cores):
#   igea distance        meshdiff IGEA IGEA_DEC --no-roughness --hausdorff sampled   (surface distance both
#                        directions, ~2.1M samples each, with reading; IGEA_DEC is igea's 10 % decimation, made with
#                        OpenMesh-commandlineDecimater -M Q -M NF -n 0.1 when that tool is there, else skipped)
#   igea compare         meshdiff IGEA IGEA_DEC
#   igea profile         meshdiff profile IGEA                          (../shared/data/meshes beside the repository)
#   1M profile           meshdiff profile A1M.ply                       (generated: torus-irregular, 1,000,000 vertices)
#   1M compare           meshdiff A1M.ply B1M.ply                       (B: the same with --seed 2)
#   10M profile/compare  meshdiff profile T5M.ply; meshdiff T5M.ply T5M_DEC.ply  (only when T5M and T5M_DEC are set:
#                        a 5M-vertex torus-irregular and its 10% decimation, see docs/performance.md; one run each)
#
# Environment: RUNS (default 3), MESHES (default ../shared/data/meshes), WORK (where the 1M tori and the igea
# decimation are made or found, default /tmp/meshdiff-targets), T5M, T5M_DEC.
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
igea_dec=$work/igea_dec10.ply
if [[ ! -f $igea_dec ]] && command -v OpenMesh-commandlineDecimater > /dev/null; then
    OpenMesh-commandlineDecimater -M Q -M NF -n 0.1 -i "$meshes/igea.ply" -o "$igea_dec" > /dev/null 2>&1
fi

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
    local median_old=""
    for b in "${bins[@]}"; do
        local label=new ratio=""
        [[ -n $old && $b == "$old" ]] && label=old
        local median
        median=$(tr ' ' '\n' <<< "${wall[$b]}" | grep . | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
        if [[ $label == old ]]; then
            median_old=$median
        elif [[ -n $median_old ]]; then
            ratio=$(awk -v n="$median" -v o="$median_old" 'BEGIN {printf "%.2f", n / o}')
        fi
        printf '%-14s %-4s %9s %9s %9d %6s  %s\n' "$name" "$label" "$median" \
            "$(tr ' ' '\n' <<< "${cpu[$b]}" | grep . | sort -g | awk '{a[NR] = $1} END {printf "%.2f", a[int((NR + 1) / 2)]}')" \
            "$((mem[$b] / 1024))" "${ratio:--}" "$target"
    done
}

printf '%-14s %-4s %9s %9s %9s %6s  %s\n' workload bin wall_s cpu_s peak_MB new/old "target (issue 30: figure; ratio to edfd398)"
if [[ -f $igea_dec ]]; then
    row "igea distance" "<= 0.9 s; <= 0.51 (0.9 / 1.78)" "$runs" "$meshes/igea.ply" "$igea_dec" --no-roughness --hausdorff sampled
    row "igea compare" "<= 1.8 s; <= 0.67 (1.8 / 2.7)" "$runs" "$meshes/igea.ply" "$igea_dec"
else
    echo "igea distance, igea compare: skipped (no $igea_dec and no OpenMesh-commandlineDecimater to make it)"
fi
row "igea profile" "<= 0.45 s; <= 0.79 (0.45 / 0.57)" "$runs" profile "$meshes/igea.ply"
row "1M profile" "<= 2.8 s, <= 220 MB; <= 0.60 (2.8 / 4.7)" "$runs" profile "$work/a1m.ply"
row "1M compare" "<= 14 s, <= 550 MB; <= 0.53 (14 / 26.5)" "$runs" "$work/a1m.ply" "$work/b1m.ply"
if [[ -n ${T5M:-} && -n ${T5M_DEC:-} ]]; then
    row "10M profile" "<= 40 s (issue 14)" 1 profile "$T5M"
    row "10M compare" "<= 75 s, <= 3 GB; <= 0.54 (75 / 139)" 1 "$T5M" "$T5M_DEC"
fi
echo "$(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%Y-%m-%dT%H:%M:%SZ)"
