// Connected components of the view graph over valid edges. A global reconstruction can only
// place views of one component in a common frame, so the engine keeps the largest one and
// reports the views it drops.
#pragma once

#include <vector>

#include "sfm_pruning/view_graph/node_groups.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// Components in the node_groups.hpp order: ids sorted, largest first, ties by smallest id.
// Isolated nodes are components of size 1. Cost O(V + E) (union-find).
std::vector<NodeGroup> ConnectedComponents(const ViewGraph& graph);

// The first of ConnectedComponents (empty for an empty graph).
NodeGroup LargestComponent(const ViewGraph& graph);

struct LargestComponentSelection {
  NodeGroup kept;     // the largest component, sorted
  NodeGroup dropped;  // every other node, sorted
};

// Removes from `graph` every node outside its largest component, with the edges touching them
// (only invalid edges can join a dropped node to a kept one). Returns which views were kept and
// dropped so the engine can report them; callers that must keep the removed edges' record copy
// the graph first.
LargestComponentSelection KeepLargestComponent(ViewGraph* graph);

}  // namespace sfm_pruning
