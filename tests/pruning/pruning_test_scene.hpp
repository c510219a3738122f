// Exact synthetic data for the pruning tests: ground-truth cameras around a point cloud, split
// into two subgraphs whose solutions live in their own frames (a known similarity each), with
// features = exact projections (feature id = point id) and a view graph of exact edges.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/sfm/similarity.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning::testing {

// A subgraph frame: x_k = frame.Apply(x_world).
using Similarity = Similarity3;

struct PruningTestScene {
  std::vector<Pose> poses;              // ground truth, by view id 0..n-1
  std::vector<Eigen::Vector3d> points;  // ground truth, by point id
  SfmData views_and_intrinsics;         // views 0..n-1, one pinhole intrinsic
  FeaturesPerView features;             // feature id = point id (extra features appended)
  ViewGraph graph;

  // Adds edge (a, b) with exact relative pose (|t| = 1) and matches over the first
  // `num_points` points (all when 0).
  void AddExactEdge(IndexT a, IndexT b, size_t num_points = 0);
  // Adds edge (i, j) whose matches pair i's feature of point p with a new feature of j placed
  // at the projection of twin(X_p): a repeated structure, so PnP puts j at a wrong pose.
  // Only the first `num_points` points are copied (all when 0): the rest is unique texture.
  void AddTwinEdge(IndexT i, IndexT j, const Similarity& twin, size_t num_points = 0);
  // The solution of the subgraph `view_ids` in the frame `frame`: poses and every point,
  // observed by every view of the subgraph.
  SubgraphSolution Solution(const std::vector<IndexT>& view_ids, const Similarity& frame) const;
};

// `num_views` cameras on an arc of radius 8 looking at a cloud of `num_points` points within
// radius 2 of the origin; seeded.
PruningTestScene MakePruningTestScene(size_t num_views, size_t num_points, uint64_t seed);

Similarity RandomSimilarity(uint64_t seed, double scale);

// The ground truth as a model: the scene's views posed exactly, every point a landmark that every
// view observes (feature id = point id).
SfmData GroundTruthModel(const PruningTestScene& scene);

}  // namespace sfm_pruning::testing
