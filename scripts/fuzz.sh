#!/usr/bin/env bash
# Fuzzes meshdiff's mesh readers with libFuzzer (clang) under AddressSanitizer +
# UndefinedBehaviorSanitizer: each format for a fixed time from fixed seeds
# (tests/fuzz/seeds/<format>/ and every input that ever failed,
# tests/fuzz/regressions/<format>/). A crash, a sanitizer report, a hang (10 s)
# or runaway memory (2 GB) fails the run, and the input is copied into
# tests/fuzz/regressions/<format>/ to be committed: from then on it is replayed
# by tests/replay_hostile.sh in every ctest run.
#
#   scripts/fuzz.sh                 # 45 s per format (what scripts/test.sh runs)
#   scripts/fuzz.sh 3600 off obj    # an hour per format, OFF and OBJ only
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-45}
shift || true
formats=("$@")
[[ ${#formats[@]} -gt 0 ]] || formats=(ply obj off stl)
jobs=${JOBS:-2}

cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMESHDIFF_BUILD_FUZZ=ON \
      -DMESHDIFF_SANITIZE=address,undefined -DMESHDIFF_WARNINGS_AS_ERRORS=OFF -DMESHDIFF_BUILD_TESTS=OFF \
      -DMESHDIFF_BUILD_BENCH=OFF -DMESHDIFF_BUILD_CLI=OFF -DMESHDIFF_BUILD_PYTHON=OFF > build-fuzz.log
cmake --build build-fuzz -j"$jobs" $(printf -- '--target fuzz_read_%s ' "${formats[@]}") >> build-fuzz.log
status=0
for fmt in "${formats[@]}"; do
    corpus=build-fuzz/corpus/$fmt
    artifacts=build-fuzz/artifacts/$fmt
    rm -rf "$corpus" "$artifacts"
    mkdir -p "$corpus" "$artifacts" tests/fuzz/regressions/"$fmt"  # git keeps no empty folder
    echo "== fuzz $fmt for $seconds s"
    if ! ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 build-fuzz/tests/fuzz/fuzz_read_"$fmt" -seed=1 \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
        -artifact_prefix="$artifacts/" "$corpus" tests/fuzz/seeds/"$fmt" tests/fuzz/regressions/"$fmt" \
        > "build-fuzz/$fmt.log" 2>&1; then
        status=1
        tail -30 "build-fuzz/$fmt.log"
        for a in "$artifacts"/*; do
            [[ -f $a ]] || continue
            name="$(basename "$a")"
            cp "$a" "tests/fuzz/regressions/$fmt/$name"
            echo "fuzz: $fmt: a failing input is now tests/fuzz/regressions/$fmt/$name (commit it)"
        done
    else
        grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "build-fuzz/$fmt.log" | tail -1
    fi
done
[[ $status == 0 ]] && echo "fuzz: no failure in ${formats[*]}"
exit $status
