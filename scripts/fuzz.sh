#!/usr/bin/env bash
# Fuzzes every file parser with libFuzzer (tests/fuzz: one target per parser). Builds the targets
# with clang, ASan and UBSan into build/fuzz, gives each a seed corpus (small files of every format
# written by fuzz_seed_corpus, plus the real files of ../shared/formats when present), then runs
# each target.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]
#   0 (the default; scripts/test.sh runs it): a smoke pass, every seed once.
#   N > 0: fuzz each target for N seconds (600 is the bar the project holds itself to). Inputs that
#   reach new code are kept in build/fuzz/corpus/TARGET for the next run.
#   TARGET...: only these (e.g. fuzz_ply); two runs on disjoint targets use two cores.
# A crash, an exception other than the readers' Error, a hang (an input over 10 s), a leak or more
# than 2 GB of memory is written to build/fuzz/findings/ and makes the script fail.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-0}
shift || true
only=("$@")
build=build/fuzz
shared=${PRUNESFM_SHARED_DIR:-../shared}/formats

echo "== Fuzz targets (clang, libFuzzer, ASan+UBSan) in $build"
mkdir -p "$build"
(  # one build at a time when several runs start together
  flock 9
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DPRUNESFM_FUZZ=ON >/dev/null
  cmake --build "$build" -j "$(nproc)" --target prunesfm_fuzz_targets
) 9>"$build/.build.lock"

seeds=$build/seeds
if [[ ${#only[@]} -gt 0 ]]; then
  seeds=$build/seeds-$$  # runs on other targets may be using build/fuzz/seeds
fi
rm -rf "$seeds"
mkdir -p "$build/findings"
"$build/tests/fuzz/fuzz_seed_corpus" "$seeds"

# The real files written by other tools, as seeds of the parser that reads them.
copy_seed() {  # TARGET FILE...
  local target=$1 file
  shift
  for file in "$@"; do
    if [[ -f $file ]]; then cp "$file" "$seeds/$target/$(echo "${file#"$shared"/}" | tr / _)"; fi
  done
}
join_seed() {  # TARGET NAME FILE... : the files of one multi-file input, joined as fuzz_input.hpp splits them
  local target=$1 name=$2 file first=1
  shift 2
  for file in "$@"; do [[ -f $file ]] || return 0; done
  for file in "$@"; do
    if [[ $first == 0 ]]; then printf '\n--prunesfm-fuzz-part--\n'; fi
    cat "$file"
    first=0
  done > "$seeds/$target/$name"
}
for file in tests/data/openmvg_json/*.json; do cp "$file" "$seeds/fuzz_sfm_data_json/"; done
if [[ -d $shared ]]; then
  castle=$shared/openmvg/sceaux_castle/matches
  copy_seed fuzz_sfm_data_json "$castle/sfm_data.json"
  copy_seed fuzz_image_describer "$castle/image_describer.json"
  copy_seed fuzz_pair_list "$castle/pairs.bin"
  copy_seed fuzz_openmvs_scene "$shared/openmvs/scene.mvs"
  join_seed fuzz_openmvg_features castle_100_7109 "$castle/100_7109.feat" "$castle/100_7109.desc"
  join_seed fuzz_openmvg_matches castle_e "$castle/matches.e.bin"
  for version in colmap-3.8 colmap-4.1.1; do
    copy_seed fuzz_colmap_database "$shared/colmap/$version/database.db"
    for encoding in bin txt; do
      model=$shared/colmap/$version/sparse_$encoding
      target=fuzz_colmap_model_$([[ $encoding == bin ]] && echo binary || echo text)
      join_seed "$target" "$version" "$model/cameras.$encoding" "$model/images.$encoding" "$model/points3D.$encoding"
    done
  done
else
  echo "fuzz: $shared not found: seeds are the generated files only"
fi

failed=()
for target_path in "$build"/tests/fuzz/fuzz_*; do
  target=$(basename "$target_path")
  [[ $target == fuzz_seed_corpus || ! -x $target_path ]] && continue
  if [[ ${#only[@]} -gt 0 && ! " ${only[*]} " == *" $target "* ]]; then continue; fi
  corpus=$build/corpus/$target
  mkdir -p "$corpus"
  options=(-timeout=10 -rss_limit_mb=2048 "-artifact_prefix=$build/findings/$target-" -print_final_stats=0)
  if [[ $seconds -gt 0 ]]; then
    options+=("-max_total_time=$seconds" -max_len=262144)
  else
    options+=(-runs=0)
  fi
  if "$target_path" "${options[@]}" "$corpus" "$seeds/$target" >"$build/findings/$target.log" 2>&1; then
    echo "fuzz: $target: $(find "$seeds/$target" "$corpus" -type f | wc -l) inputs, no finding"
  else
    echo "fuzz: $target: FAILED (log: $build/findings/$target.log)"
    tail -n 30 "$build/findings/$target.log"
    failed+=("$target")
  fi
done
if [[ ${#only[@]} -gt 0 ]]; then rm -rf "$seeds"; fi
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: findings in ${failed[*]}"
  exit 1
fi
echo "== Fuzzing found nothing ($([[ $seconds -gt 0 ]] && echo "$seconds s per target" || echo "smoke pass over the seeds"))"
