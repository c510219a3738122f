// Spectral bisection of a view graph (Fiedler 1973): the views sorted by their entry of the
// eigenvector of the second smallest eigenvalue of the weighted graph Laplacian L = D - W, cut into
// halves of floor(n/2) and ceil(n/2) views. Among balanced cuts it approximately minimises the
// weight of the edges it cuts, so it separates what the weights hold together least.
//
// Used by the recursive partition where Louvain returns an inconsistent community whole
// (RecursivePartitionOptions::bisect_unsplittable): modularity sees no gain in splitting a
// small, dense community, but its consistency tests have shown it holds a wrong edge.
//
// Dense eigen-decomposition, O(n^3): meant for communities (tens of views), not whole scenes.
// Deterministic: the eigenvector's sign is fixed (the smallest view id gets a value <= 0) and equal
// values keep view id order.
#pragma once

#include <utility>

#include "sfm_pruning/view_graph/node_groups.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// The two halves (each sorted; the first holds the smallest view id's side). Needs at least two
// nodes; valid edges only, by ViewGraphEdge::weight (a graph without weights: every edge 1).
std::pair<NodeGroup, NodeGroup> SpectralBisection(const ViewGraph& graph);

}  // namespace sfm_pruning
