// Maximum spanning tree of the view graph by edge weight (inlier count): the most reliable
// pairs first. Rotation averaging initialises by walking it from the root, composing relative
// rotations along tree edges.
#pragma once

#include <map>
#include <vector>

#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct SpanningTree {
  // The node of largest weighted degree over valid edges, ties by smallest id;
  // kUndefinedIndex for an empty graph.
  IndexT root = kUndefinedIndex;
  // Parent of every node of the tree; the root is its own parent.
  std::map<IndexT, IndexT> parent;
  // Root first, then breadth-first with children in increasing id: every node comes after its
  // parent, so a single pass in this order can propagate poses.
  std::vector<IndexT> bfs_order;
  std::vector<ViewPair> edges;  // tree edges, increasing ViewPair order
  double total_weight = 0.0;    // sum of the tree edges' weights
};

// Kruskal over the valid edges: weight descending, ties by ViewPair order, union-find to reject
// cycles. Cost O(E log E). The graph should be connected (keep the largest component first);
// otherwise the tree spans the root's component only and the other nodes are absent from
// `parent` and `bfs_order`.
SpanningTree MaximumSpanningTree(const ViewGraph& graph);

}  // namespace sfm_pruning
