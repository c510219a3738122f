// Small view graphs for the view_graph tests, built from explicit structure or from absolute
// poses so that relative poses are consistent by construction.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning::testing {

// Adds edge (a, b) with `weight` and an identity relative pose (structure-only tests).
void AddWeightedEdge(ViewGraph* graph, IndexT a, IndexT b, double weight);

struct WeightedPair {
  IndexT a = 0;
  IndexT b = 0;
  double weight = 0.0;
};
// AddWeightedEdge for each entry, in order.
void AddWeightedEdges(ViewGraph* graph, const std::vector<WeightedPair>& edges);

// Every pair (a, b), a < b < num_nodes, in ViewPair order (the complete graph).
std::vector<ViewPair> AllPairs(IndexT num_nodes);

// Complete graph on `ids`, every edge of weight `weight`.
void AddClique(ViewGraph* graph, const std::vector<IndexT>& ids, double weight);

// Erdos-Renyi graph on ids 0..n-1: each pair present with probability `p`, integer weights
// uniform in [1, 100] (like inlier counts), from std::mt19937(seed).
ViewGraph RandomGraph(size_t num_nodes, double edge_probability, uint32_t seed);

// Random absolute poses for ids 0..n-1 (rotations up to 180°, centres in a 10 m cube).
std::map<IndexT, Pose> RandomPoses(size_t num_nodes, uint32_t seed);

// Adds every pair in `pairs` with the relative pose implied by `poses` (sfm/pose.hpp),
// translation normalised to |t| = 1, and `num_matches` synthetic matches (weight).
void AddEdgesFromPoses(ViewGraph* graph, const std::map<IndexT, Pose>& poses,
                       const std::vector<ViewPair>& pairs, size_t num_matches = 50);

}  // namespace sfm_pruning::testing
