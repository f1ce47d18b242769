#!/usr/bin/env bash
# Prints wall times (median of RUNS) of profile and compare on fans of N triangles around one vertex (issue 13: a
# vertex of valence 100,000), old binary vs new, runs interleaved. Not a timed test: figures for
# docs/performance.md.
#
#   bench/hub_fan.sh NEW_BINARY [OLD_BINARY]
#
# Environment: SIZES (default "5000 20000 100000"), RUNS (default 3), SLOW (seconds, default 300: a cell whose first
# run took longer is run only once), LIMIT (seconds per run, default 1800: a run over it is printed as ">LIMIT"),
# IGEA (a mesh profiled as well, both binaries, to show no slowdown on an ordinary mesh; default
# ../shared/data/meshes/igea.ply beside the repository, if present).
# The fan: centre (0, 0, 0.1), N rim vertices on the unit circle with z = 0.01 sin(7a), faces (0, i, i + 1 mod N).
set -euo pipefail
new=$1
old=${2:-}
sizes=${SIZES:-5000 20000 100000}
runs=${RUNS:-3}
limit=${LIMIT:-1800}
slow=${SLOW:-300}
here=$(cd "$(dirname "$0")" && pwd)
igea=${IGEA:-$here/../../shared/data/meshes/igea.ply}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for n in $sizes; do
    python3 "$here/../tests/make_fan.py" "$n" "$tmp/fan$n.ply"
done

# Cells: "label|binary|args"; each run appends its time to $tmp/<cell index>.
cells=()
for n in $sizes; do
    for which in old new; do
        bin=$([[ $which == old ]] && echo "$old" || echo "$new")
        [[ -n $bin ]] || continue
        cells+=("fan $n profile|$which|$bin|profile $tmp/fan$n.ply")
        cells+=("fan $n compare|$which|$bin|$tmp/fan$n.ply $tmp/fan$n.ply")
    done
done
if [[ -f $igea ]]; then
    for which in old new; do
        bin=$([[ $which == old ]] && echo "$old" || echo "$new")
        [[ -n $bin ]] && cells+=("igea profile|$which|$bin|profile $igea")
    done
fi

for ((r = 1; r <= runs; r++)); do
    for i in "${!cells[@]}"; do
        IFS='|' read -r label which bin args <<< "${cells[$i]}"
        if [[ -f $tmp/$i ]]; then  # over the limit, or slow: once only
            grep -q '^>' "$tmp/$i" && continue
            [[ $(echo "$(head -1 "$tmp/$i") > $slow" | bc) == 1 ]] && continue
        fi
        start=$(date +%s.%N)
        set +e
        # shellcheck disable=SC2086
        timeout "$limit" "$bin" $args > /dev/null 2> "$tmp/err"
        code=$?
        set -e
        end=$(date +%s.%N)
        if [[ $code == 124 ]]; then
            echo ">$limit" >> "$tmp/$i"
        elif [[ $code != 0 ]]; then
            echo "$label ($which) failed with exit code $code: $(head -c 300 "$tmp/err")" >&2
            exit 1
        else
            echo "$end - $start" | bc >> "$tmp/$i"
        fi
    done
done

printf '%-16s %-4s %10s   %s\n' workload bin median runs
for i in "${!cells[@]}"; do
    IFS='|' read -r label which bin args <<< "${cells[$i]}"
    if grep -q '^>' "$tmp/$i"; then
        med=$(grep '^>' "$tmp/$i")
    else
        med=$(sort -g "$tmp/$i" | awk '{a[NR] = $1} END {printf "%.2f", (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}')
    fi
    printf '%-16s %-4s %10s   %s\n' "$label" "$which" "$med" "$(awk '/^>/ {printf "%s ", $1; next} {printf "%.2f ", $1}' "$tmp/$i")"
done
