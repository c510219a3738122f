#include "sfm_pruning/pruning/pair_trust.hpp"

#include "sfm_pruning/view_graph/distinctive_weights.hpp"

namespace sfm_pruning {

PairTrust::PairTrust(PairTrustMeasure measure, const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted)
    : measure_(measure), graph_(graph) {
  if (measure_ != PairTrustMeasure::kDistinctiveShare) return;
  edge_weights_ = DistinctiveMatchWeights(graph, FeatureDistinctiveness(graph));
  std::map<IndexT, size_t> subgraph_of;
  for (size_t k = 0; k < accepted.size(); ++k) {
    for (IndexT view : accepted[k].solution.view_ids) subgraph_of[view] = k;
  }
  std::vector<ViewPair> inside;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    const auto a = subgraph_of.find(pair.first);
    const auto b = subgraph_of.find(pair.second);
    if (a != subgraph_of.end() && b != subgraph_of.end() && a->second == b->second) inside.push_back(pair);
  });
  reference_share_ = Share(inside);
}

double PairTrust::Share(const std::vector<ViewPair>& edges) const {
  double weight = 0.0;
  double inliers = 0.0;
  for (const ViewPair& edge : edges) {
    const ViewPair key = MakeViewPair(edge.first, edge.second);
    const auto it = edge_weights_.find(key);
    if (it == edge_weights_.end()) continue;
    weight += it->second;
    inliers += static_cast<double>(graph_.FindEdge(key.first, key.second)->matches.size());
  }
  return inliers > 0.0 ? weight / inliers : 0.0;
}

double PairTrust::Of(const std::vector<ViewPair>& edges, const AlignmentHypothesis* selected) const {
  if (measure_ == PairTrustMeasure::kMatchCoverage) return selected != nullptr ? selected->Coverage() : 0.0;
  const double share = Share(edges);
  return reference_share_ > 0.0 ? share / reference_share_ : share;
}

}  // namespace sfm_pruning
