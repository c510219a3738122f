// What a reconstruction (pipeline/reconstruction.hpp) reads before verification: views +
// intrinsics, features, and either putative matches or already verified pairs, from an OpenMVG
// project or a COLMAP database.
#pragma once

#include <filesystem>
#include <set>
#include <string>

#include "sfm_pruning/global/verified_pairs.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

struct ReconstructionInput {
  std::string source;  // the file named in error messages
  SfmData scene;       // views and intrinsics, no poses or structure
  FeaturesPerView features;
  PairwiseMatches putative;  // to verify (used when `verified` is empty)
  VerifiedPairs verified;    // COLMAP two_view_geometries
  // Intrinsics whose focal is a guess (COLMAP's prior_focal_length = 0; `focal_trusted` false in
  // the camera_priors.json of `prunesfm init`); the others carry a focal prior (EXIF, --focal).
  std::set<IndexT> guessed_focal;
  // Intrinsics the user calibrated (`prunesfm init --k_file`): never refined by default.
  std::set<IndexT> k_file_intrinsics;
};

// sfm_data.json (views + intrinsics; guessed focals from a camera_priors.json beside it), the
// .feat files of `matches_dir` and the match file chosen
// by FindOpenMvgMatchesFile (`match_file` when given). Matches are verified again whatever
// OpenMVG did with them (its files carry no relative pose).
ReconstructionInput ReadOpenMvgInput(const std::filesystem::path& sfm_data,
                                     const std::filesystem::path& matches_dir,
                                     const std::filesystem::path& match_file,
                                     const ProgressCallback& progress);

// A COLMAP database: its two_view_geometries when it has any, its matches otherwise.
ReconstructionInput ReadColmapInput(const std::filesystem::path& database);

// Hands the pairs another tool verified (`input->verified`) to this project's own verification:
// each becomes a putative pair holding its raw matches (the database's `matches` table; its
// inliers when the database has no raw matches for it), and `verified` is emptied. Pairs the
// other tool rejected stay out. Why: COLMAP accepts inliers within 4 px of the epipolar line, so
// inside a true pair of a scene with repeated structure the matches between different copies
// that lie along the epipolar line pass and later merge copies into one track; the own
// verification's precise threshold (RelativePoseOptions) drops most of them (docs/global.md,
// "The view graph", which also says why the CLI leaves it off by default). No-op when `verified`
// is empty.
void ReverifyDatabasePairs(ReconstructionInput* input);

}  // namespace sfm_pruning
