#include "sfm_pruning/pruning/pair_trust.hpp"

#include "sfm_pruning/view_graph/distinctive_weights.hpp"

namespace sfm_pruning {
namespace {

// Σ matched / Σ expected over every edge inside a subgraph with both views posed there, each edge
// measured both ways with the subgraph's own poses; 0 when nothing is expected anywhere.
double InsideMatchCoverage(const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted,
                           const SfmData& views_and_intrinsics, const EdgePlacementOptions& placement) {
  double expected = 0.0;
  double matched = 0.0;
  for (const AcceptedSubgraph& subgraph : accepted) {
    const SubgraphSolution& solution = subgraph.solution;
    const std::map<ObservationKey, IndexT> landmarks = IndexLandmarksByObservation(solution);
    for (const auto& [view_a, pose_a] : solution.poses) {
      for (const auto& [view_b, pose_b] : solution.poses) {
        if (view_a == view_b || !graph.HasValidEdge(view_a, view_b)) continue;
        const CameraIntrinsics* intrinsics_b = views_and_intrinsics.FindIntrinsics(view_b);
        if (intrinsics_b == nullptr) continue;
        const MatchCoverage coverage =
            MeasureMatchCoverage(graph, view_a, view_b, pose_b, solution, landmarks, *intrinsics_b, placement);
        expected += static_cast<double>(coverage.expected);
        matched += static_cast<double>(coverage.matched);
      }
    }
  }
  return expected > 0.0 ? matched / expected : 0.0;
}

std::vector<ViewPair> EdgesOf(const SubgraphAlignmentResult& alignment, bool all_edges) {
  std::vector<ViewPair> edges;
  for (const InterSubgraphEdgeDecision& decision : alignment.edges) {
    if (decision.kept || all_edges) edges.push_back({decision.placement.view_i, decision.placement.view_j});
  }
  return edges;
}

}  // namespace

PairTrust::PairTrust(PairTrustMeasure measure, const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted,
                     const SfmData& views_and_intrinsics, const EdgePlacementOptions& placement, double prior_edges)
    : measure_(measure), prior_edges_(prior_edges), graph_(graph) {
  reference_coverage_ = InsideMatchCoverage(graph, accepted, views_and_intrinsics, placement);
  if (measure_ == PairTrustMeasure::kMatchCoverage) return;  // the distinctive weights serve the share only
  edge_weights_ = DistinctiveMatchWeights(graph, FeatureDistinctiveness(graph));
  std::vector<ViewPair> inside;
  for (const EdgeOfSubgraphs& edge : EdgesOfAcceptedSubgraphs(graph, accepted)) {
    if (edge.k_first == edge.k_second) inside.push_back(edge.pair);
  }
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

double PairTrust::RelativeCoverageOf(const SubgraphAlignmentResult& alignment, bool all_edges) const {
  double expected = 0.0;
  double matched = 0.0;
  for (const InterSubgraphEdgeDecision& decision : alignment.edges) {
    if (!(decision.kept || all_edges) || decision.placement.status != EdgePlacementStatus::kPlaced) continue;
    expected += static_cast<double>(decision.placement.num_expected_landmarks);
    matched += static_cast<double>(decision.placement.num_matched_landmarks);
  }
  if (!(expected > 0.0) || !(reference_coverage_ > 0.0)) return -1.0;
  return matched / expected / reference_coverage_;
}

double PairTrust::Of(const SubgraphAlignmentResult& alignment, bool all_edges) const {
  if (measure_ == PairTrustMeasure::kMatchCoverage) {
    if (alignment.selected_hypothesis < 0) return 0.0;
    return alignment.hypotheses[static_cast<size_t>(alignment.selected_hypothesis)].Coverage();
  }
  const std::vector<ViewPair> edges = EdgesOf(alignment, all_edges);
  double share = Share(edges);
  // A pair that kept nothing stays at 0: the prior only tempers the share of edges that were kept.
  if (prior_edges_ > 0.0 && !all_edges && !edges.empty()) {
    const double kept = static_cast<double>(edges.size());
    share = (kept * share + prior_edges_ * Share(EdgesOf(alignment, true))) / (kept + prior_edges_);
  }
  return reference_share_ > 0.0 ? share / reference_share_ : share;
}

}  // namespace sfm_pruning
