#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds PruneSfM (Release) and runs the
# main job end to end on a small default input. Output goes to out/demo/.
#
# Until the image front end lands (issue 6), the default input is a generated scene: the
# synthetic `clean` scene (features + putative matches + ground truth) is reconstructed with the
# GLOBAL engine and the result is evaluated against the truth and exported.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}

bash scripts/install_deps.sh
if [[ ! -x build/release/src/software/prunesfm ]]; then
  cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build/release -j "$(nproc)" --target prunesfm
prunesfm=build/release/src/software/prunesfm

rm -rf "$out"
"$prunesfm" synth --scene clean --output "$out/scene" --seed 1
"$prunesfm" reconstruct --engine GLOBAL --sfm_data "$out/scene/sfm_data.json" \
  --matches_dir "$out/scene/matches" --output "$out/reconstruction"
"$prunesfm" evaluate --estimate "$out/reconstruction/sparse/0" \
  --ground_truth "$out/scene/ground_truth/gt_cameras.txt" --json "$out/evaluation.json"
"$prunesfm" convert --input "$out/reconstruction/sfm_data.json" --output "$out/model.ply"
echo "demo: outputs in $out"
