// View-graph focal calibration: the focal lengths of cameras whose focal is only a guess (COLMAP's
// 1.2 * max(width, height) prior when the images carry no EXIF) from the fundamental matrices of
// the verified pairs, before any pose is estimated.
//
// Idea (as in GLOMAP's view-graph calibration; the code is our own): for the true intrinsics,
// E = K_j^T F K_i is an essential matrix, whose two non-zero singular values are equal. Each pair
// is fitted once, F_n, in the normalised coordinates of the current (prior) intrinsics; with the
// principal point and distortion held, a new focal f = lambda * f_prior turns it into
//   E(lambda_i, lambda_j) = diag(lambda_j, lambda_j, 1) F_n diag(lambda_i, lambda_i, 1)
// and the cost of the pair is the relative gap of its singular values,
//   g = (s1 - s2) / (s1 + s2)   (0 for an essential matrix, 1 at worst),
// under a Cauchy loss. One log(lambda) per calibrated intrinsic: a coarse grid over a shared
// lambda (the cost has local minima far from the truth), then Ceres refines each one.
//
// The focal is observable only when the pairs are not degenerate: planar scenes (F undefined:
// such pairs are skipped) and optical axes that meet in one point (a ring of cameras looking at
// its centre) leave the cost flat along the focal. A result is therefore kept only when the
// cost is clearly sharper at the estimate than a step away from it, lies inside the search range
// and beats the prior; otherwise the prior stays and the report says why.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/global/verified_pairs.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct FocalCalibrationOptions {
  // Search range of focal / prior focal.
  double min_focal_ratio = 0.2;
  double max_focal_ratio = 5.0;
  // Log-spaced candidates of the shared grid search over that range.
  int num_grid_steps = 97;
  // Cauchy scale of the singular-value gap g.
  double gap_loss_scale = 0.01;
  // Pairs with fewer inlier matches, or whose F is not defined (FundamentalMatrix definition
  // below min_f_definition: planar scene, pure rotation), are left out.
  size_t min_inliers_per_pair = 30;
  double min_f_definition = 5.0;
  // Robust scale of the F fit, in pixels.
  double sampson_scale_px = 2.0;
  // An intrinsic needs this many usable pairs to be calibrated.
  size_t min_pairs_per_intrinsic = 3;
  // Sharpness test: the cost at focal * (1 +- sharpness_step) must exceed the cost at the
  // estimate by at least this fraction of it.
  double sharpness_step = 0.1;
  double min_sharpness = 0.02;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct IntrinsicFocalCalibration {
  IndexT intrinsic_id = kUndefinedIndex;
  double prior_focal = 0.0;
  double estimated_focal = 0.0;  // of the optimisation, whether accepted or not (0: not run)
  bool accepted = false;         // the intrinsic now holds estimated_focal
  std::string reason;            // why it was not accepted (empty when accepted)
  size_t num_pairs = 0;          // usable pairs that involve it
  double median_gap_prior = 0.0;     // median g of those pairs at the prior focal
  double median_gap_estimated = 0.0; // ... and at the estimate
  double sharpness = 0.0;        // min relative cost increase one step away from the estimate
};

struct FocalCalibrationReport {
  size_t num_pairs_given = 0;
  size_t num_pairs_used = 0;
  size_t num_pairs_undefined = 0;  // F not defined by the inliers (planar / rotation only)
  std::vector<IntrinsicFocalCalibration> intrinsics;  // intrinsic id order
};

// The inlier matches of each pair, by reference (the source must outlive the map).
using PairInliers = std::map<ViewPair, const std::vector<FeatureMatch>*>;
PairInliers InliersOfPairs(const VerifiedPairs& verified);
PairInliers InliersOfEdges(const ViewGraph& graph);  // valid edges only

// `pairs`: the inlier matches of verified pairs (FeatureMatch::i in ViewPair::first). Calibrates
// the focal of each intrinsic of `calibrate` (ids of scene->intrinsics, pinhole family) and
// writes the accepted ones into scene->intrinsics; other intrinsics are held as they are.
// Deterministic (no random choice). Never prints. Throws std::invalid_argument when options.Check() does.
FocalCalibrationReport CalibrateFocalLengths(const FocalCalibrationOptions& options, const std::set<IndexT>& calibrate,
                                             const PairInliers& pairs, const FeaturesPerView& features,
                                             SfmData* scene);

}  // namespace sfm_pruning
