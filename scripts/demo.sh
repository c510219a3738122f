#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds PruneSfM (Release) and runs the
# main job end to end on a small default input: `prunesfm run` with no arguments, which
# reconstructs the 16 templeSparseRing images (../shared/datasets/middlebury/templeSparseRing)
# from the photos (SIFT, matching, verification, GLOBAL engine) into out/default. Without
# ../shared it says so and reconstructs the generated synthetic scene 'clean' instead.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_deps.sh
if [[ ! -x build/release/src/software/prunesfm ]]; then
  cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build/release -j "$(nproc)" --target prunesfm
prunesfm=build/release/src/software/prunesfm

rm -rf out/default
"$prunesfm" run
echo "demo: outputs in out/default (sfm_data.json, sparse/0, cloud_and_poses.ply, timings.json)"
