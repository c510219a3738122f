// The edges the pruning kept, judged by the correspondences they miss in the model solved from the
// pruned graph (PruneSfM's addition to the paper, after Zach et al. 2008, "What can missing
// correspondences tell us about 3D structure and motion?"; docs/pruning.md, "Missing
// correspondences").
//
// Why: a twin edge that survives the pruning joins two places whose repeated structure is alike but
// whose surroundings are not. The solve that follows has to place its two views so that their twin
// matches meet, which puts the landmarks the other view does see into the view of each: the unique
// texture around the first copy projects into the second view's image, where the view observes the
// surroundings of the second copy instead. A true edge's two views see each other's landmarks
// wherever the model says they can, up to the detection and matching rate that every true edge of
// the scene shares. So the share of the predicted landmarks that a view actually observes is
// lower on a twin edge than on the true edges of the same model, and the true edges give the scale
// of its spread: no fixed rate, the scene's own (the detection rate, clutter and texture vary from
// scene to scene).
//
// How: for every kept edge between two subgraphs with both views posed, each landmark that one view
// observes is predicted in the other when it lies in front of it, inside its image, seen from a
// direction within max_viewing_angle_deg of the observing view's and from a distance within a
// factor max_distance_ratio of it (beyond that a feature detector does not find the same point).
// The edge's observed share is that of its better direction: the predicted landmarks the other view
// observes, over the predicted ones. Both views of a misplaced pair miss the other's landmarks; where
// only one does, the prediction is what failed (a surface the one view sees at a grazing angle, an
// occluder, both of which the model does not know). An edge of at least min_predicted_landmarks in
// each direction whose share lies more than
// max_robust_deviations robust standard deviations (1.4826 x the median absolute deviation) below
// the median share of such edges is removed, lowest share first, unless its removal would cut views
// off from the rest (their only placement). Removing edges changes the model, so the caller solves
// again and judges again, for at most max_rounds rounds (PruneAndAudit, view_graph_pruning.cpp).
//
// What it cannot see: a model that folds all copies onto one (every view of each copy on top of the
// other copies' views) predicts the landmarks of copies that look alike, and the few unique ones
// are then within the spread of the true edges; edges between views of one subgraph (they passed
// the subgraph's consistency tests) are not judged.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct MissingCorrespondenceOptions {
  bool enabled = true;
  // Solve, judge and remove; again while a round removes edges, at most this many times (each round
  // costs one solve of the pruned graph; 0: off).
  size_t max_rounds = 3;
  double max_viewing_angle_deg = 45.0;
  double max_distance_ratio = 2.0;
  // An edge with fewer predicted landmarks in either direction is not judged.
  size_t min_predicted_landmarks = 15;
  double max_robust_deviations = 3.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// The landmarks one view observes that the model predicts in the other, and those of them the other
// view observes.
struct ObservedLandmarks {
  size_t predicted = 0;
  size_t observed = 0;
  double Share() const {
    return predicted > 0 ? static_cast<double>(observed) / static_cast<double>(predicted) : 0.0;
  }
};

// One edge (first, second): the landmarks of `first` predicted in `second` (to_second) and those of
// `second` predicted in `first` (to_first).
struct EdgeObservedShare {
  ViewPair pair{kUndefinedIndex, kUndefinedIndex};
  ObservedLandmarks to_second;
  ObservedLandmarks to_first;
  size_t MinPredicted() const { return std::min(to_second.predicted, to_first.predicted); }
  // The better direction's share (see the top of the file).
  double Share() const { return std::max(to_second.Share(), to_first.Share()); }
};

// One round: the edges measured, the median share of the judged ones and the bound below which an
// edge was removed (median - max_robust_deviations x the robust standard deviation).
struct MissingCorrespondenceRound {
  std::vector<EdgeObservedShare> edges;
  size_t num_judged = 0;
  double median_share = 0.0;
  double bound = 0.0;
  // The judged edges below the bound, in the order of `edges`; the caller keeps those it needs to keep
  // views connected and leaves the ones it removed, in the order it removed them.
  std::vector<ViewPair> removed;
};

// One entry per pair of `edges` with both views posed in `model`, in order.
std::vector<EdgeObservedShare> MeasureObservedShares(const SfmData& model, const std::vector<ViewPair>& edges,
                                                     const MissingCorrespondenceOptions& options);

// The round's verdict on `edges` (MeasureObservedShares): which to remove.
MissingCorrespondenceRound JudgeObservedShares(std::vector<EdgeObservedShare> edges,
                                               const MissingCorrespondenceOptions& options);

}  // namespace sfm_pruning
