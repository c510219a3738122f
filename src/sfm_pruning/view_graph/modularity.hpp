// Weighted modularity of a partition of the view graph (the paper, "Subgraph Partition"):
//
//   Q = 1/(2m) * sum_{i,j} [ A_ij - gamma * k_i k_j / (2m) ] * delta(c_i, c_j)
//
// with A_ij the weight of the valid edge <i,j> (inlier count), k_i the weighted degree,
// m the total edge weight and gamma the resolution (1 in the paper). Summed per community c:
//   Q = sum_c [ L_c / m - gamma * (D_c / (2m))^2 ]
// where L_c is the weight of the edges inside c (each counted once) and D_c the sum of the
// degrees of its nodes. Our own implementation, used to check igraph's value.
#pragma once

#include <vector>

#include "sfm_pruning/view_graph/node_groups.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// `partition` must hold every node of the graph exactly once (throws std::invalid_argument
// otherwise). A graph of total weight 0 has modularity 0 by convention (the formula is 0/0).
double ComputeModularity(const ViewGraph& graph, const std::vector<NodeGroup>& partition,
                         double resolution = 1.0);

}  // namespace sfm_pruning
