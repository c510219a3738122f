#include "sfm_pruning/view_graph/node_groups.hpp"

#include <algorithm>

namespace sfm_pruning {

void SortNodeGroups(std::vector<NodeGroup>* groups) {
  for (NodeGroup& group : *groups) std::sort(group.begin(), group.end());
  // Equal sizes: compare smallest ids (groups are sorted now); empty groups are all equal.
  std::sort(groups->begin(), groups->end(), [](const NodeGroup& a, const NodeGroup& b) {
    if (a.size() != b.size()) return a.size() > b.size();
    return !a.empty() && a.front() < b.front();
  });
}

}  // namespace sfm_pruning
