#include "sfm_pruning/view_graph/modularity.hpp"

#include <map>
#include <stdexcept>
#include <string>

namespace sfm_pruning {
namespace {

// Community index of every node; throws unless the partition covers the nodes exactly once.
std::map<IndexT, size_t> CommunityOfNodes(const ViewGraph& graph, const std::vector<NodeGroup>& partition) {
  std::map<IndexT, size_t> community_of;
  for (size_t c = 0; c < partition.size(); ++c) {
    for (IndexT id : partition[c]) {
      if (!graph.HasNode(id)) {
        throw std::invalid_argument("ComputeModularity: view " + std::to_string(id) + " is not a node");
      }
      if (!community_of.emplace(id, c).second) {
        throw std::invalid_argument("ComputeModularity: view " + std::to_string(id) +
                                    " is in two communities");
      }
    }
  }
  if (community_of.size() != graph.NumNodes()) {
    throw std::invalid_argument("ComputeModularity: the partition misses some nodes");
  }
  return community_of;
}

}  // namespace

double ComputeModularity(const ViewGraph& graph, const std::vector<NodeGroup>& partition, double resolution) {
  const std::map<IndexT, size_t> community_of = CommunityOfNodes(graph, partition);
  std::vector<double> inside(partition.size(), 0.0);  // L_c
  std::vector<double> degree(partition.size(), 0.0);  // D_c
  double total = 0.0;                                 // m
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const size_t c1 = community_of.at(pair.first);
    const size_t c2 = community_of.at(pair.second);
    total += edge.weight;
    degree[c1] += edge.weight;
    degree[c2] += edge.weight;
    if (c1 == c2) inside[c1] += edge.weight;
  });
  if (total == 0.0) return 0.0;

  double q = 0.0;
  for (size_t c = 0; c < partition.size(); ++c) {
    const double degree_fraction = degree[c] / (2.0 * total);
    q += inside[c] / total - resolution * degree_fraction * degree_fraction;
  }
  return q;
}

}  // namespace sfm_pruning
