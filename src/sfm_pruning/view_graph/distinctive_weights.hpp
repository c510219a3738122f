// Feature distinctiveness from the view graph's own matches (not in the paper; METHOD.md lets a
// measured improvement replace the paper's choice behind an option; docs/pruning.md).
//
// On scenes whose repeated structure fills the views (a street of identical facades, four alike
// walls) a view matches the views of every copy about as strongly as its true neighbours, so the
// inlier count groups views by what they look at, not by where they stand, and a twin edge
// "matches" most of what its placed view should see. What tells the copies apart is the unique
// texture (the street surface, a sign, a door): its features are matched only by the views of one
// place, while a feature of the repeated structure is matched by the views of every copy. So a
// feature weighs the inverse of the number of edges that match it, as a word frequent in every
// document weighs little in retrieval (inverse document frequency). A clean scene keeps its
// locality: a feature is matched only by the views that see it.
#pragma once

#include <cstdint>
#include <map>
#include <unordered_map>

#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

class FeatureDistinctiveness {
 public:
  // Counts, for every feature, the valid edges of `graph` whose inliers contain it (matches of one
  // pair are one-to-one, so an edge counts a feature once).
  explicit FeatureDistinctiveness(const ViewGraph& graph);

  // 1 / (edges matching feature `feature` of view `view_id`); 1 for a feature no edge matches.
  double Weight(IndexT view_id, IndexT feature) const;

 private:
  std::unordered_map<uint64_t, uint32_t> match_counts_;
};

// For every valid edge of `graph`: Σ over its inlier matches (f_a, f_b) of
// (Weight(a, f_a) + Weight(b, f_b)) / 2. A match of two features that only this edge matches
// weighs 1, as in the inlier count.
std::map<ViewPair, double> DistinctiveMatchWeights(const ViewGraph& graph, const FeatureDistinctiveness& distinctiveness);

}  // namespace sfm_pruning
