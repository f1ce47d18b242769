#!/usr/bin/env bash
# Installs a configured and built meshdiff build tree into a temporary prefix,
# checks the installed package (headers, CMake config, version check), builds
# tests/consumer (examples/compare_meshes.cpp) against it with find_package and
# runs it; checks that docs/library.md shows that example unchanged.
# Usage: tests/consumer_test.sh BUILD_DIR      (temporary files under $TMPDIR)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[[ $# -eq 1 && -d "$1" ]] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
build="$(cd "$1" && pwd)"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/meshdiff-consumer.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
data="$root/tests/data"
fail() {
    echo "FAIL: $*" >&2
    exit 1
}

echo "-- install $build into $prefix"
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log" >&2; fail "install"; }
[[ -f "$prefix/include/meshdiff/version.h" ]] || fail "no include/meshdiff/version.h"
[[ -f "$prefix/include/meshdiff/distance/surface_distance.h" ]] || fail "no include/meshdiff/distance/surface_distance.h"
grep -q '^#define MESHDIFF_VERSION "' "$prefix/include/meshdiff/version.h" || fail "version.h has no MESHDIFF_VERSION"
cfg=""
for d in "$prefix"/lib*/cmake/meshdiff; do [[ -f "$d/meshdiffConfig.cmake" ]] && cfg="$d"; done
[[ -n "$cfg" ]] || fail "no lib*/cmake/meshdiff/meshdiffConfig.cmake"
[[ -f "$cfg/meshdiffConfigVersion.cmake" ]] || fail "no meshdiffConfigVersion.cmake"
[[ -f "$cfg/meshdiffTargets.cmake" ]] || fail "no meshdiffTargets.cmake"

echo "-- find_package(meshdiff X) must fail for an incompatible version"
mkdir "$tmp/version"
cat >"$tmp/version/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(meshdiff_version_check NONE)
find_package(meshdiff ${WANT} REQUIRED)
CMAKE
for want in 9.0 0.1; do
    if cmake -S "$tmp/version" -B "$tmp/version/build-$want" -DWANT="$want" -DCMAKE_PREFIX_PATH="$prefix" \
        >"$tmp/version.log" 2>&1; then
        fail "find_package(meshdiff $want) succeeded"
    fi
    grep -q "compatible with requested version \"$want\"" "$tmp/version.log" || {
        cat "$tmp/version.log" >&2
        fail "find_package(meshdiff $want) failed, but not on the version"
    }
done

echo "-- build tests/consumer against the installed package"
# The consumer's own warnings as errors: the public headers must compile cleanly.
cmake -S "$root/tests/consumer" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_CXX_FLAGS="-Wall -Wextra -Werror" >"$tmp/configure.log" || { cat "$tmp/configure.log" >&2; fail "configure"; }
found="$(sed -n 's/^meshdiff_DIR:PATH=//p' "$tmp/consumer/CMakeCache.txt")"
[[ "$found" -ef "$cfg" ]] || fail "the consumer found meshdiff in '$found', not in $cfg"
cmake --build "$tmp/consumer" -j"${JOBS:-2}" >"$tmp/build.log" || { cat "$tmp/build.log" >&2; fail "build"; }

app="$tmp/consumer/compare_meshes"
out="$("$app" "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply")" || fail "compare_meshes exited with $?"
echo "$out"
for line in '^meshdiff [0-9]+\.[0-9]+\.[0-9]+: ' '^levels: 20 \+ global$' '^  d_1  = [0-9.]+$' '^  d_G  = [0-9.]+$' \
    '^forward max: ' '^backward max: ' '^Hausdorff: .* of the diagonal '; do
    grep -Eq "$line" <<<"$out" || fail "no line matching /$line/"
done

echo "-- meshdiff::report: the comparison as meshdiff.compare/2 JSON"
json_out="$("$tmp/consumer/compare_json" "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply")" ||
    fail "compare_json exited with $?"
echo "$json_out"
grep -Eq '^meshdiff.compare/2 hausdorff [0-9.e-]+$' <<<"$json_out" || fail "compare_json output"

echo "-- the 0.2 include paths forward to the subsystem folders"
for f in "$root"/include/compat/meshdiff/*.h; do
    h="meshdiff/$(basename "$f")"
    [[ -f "$prefix/include/$h" ]] || fail "$h is not installed"
    grep -q "^#include \"$h\"" "$root/tests/consumer/old_paths.cpp" || fail "tests/consumer/old_paths.cpp misses $h"
done
"$tmp/consumer/old_paths" || fail "old_paths exited with $?"

echo "-- a missing file: nonzero exit and a message"
set +e
"$app" "$tmp/no_such_mesh.ply" "$data/bunny_res3.ply" >"$tmp/missing.out" 2>"$tmp/missing.err"
code=$?
set -e
[[ $code -ne 0 ]] || fail "compare_meshes exited 0 on a missing file"
grep -q "^error: .*no_such_mesh.ply" "$tmp/missing.err" || { cat "$tmp/missing.err" >&2; fail "no error message"; }
echo "exit $code: $(cat "$tmp/missing.err")"

echo "-- docs/library.md shows examples/compare_meshes.cpp"
"$root/tests/doc_example_test.sh" "$root/docs/library.md"

echo "consumer test passed"
