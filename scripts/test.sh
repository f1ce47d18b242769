#!/usr/bin/env bash
# The whole test suite, as CI runs it: installs the Debian dependencies, then
#  1. a Release build with warnings as errors (with the Python module), and
#     ctest (with the HTML report's test in headless chromium); installs it
#     into a temporary prefix and builds tests/consumer against it;
#  2. the Python package: `pip install .` into a virtual environment (reusing
#     the Release tree: MESHDIFF_CMAKE_BUILD_DIR), pytest (python/tests, with
#     stubtest and mypy) against that installed package, and an import of the
#     package installed by cmake --install;
#  3. a Debug build with AddressSanitizer + UndefinedBehaviorSanitizer, and ctest;
#  4. the fuzzing of the readers (scripts/fuzz.sh: libFuzzer with clang, ASan + UBSan, 45 s per format) and of
#     the Python array path (scripts/fuzz_arrays.py, 45 s: no crash, no hang, only ValueError/TypeError);
#  5. the clang-format check of include/ src/ tools/ tests/ bench/ examples/ python/.
# Usage: scripts/test.sh            (from anywhere; builds into build/ and build-asan/)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}

scripts/install-deps.sh

echo "== Release build + tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMESHDIFF_WARNINGS_AS_ERRORS=ON -DMESHDIFF_BUILD_PYTHON=ON
cmake --build build -j"$jobs"
# html_browser (tests/html_browser_test.py: the HTML report in headless chromium) must run here, not skip.
MESHDIFF_REQUIRE_BROWSER=1 ctest --test-dir build --output-on-failure -j"$jobs"

echo "== install and build a consumer against the installed package"
tests/consumer_test.sh build

echo "== Python package: pip install into a virtual environment, pytest, stubtest, mypy"
# The interpreter CMake chose: one that imports numpy (/usr/bin/python3 on
# Debian; the python3 first on PATH may be another one without numpy).
py=$(sed -n 's/^MESHDIFF_PYTHON_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)
[[ -x "$py" ]] || { echo "no Python interpreter in build/CMakeCache.txt (MESHDIFF_PYTHON_EXECUTABLE)" >&2; exit 1; }
echo "python: $py"
# `pip install .` as a user runs it (docs/python.md), offline; MESHDIFF_CMAKE_BUILD_DIR makes the
# build backend (setup.py) reuse the Release tree built above instead of building the extension again.
venv=build/venv
rm -rf "$venv"
"$py" -m venv --system-site-packages "$venv"
start=$SECONDS
MESHDIFF_CMAKE_BUILD_DIR="$PWD/build" "$venv/bin/python" -m pip install --no-build-isolation --no-index -q .
echo "pip install: $((SECONDS - start)) s"
venv_python="$PWD/$venv/bin/python"
(cd / && "$venv_python" -c "import meshdiff; print('installed:', meshdiff.__file__)")
# The tests import the installed package (conftest.py refuses the build or source tree's); they run
# stubtest and mypy on it too (test_typing.py). pytest exits 5 when it collects no test: a failure here.
status=0
MESHDIFF_TEST_INSTALLED=1 MESHDIFF_BUILD_DIR="$PWD/build" "$venv/bin/python" -m pytest python/tests -q \
    -p no:cacheprovider || status=$?
if ((status == 5)); then
    echo "pytest collected no tests (exit 5)" >&2
    exit 1
elif ((status != 0)); then
    echo "pytest failed (exit $status)" >&2
    exit 1
fi
# cmake --install puts the package where that interpreter imports it from the prefix.
pyprefix=$(mktemp -d "${TMPDIR:-/tmp}/meshdiff-python.XXXXXX")
cmake --install build --prefix "$pyprefix" --component python > /dev/null
pydir=$(sed -n 's/^MESHDIFF_PYTHON_INSTALL_DIR:[A-Z]*=//p' build/CMakeCache.txt)
(cd / && PYTHONPATH="$pyprefix/$pydir" "$py" -c "import meshdiff, sys; \
    assert meshdiff.__file__.startswith('$pyprefix'), meshdiff.__file__; print('installed:', meshdiff.__file__)")
rm -rf "$pyprefix"

echo "== Debug build with AddressSanitizer + UndefinedBehaviorSanitizer + tests"
# -O1 keeps Eigen usable under the sanitizers; asserts stay on (no NDEBUG).
# No Python module here: an ASan-instrumented extension needs the ASan runtime
# preloaded into the (uninstrumented) interpreter, and reports the
# interpreter's own allocations; the C++ it binds is tested here through ctest.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
      -DMESHDIFF_SANITIZE=address,undefined -DMESHDIFF_BUILD_BENCH=OFF -DMESHDIFF_WARNINGS_AS_ERRORS=ON \
      -DMESHDIFF_BUILD_PYTHON=OFF
cmake --build build-asan -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$jobs"

echo "== fuzz the mesh readers (libFuzzer, ASan + UBSan, 45 s per format)"
scripts/fuzz.sh "${FUZZ_SECONDS:-45}"

echo "== fuzz the Python array path (${FUZZ_SECONDS:-45} s; the trials that ever failed first)"
MESHDIFF_BUILD_DIR="$PWD/build" "$py" scripts/fuzz_arrays.py "${FUZZ_SECONDS:-45}"

echo "== clang-format"
find include src tools tests bench examples python \( -name '*.h' -o -name '*.cpp' \) -print0 |
    xargs -0 clang-format --dry-run --Werror

echo "== all tests passed"
