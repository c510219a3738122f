// How much the kept edges of a pair of subgraphs look like true edges: the order in which the
// loop check trusts the pairs (ViewGraphPruningOptions::link_trust, SubgraphLink::trust,
// SubgraphPairLink::trust).
#pragma once

#include <map>
#include <vector>

#include "sfm_pruning/pruning/recursive_partition.hpp"
#include "sfm_pruning/pruning/subgraph_alignment.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

enum class PairTrustMeasure {
  // The match coverage of the pair's selected RANSAC hypothesis (0 without one).
  kMatchCoverage,
  // The mean distinctiveness of the inliers of the given edges (view_graph/distinctive_weights.hpp)
  // over that of the edges inside the accepted subgraphs.
  kDistinctiveShare,
};

class PairTrust {
 public:
  // `graph`: the graph the subgraphs were partitioned from (feature match counts are taken on it).
  PairTrust(PairTrustMeasure measure, const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted);

  // The trust of a pair keeping `edges` (either orientation; valid edges of the graph) whose RANSAC
  // selected `selected` (nullptr: none).
  double Of(const std::vector<ViewPair>& edges, const AlignmentHypothesis* selected) const;

  // kDistinctiveShare: the mean distinctiveness of the inliers inside the subgraphs (the unit of
  // the trust); 0 otherwise.
  double ReferenceShare() const { return reference_share_; }

 private:
  double Share(const std::vector<ViewPair>& edges) const;

  PairTrustMeasure measure_;
  const ViewGraph& graph_;
  std::map<ViewPair, double> edge_weights_;  // kDistinctiveShare: DistinctiveMatchWeights
  double reference_share_ = 0.0;
};

}  // namespace sfm_pruning
