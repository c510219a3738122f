#!/usr/bin/env bash
# The test command: installs the dependencies (Debian packages, by name), builds PruneSfM from
# scratch with warnings as errors, runs every test, then rebuilds with ASan+UBSan and runs the
# unit tests again. Usage: scripts/test.sh [--no-sanitizers]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=$(nproc)

bash scripts/install_deps.sh

echo "== Release build (warnings are errors)"
rm -rf build/release
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRUNESFM_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build build/release -j "$jobs"
echo "== Tests (Release)"
(cd build/release && ctest --output-on-failure -j "$jobs" --timeout 1200)

if [[ "${1:-}" != "--no-sanitizers" ]]; then
  echo "== ASan+UBSan build"
  rm -rf build/sanitize
  cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPRUNESFM_SANITIZE=ON \
    -DPRUNESFM_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build/sanitize -j "$jobs"
  echo "== Unit tests under ASan+UBSan (label 'slow' and interop excluded)"
  (cd build/sanitize && ASAN_OPTIONS=alloc_dealloc_mismatch=0:detect_leaks=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --output-on-failure -j "$jobs" --timeout 1200 -LE "slow|interop")
fi
echo "== All tests passed ($root)"
