#include "sfm_pruning/view_graph/distinctive_weights.hpp"

namespace sfm_pruning {
namespace {

uint64_t FeatureKey(IndexT view_id, IndexT feature) {
  return (static_cast<uint64_t>(view_id) << 32) | static_cast<uint64_t>(feature);
}

}  // namespace

FeatureDistinctiveness::FeatureDistinctiveness(const ViewGraph& graph) {
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    for (const FeatureMatch& m : edge.matches) {
      ++match_counts_[FeatureKey(pair.first, m.i)];
      ++match_counts_[FeatureKey(pair.second, m.j)];
    }
  });
}

double FeatureDistinctiveness::Weight(IndexT view_id, IndexT feature) const {
  const auto it = match_counts_.find(FeatureKey(view_id, feature));
  return it == match_counts_.end() ? 1.0 : 1.0 / static_cast<double>(it->second);
}

std::map<ViewPair, double> DistinctiveMatchWeights(const ViewGraph& graph,
                                                   const FeatureDistinctiveness& distinctiveness) {
  std::map<ViewPair, double> weights;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    double weight = 0.0;
    for (const FeatureMatch& m : edge.matches) {
      weight += 0.5 * (distinctiveness.Weight(pair.first, m.i) + distinctiveness.Weight(pair.second, m.j));
    }
    weights.emplace(pair, weight);
  });
  return weights;
}

}  // namespace sfm_pruning
