#include "sfm_pruning/view_graph/spanning_tree.hpp"

#include <algorithm>
#include <deque>
#include <utility>

#include "sfm_pruning/view_graph/dense_node_index.hpp"
#include "sfm_pruning/view_graph/union_find.hpp"

namespace sfm_pruning {
namespace {

// Largest weighted degree, ties by smallest id (nodes are visited in increasing id and only a
// strictly larger degree replaces the current best).
IndexT HeaviestNode(const ViewGraph& graph) {
  IndexT best = kUndefinedIndex;
  double best_degree = -1.0;
  for (IndexT id : graph.Nodes()) {
    const double degree = graph.WeightedDegree(id);
    if (degree > best_degree) {
      best = id;
      best_degree = degree;
    }
  }
  return best;
}

// The maximum spanning forest as adjacency lists (increasing ids), one tree per component.
std::map<IndexT, std::vector<IndexT>> KruskalForest(const ViewGraph& graph) {
  std::vector<std::pair<ViewPair, double>> candidates;
  graph.ForEachValidEdge([&candidates](const ViewPair& pair, const ViewGraphEdge& edge) {
    candidates.emplace_back(pair, edge.weight);
  });
  // Stable sort keeps ViewPair order among equal weights.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });

  const DenseNodeIndex index(graph);
  UnionFind<size_t> sets(index.size());
  std::map<IndexT, std::vector<IndexT>> forest;
  for (const auto& [pair, weight] : candidates) {
    if (sets.Union(index.IndexOf(pair.first), index.IndexOf(pair.second))) {
      forest[pair.first].push_back(pair.second);
      forest[pair.second].push_back(pair.first);
    }
  }
  for (auto& [id, children] : forest) std::sort(children.begin(), children.end());
  return forest;
}

}  // namespace

SpanningTree MaximumSpanningTree(const ViewGraph& graph) {
  SpanningTree tree;
  tree.root = HeaviestNode(graph);
  if (tree.root == kUndefinedIndex) return tree;

  const std::map<IndexT, std::vector<IndexT>> forest = KruskalForest(graph);
  tree.parent[tree.root] = tree.root;
  std::deque<IndexT> queue = {tree.root};
  while (!queue.empty()) {
    const IndexT node = queue.front();
    queue.pop_front();
    tree.bfs_order.push_back(node);
    const auto it = forest.find(node);
    if (it == forest.end()) continue;  // isolated root
    for (IndexT child : it->second) {
      if (tree.parent.count(child) > 0) continue;  // the node's own parent
      tree.parent[child] = node;
      tree.edges.push_back(MakeViewPair(node, child));
      tree.total_weight += graph.FindEdge(node, child)->weight;
      queue.push_back(child);
    }
  }
  std::sort(tree.edges.begin(), tree.edges.end());
  return tree;
}

}  // namespace sfm_pruning
