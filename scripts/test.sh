#!/usr/bin/env bash
# The test command: installs the dependencies (Debian packages, by name), builds PruneSfM from
# scratch with warnings as errors and ASan+UBSan, runs every test in that build, then passes every
# seed of the parsers' fuzz targets once (scripts/fuzz.sh, a clang build of the readers only).
#
# Why one build: on CI's 2 cores a from-scratch Release build takes about 15 minutes, so a Release
# build plus a separate -O0 sanitizer build (whose end-to-end tests crawl) did not fit the
# 30-minute budget. The -O1 sanitizer build (cmake/PruneSfMFlags.cmake: UBSan without the
# per-access pointer checks) compiles about as fast as Release; the sanitizers do not change
# floating-point results, so the accuracy assertions of the end-to-end tests hold there just as
# in Release, and every test, slow and interop included, runs under ASan+UBSan.
#
# Usage: scripts/test.sh [--no-sanitizers]   (--no-sanitizers: a plain Release build instead)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=$(nproc)

bash scripts/install_deps.sh

if [[ "${1:-}" == "--no-sanitizers" ]]; then
  build=build/release
  echo "== Release build (warnings are errors)"
  rm -rf "$build"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRUNESFM_WARNINGS_AS_ERRORS=ON \
    -DCMAKE_INSTALL_PREFIX="$root/$build/install" >/dev/null
else
  build=build/sanitize
  echo "== ASan+UBSan build at -O1 (warnings are errors)"
  rm -rf "$build"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DPRUNESFM_SANITIZE=ON -DPRUNESFM_WARNINGS_AS_ERRORS=ON -DCMAKE_INSTALL_PREFIX="$root/$build/install" >/dev/null
fi
cmake --build "$build" -j "$jobs"

echo "== Tests ($build)"
export ASAN_OPTIONS=alloc_dealloc_mismatch=0:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$build" && ctest --output-on-failure -j "$jobs" --timeout 1200)
echo "== The installed package in another project (examples/consumer: find_package(PruneSfM), GLOBAL_PRUNED)"
rm -rf "$build/install" "$build/consumer"
cmake --install "$build" >/dev/null
cmake -S examples/consumer -B "$build/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$root/$build/install" >/dev/null
cmake --build "$build/consumer"
"$build/consumer/prunesfm_consumer"
# Every parser's fuzz target over its seeds once (a real fuzzing run: scripts/fuzz.sh 600).
bash scripts/fuzz.sh
echo "== All tests passed ($root, $build and build/fuzz)"
