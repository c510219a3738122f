#include "view_graph/graph_builders.hpp"

#include <random>

namespace sfm_pruning::testing {

void AddWeightedEdge(ViewGraph* graph, IndexT a, IndexT b, double weight) {
  ViewGraphEdge edge;
  edge.weight = weight;
  graph->AddEdge(MakeViewPair(a, b), edge);
}

void AddWeightedEdges(ViewGraph* graph, const std::vector<WeightedPair>& edges) {
  for (const WeightedPair& edge : edges) AddWeightedEdge(graph, edge.a, edge.b, edge.weight);
}

std::vector<ViewPair> AllPairs(IndexT num_nodes) {
  std::vector<ViewPair> pairs;
  for (IndexT a = 0; a < num_nodes; ++a) {
    for (IndexT b = a + 1; b < num_nodes; ++b) pairs.push_back({a, b});
  }
  return pairs;
}

void AddClique(ViewGraph* graph, const std::vector<IndexT>& ids, double weight) {
  for (size_t x = 0; x < ids.size(); ++x) {
    for (size_t y = x + 1; y < ids.size(); ++y) AddWeightedEdge(graph, ids[x], ids[y], weight);
  }
}

ViewGraph RandomGraph(size_t num_nodes, double edge_probability, uint32_t seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution present(edge_probability);
  std::uniform_int_distribution<int> inliers(1, 100);
  ViewGraph graph;
  for (IndexT a = 0; a < num_nodes; ++a) {
    graph.AddNode(a);
    for (IndexT b = a + 1; b < num_nodes; ++b) {
      if (present(rng)) AddWeightedEdge(&graph, a, b, inliers(rng));
    }
  }
  return graph;
}

std::map<IndexT, Pose> RandomPoses(size_t num_nodes, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::map<IndexT, Pose> poses;
  for (IndexT id = 0; id < num_nodes; ++id) {
    const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const double angle = M_PI * unit(rng);
    const Eigen::Vector3d center(5 * unit(rng), 5 * unit(rng), 5 * unit(rng));
    poses[id] = Pose(Eigen::AngleAxisd(angle, axis).toRotationMatrix(), center);
  }
  return poses;
}

void AddEdgesFromPoses(ViewGraph* graph, const std::map<IndexT, Pose>& poses,
                       const std::vector<ViewPair>& pairs, size_t num_matches) {
  for (const auto& [a, b] : pairs) {
    RelativePose relative = RelativePoseBetween(poses.at(a), poses.at(b));
    relative.translation.normalize();
    std::vector<FeatureMatch> matches;
    for (IndexT k = 0; k < num_matches; ++k) matches.push_back({k, k + 1000});
    graph->AddEdge(a, b, matches, relative);
  }
}

}  // namespace sfm_pruning::testing
