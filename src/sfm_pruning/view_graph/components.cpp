#include "sfm_pruning/view_graph/components.hpp"

#include <algorithm>
#include <map>

#include "sfm_pruning/view_graph/dense_node_index.hpp"
#include "sfm_pruning/view_graph/union_find.hpp"

namespace sfm_pruning {

std::vector<NodeGroup> ConnectedComponents(const ViewGraph& graph) {
  const DenseNodeIndex index(graph);
  UnionFind<size_t> sets(index.size());
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge&) {
    sets.Union(index.IndexOf(pair.first), index.IndexOf(pair.second));
  });

  std::map<size_t, NodeGroup> by_root;
  for (size_t k = 0; k < index.size(); ++k) by_root[sets.Find(k)].push_back(index.IdOf(k));
  std::vector<NodeGroup> components;
  components.reserve(by_root.size());
  for (auto& [root, members] : by_root) components.push_back(std::move(members));
  SortNodeGroups(&components);
  return components;
}

NodeGroup LargestComponent(const ViewGraph& graph) {
  std::vector<NodeGroup> components = ConnectedComponents(graph);
  return components.empty() ? NodeGroup{} : std::move(components.front());
}

LargestComponentSelection KeepLargestComponent(ViewGraph* graph) {
  LargestComponentSelection selection;
  selection.kept = LargestComponent(*graph);
  for (IndexT id : graph->Nodes()) {
    if (!std::binary_search(selection.kept.begin(), selection.kept.end(), id)) {
      selection.dropped.push_back(id);
    }
  }
  graph->RemoveNodes(selection.dropped);
  return selection;
}

}  // namespace sfm_pruning
