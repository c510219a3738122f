// Louvain community detection on the inlier-weighted view graph (Blondel et al. 2008), the
// partition step of METHOD.md §3: greedy local moves that maximise weighted modularity
// (modularity.hpp), then aggregation of each community into a super-node, repeated until
// modularity stops increasing. Runs igraph 0.10's igraph_community_multilevel.
//
// Determinism: igraph visits nodes in a random order drawn from its global RNG. Every call
// holds one process-wide mutex, re-seeds that RNG with `seed`, and maps node ids to igraph
// vertices 0..n-1 in increasing id order, so the result depends only on (graph, options).
#pragma once

#include <cstdint>
#include <vector>

#include "sfm_pruning/view_graph/node_groups.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct LouvainOptions {
  // gamma of the modularity (modularity.hpp). 1 = classic modularity, as in the paper; larger
  // values give more, smaller communities.
  double resolution = 1.0;
  // Seed of igraph's RNG (node visiting order). Same graph + same seed = same communities.
  uint64_t seed = 0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct LouvainResult {
  // Every node exactly once; ids sorted, largest community first, ties by smallest id.
  std::vector<NodeGroup> communities;
  // Modularity of `communities` at options.resolution, as igraph reports it (ComputeModularity
  // agrees to 1e-9). 0 when the graph has no edge weight.
  double modularity = 0.0;
  // Aggregation levels igraph performed; 0 when there was nothing to cluster.
  int num_levels = 0;
};

// Uses the valid edges and their weights (must be finite and >= 0: throws
// std::invalid_argument otherwise). Special cases, without calling igraph: an empty graph
// gives no community; a graph without edge weight (no valid edge, or all weights 0) gives one
// community per node. Disconnected graphs are fine: communities never span components.
// Throws std::runtime_error if igraph reports an error.
LouvainResult DetectCommunitiesLouvain(const ViewGraph& graph, const LouvainOptions& options = {});

}  // namespace sfm_pruning
