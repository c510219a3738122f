// COLMAP's database.db (SQLite): read both the 3.x and the 4.x schema, write the 3.8 schema,
// and copy a database keeping only some of its two-view geometries (the pruning filter).
//
// Id mapping as for models: view id = pose id = image_id, intrinsic id = camera_id. Keypoints are
// shifted to our pixel convention (colmap_camera.hpp). Matches are stored by COLMAP with the
// smaller image id first, which is our ViewPair order, so FeatureMatch::i indexes the features
// of ViewPair::first.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// COLMAP's two-view geometry `config` values.
enum class ColmapTwoViewConfig : int {
  kUndefined = 0,
  kDegenerate = 1,
  kCalibrated = 2,
  kUncalibrated = 3,
  kPlanar = 4,
  kPanoramic = 5,
  kPlanarOrPanoramic = 6,
  kWatermark = 7,
  kMultiple = 8,
};

// One row of two_view_geometries, for the pair (first, second) with first < second.
struct ColmapTwoViewGeometry {
  std::vector<FeatureMatch> inliers;
  int config = 0;  // a ColmapTwoViewConfig value
  // For pixel coordinates in COLMAP's convention: x_second^T F x_first = 0; E relates the
  // normalized coordinates the same way. H maps first to second. Zero when not estimated.
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  // Camera-first -> camera-second (pose.hpp's RelativePose), when COLMAP computed it (its qvec /
  // tvec; absent when NULL or all zero, as written without --SiftMatching.compute_relative_pose).
  std::optional<RelativePose> relative_pose;
};

struct ColmapDatabase {
  SfmData sfm_data;  // views and intrinsics only; root_path empty, no poses
  // Cameras whose focal COLMAP guessed (cameras.prior_focal_length = 0: no EXIF, 1.2 * max(w, h));
  // the others' focal is trusted.
  std::set<IndexT> intrinsics_with_guessed_focal;
  FeaturesPerView features;
  PairwiseMatches putative;  // pairs of the matches table with at least one match
  // Pairs of two_view_geometries with at least one inlier; COLMAP's empty rows (pairs whose
  // verification failed) are skipped.
  std::map<ViewPair, ColmapTwoViewGeometry> verified;
};

// COLMAP's pair id of two image ids (smaller id first) and back.
uint64_t ColmapPairId(IndexT image_id1, IndexT image_id2);
ViewPair ColmapPairFromId(uint64_t pair_id);

// Reads database.db (opened read-only). Throws Error naming the file when it is missing, not an
// SQLite database, lacks a COLMAP table, or holds blobs of the wrong size or unsupported models.
// Pose priors (3.x prior_* columns, 4.x pose_priors) and 4.x rigs/frames are not read.
ColmapDatabase ReadColmapDatabase(const std::filesystem::path& path);

// Writes a new database in COLMAP 3.8's schema, atomically (an existing file is replaced):
// cameras (prior_focal_length = 0 for intrinsics_with_guessed_focal, 1 otherwise), images (named RelativeImagePath()),
// keypoints (4 columns: x y scale orientation), descriptors (views that have them), matches and
// two_view_geometries. Every view needs an intrinsic; ids must be below 2147483647.
void WriteColmapDatabase(const ColmapDatabase& database, const std::filesystem::path& path);

// Copies database `input` to `output` (atomically; they may be the same file) with only the
// two_view_geometries rows of the pairs in `keep`, and without the inliers `drop` lists for a
// pair (FeatureMatch i of the pair's first image, j of its second; inliers not in the row are
// ignored). Everything else is copied byte for byte, whatever the schema version.
void CopyColmapDatabaseKeepingPairs(const std::filesystem::path& input, const std::filesystem::path& output,
                                    const std::set<ViewPair>& keep,
                                    const std::map<ViewPair, std::vector<FeatureMatch>>& drop = {});

// Copies database `input` to `output` (atomically) with `verified` as its two_view_geometries in
// place of the rows it had; everything else is copied byte for byte. For a database whose matches
// another tool has not verified (`prunesfm prune` writes its own verification's pairs).
void CopyColmapDatabaseWithGeometries(const std::filesystem::path& input, const std::filesystem::path& output,
                                      const std::map<ViewPair, ColmapTwoViewGeometry>& verified);

}  // namespace sfm_pruning
