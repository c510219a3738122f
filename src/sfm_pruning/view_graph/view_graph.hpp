// ViewGraph: nodes are view ids, edges are verified pairs keyed by ViewPair (first < second).
//
// Every traversal is ordered (std::set / std::map, neighbours in increasing id), so algorithms
// built on it are deterministic. Invalid edges stay in the graph with their EdgeInvalidation;
// every "valid" query (neighbours, counts, iteration) skips them.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph_edge.hpp"

namespace sfm_pruning {

class ViewGraph {
 public:
  // Adds an isolated node (no-op if present). AddEdge adds its endpoints itself.
  void AddNode(IndexT view_id);

  // Adds (or replaces) the edge between a and b from data expressed from a to b: `matches` have
  // FeatureMatch::i in view a, `pose_a_to_b` maps camera a to camera b. Stores them in the
  // (first < second) orientation, inverting / swapping when a > b. Weight = matches.size().
  // Throws std::invalid_argument when a == b.
  ViewGraphEdge& AddEdge(IndexT a, IndexT b, const std::vector<FeatureMatch>& matches,
                         const RelativePose& pose_a_to_b);
  // Adds (or replaces) an edge given in the pair's own orientation, weight and flags as given.
  // Throws std::invalid_argument unless pair.first < pair.second.
  ViewGraphEdge& AddEdge(const ViewPair& pair, ViewGraphEdge edge);

  // Removes the nodes and every edge touching them (e.g. views outside the largest component).
  void RemoveNodes(const std::vector<IndexT>& view_ids);

  const std::set<IndexT>& Nodes() const { return nodes_; }
  // All edges, valid or not, in ViewPair order.
  const std::map<ViewPair, ViewGraphEdge>& Edges() const { return edges_; }
  bool HasNode(IndexT view_id) const { return nodes_.count(view_id) > 0; }
  size_t NumNodes() const { return nodes_.size(); }
  size_t NumEdges() const { return edges_.size(); }
  size_t NumValidEdges() const;

  // Edge between a and b in either order; nullptr when absent (valid or not).
  const ViewGraphEdge* FindEdge(IndexT a, IndexT b) const;
  ViewGraphEdge* MutableEdge(IndexT a, IndexT b);
  // True when the edge exists and is valid.
  bool HasValidEdge(IndexT a, IndexT b) const;

  // Valid edges in increasing ViewPair order.
  std::vector<ViewPair> ValidEdgePairs() const;
  // Calls visit(const ViewPair&, const ViewGraphEdge&) for every valid edge, in ViewPair order.
  template <typename Visitor>
  void ForEachValidEdge(Visitor&& visit) const {
    for (const auto& [pair, edge] : edges_) {
      if (edge.is_valid) visit(pair, edge);
    }
  }

  // Neighbours of a node over valid edges, increasing ids; empty for an unknown node.
  std::vector<IndexT> ValidNeighbors(IndexT view_id) const;
  // Valid adjacency lists of every node (isolated nodes map to an empty list), increasing ids.
  // Build it once when an algorithm walks the graph many times.
  std::map<IndexT, std::vector<IndexT>> ValidAdjacency() const;
  // Sum of the weights of the valid edges at a node.
  double WeightedDegree(IndexT view_id) const;

  // Relative pose mapping camera a to camera b, for either order of (a, b): the stored pose
  // when a < b, its inverse when a > b. Throws std::out_of_range when there is no such edge.
  RelativePose OrientedRelativePose(IndexT a, IndexT b) const;
  // Inlier matches with FeatureMatch::i in view a and j in view b. Throws std::out_of_range.
  std::vector<FeatureMatch> OrientedMatches(IndexT a, IndexT b) const;

  // The nodes of `view_ids` that are in this graph and every edge (valid or not, flags kept)
  // between two of them.
  ViewGraph InducedSubgraph(const std::set<IndexT>& view_ids) const;

  // Flags the edge invalid with `why`. An edge already invalid keeps its first reason (the stage
  // that actually cut it); returns whether the edge was valid before the call.
  // Throws std::out_of_range when there is no such edge.
  bool InvalidateEdge(IndexT a, IndexT b, const EdgeInvalidation& why);

 private:
  std::set<IndexT> nodes_;
  std::map<ViewPair, ViewGraphEdge> edges_;
  // All edges (valid or not) per node, so neighbour queries cost O(degree), not O(E).
  std::map<IndexT, std::set<IndexT>> incident_;
};

}  // namespace sfm_pruning
