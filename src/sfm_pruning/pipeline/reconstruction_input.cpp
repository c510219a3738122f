#include "sfm_pruning/pipeline/reconstruction_input.hpp"

#include "sfm_pruning/io/camera_priors.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"

namespace sfm_pruning {

ReconstructionInput ReadOpenMvgInput(const std::filesystem::path& sfm_data,
                                     const std::filesystem::path& matches_dir,
                                     const std::filesystem::path& match_file,
                                     const ProgressCallback& progress) {
  ReconstructionInput input;
  input.source = sfm_data.string();
  input.scene = ReadSfmData(sfm_data, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  // `prunesfm init` says beside its sfm_data.json which focal lengths are only a guess.
  const std::filesystem::path priors = sfm_data.parent_path() / kCameraPriorsFileName;
  if (std::filesystem::exists(priors)) {
    const CameraPriors camera_priors = ReadCameraPriors(priors);
    input.guessed_focal = camera_priors.IntrinsicsWithGuessedFocal();
    input.k_file_intrinsics = camera_priors.IntrinsicsFromKFile();
  }
  input.features = ReadOpenMvgFeatures(input.scene, matches_dir, false, progress);
  const std::filesystem::path matches_file = FindOpenMvgMatchesFile(matches_dir, match_file);
  MatchReadOptions options;
  options.sfm_data = &input.scene;
  options.features = &input.features;
  input.putative = ReadOpenMvgMatches(matches_file, options);
  input.source = matches_file.string();
  return input;
}

ReconstructionInput ReadColmapInput(const std::filesystem::path& database) {
  ColmapDatabase colmap = ReadColmapDatabase(database);
  ReconstructionInput input;
  input.source = database.string();
  input.scene = std::move(colmap.sfm_data);
  input.guessed_focal = std::move(colmap.intrinsics_with_guessed_focal);
  input.features = std::move(colmap.features);
  input.putative = std::move(colmap.putative);
  for (auto& [pair, geometry] : colmap.verified) {
    VerifiedPair& verified = input.verified[pair];
    verified.inliers = std::move(geometry.inliers);
    verified.relative_pose = geometry.relative_pose;
  }
  return input;
}

void ReverifyDatabasePairs(ReconstructionInput* input) {
  if (input->verified.empty()) return;
  PairwiseMatches to_verify;
  for (auto& [pair, verified] : input->verified) {
    auto raw = input->putative.find(pair);
    const bool has_raw_matches = raw != input->putative.end() && !raw->second.empty();
    to_verify[pair] = has_raw_matches ? std::move(raw->second) : std::move(verified.inliers);
  }
  input->putative = std::move(to_verify);
  input->verified.clear();
}

}  // namespace sfm_pruning
