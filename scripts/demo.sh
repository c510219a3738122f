#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds PruneSfM (Release) and runs the
# main job end to end on a small default input. Output goes to out/demo/.
#
# Until the reconstruction engines land (issues 4 and 5), the main job is the part of the
# pipeline that exists: generate the synthetic courtyard scene (four alike walls), convert its
# ground truth to a COLMAP model and a PLY, and evaluate the COLMAP model against the truth.
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
"$prunesfm" synth --scene courtyard --output "$out/scene" --seed 1
"$prunesfm" convert --input "$out/scene/ground_truth/sfm_data.json" --output "$out/ground_truth_colmap"
"$prunesfm" convert --input "$out/scene/ground_truth/sfm_data.json" --output "$out/ground_truth.ply"
"$prunesfm" evaluate --estimate "$out/ground_truth_colmap" \
  --ground_truth "$out/scene/ground_truth/gt_cameras.txt" --json "$out/evaluation.json"
echo "demo: outputs in $out"
