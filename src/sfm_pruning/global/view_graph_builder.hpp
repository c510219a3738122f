// View-graph construction (METHOD.md §1): putative matches -> two-view verification per pair
// (geometry/two_view_geometry.hpp) -> ViewGraph of the accepted pairs, restricted to its largest
// connected component. Every rejected pair and every dropped view is reported with its reason.
//
// Pairs are verified in parallel (num_threads workers take pairs in turn) but results are
// gathered in pair order, and each pair's RANSAC seed depends only on the base seed and the two
// view ids, so the graph does not depend on the number of threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sfm_pruning/geometry/two_view_geometry.hpp"
#include "sfm_pruning/global/verified_pairs.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct ViewGraphBuildOptions {
  // Acceptance (min_num_inliers = 30, min_inlier_ratio = 0.25, GLOMAP's values) and the RANSAC /
  // refinement settings. two_view.relative_pose.ransac.seed is ignored: see `seed`.
  TwoViewGeometryOptions two_view;
  // Base seed; pair (a, b) uses PairSeed(seed, a, b).
  uint64_t seed = 0;
  // Worker threads for the verification; results do not depend on it. <= 0 means 1.
  int num_threads = 1;
  // Remove every view outside the largest connected component (reported in dropped_views).
  bool keep_largest_component = true;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RejectedPair {
  ViewPair pair;
  std::string reason;  // the estimator's reason ("too few inliers ...", "RANSAC found no model")
  size_t num_matches = 0;
  size_t num_inliers = 0;
};

struct DroppedView {
  IndexT view_id = kUndefinedIndex;
  std::string reason;  // e.g. "no intrinsics", "no verified pair", "outside the largest component"
};

struct ViewGraphBuildReport {
  size_t num_pairs = 0;          // pairs given
  size_t num_verified_pairs = 0;  // accepted as edges (before the component selection)
  size_t num_edges = 0;           // edges of the returned graph
  std::vector<RejectedPair> rejected_pairs;  // pair order
  std::vector<DroppedView> dropped_views;    // view id order
};

// RANSAC seed of the pair (a, b): a hash of the base seed and both ids (order-independent).
uint64_t PairSeed(uint64_t base_seed, IndexT a, IndexT b);

// Verifies every pair of `putative` whose views have intrinsics and features (pairs naming
// anything else are rejected with the reason). Nodes: every view of `views_and_intrinsics`.
// Edges: accepted pairs with their inlier matches and relative pose, weight = inliers.
// Throws Error when a match names a feature that does not exist, std::invalid_argument when
// options.Check() does. Progress stage: "verifying pairs".
ViewGraph BuildViewGraphFromMatches(const ViewGraphBuildOptions& options, const SfmData& views_and_intrinsics,
                                    const FeaturesPerView& features, const PairwiseMatches& putative,
                                    ViewGraphBuildReport* report = nullptr, const ProgressCallback& progress = {});

// The same from already verified pairs: a pair with a relative pose is accepted when it has at
// least min_num_inliers inliers; a pair without one gets its pose re-estimated from its inliers
// with the same estimator and thresholds (edge matches = the re-estimation's inliers). Throws as
// BuildViewGraphFromMatches.
ViewGraph BuildViewGraphFromVerifiedPairs(const ViewGraphBuildOptions& options, const SfmData& views_and_intrinsics,
                                          const FeaturesPerView& features, const VerifiedPairs& verified,
                                          ViewGraphBuildReport* report = nullptr,
                                          const ProgressCallback& progress = {});

}  // namespace sfm_pruning
