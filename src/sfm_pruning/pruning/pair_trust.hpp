// How much the kept edges of a pair of subgraphs look like true edges: the order in which the
// loop check trusts the pairs (ViewGraphPruningOptions::link_trust, SubgraphLink::trust,
// SubgraphPairLink::trust). Both signals a twin cannot fake are measured against the edges inside
// the accepted subgraphs, i.e. against what a true edge shows on this very scene (a synthetic
// matcher re-detects most of what it should, SIFT on photos far less).
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
  // The mean distinctiveness of the inliers of the pair's edges (view_graph/distinctive_weights.hpp)
  // over that of the edges inside the accepted subgraphs.
  kDistinctiveShare,
};

class PairTrust {
 public:
  // `graph`: the graph the subgraphs were partitioned from (feature match counts are taken on it);
  // `views_and_intrinsics` and `placement`: as for AlignSubgraphPair (the reference coverage).
  // `prior_edges`: ViewGraphPruningOptions::trust_prior_edges (kDistinctiveShare only).
  PairTrust(PairTrustMeasure measure, const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted,
            const SfmData& views_and_intrinsics, const EdgePlacementOptions& placement, double prior_edges = 0.0);

  // The trust of an aligned pair's kept edges, or of all its connecting edges (`all_edges`: a pair
  // without a transform keeps all of them if it is kept at all).
  double Of(const SubgraphAlignmentResult& alignment, bool all_edges) const;

  // The match coverage of those edges (matched / expected landmarks over the placed ones) over that
  // of the edges inside the subgraphs: a twin edge misses the unique texture its placed view should
  // see. -1 when none of them expected anything (or nothing inside did).
  double RelativeCoverageOf(const SubgraphAlignmentResult& alignment, bool all_edges) const;

  // What the edges inside the subgraphs show: the unit of the trust (0 when not measured).
  double ReferenceShare() const { return reference_share_; }
  double ReferenceCoverage() const { return reference_coverage_; }

 private:
  double Share(const std::vector<ViewPair>& edges) const;

  PairTrustMeasure measure_;
  double prior_edges_ = 0.0;
  const ViewGraph& graph_;
  std::map<ViewPair, double> edge_weights_;  // DistinctiveMatchWeights (kDistinctiveShare only)
  double reference_share_ = 0.0;
  double reference_coverage_ = 0.0;
};

}  // namespace sfm_pruning
