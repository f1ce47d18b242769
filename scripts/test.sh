#!/usr/bin/env bash
# The whole test suite, as CI runs it: installs the Debian dependencies, then
#  1. a Release build with warnings as errors, and ctest; installs it into a
#     temporary prefix and builds tests/consumer against it;
#  2. a Debug build with AddressSanitizer + UndefinedBehaviorSanitizer, and ctest;
#  3. the clang-format check of include/ src/ tools/ tests/ bench/ examples/.
# Usage: scripts/test.sh            (from anywhere; builds into build/ and build-asan/)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}

scripts/install-deps.sh

echo "== Release build + tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMESHDIFF_WARNINGS_AS_ERRORS=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== install and build a consumer against the installed package"
tests/consumer_test.sh build

echo "== Debug build with AddressSanitizer + UndefinedBehaviorSanitizer + tests"
# -O1 keeps Eigen usable under the sanitizers; asserts stay on (no NDEBUG).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
      -DMESHDIFF_SANITIZE=address,undefined -DMESHDIFF_BUILD_BENCH=OFF -DMESHDIFF_WARNINGS_AS_ERRORS=ON
cmake --build build-asan -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs"

echo "== clang-format"
find include src tools tests bench examples \( -name '*.h' -o -name '*.cpp' \) -print0 |
    xargs -0 clang-format --dry-run --Werror

echo "== all tests passed"
