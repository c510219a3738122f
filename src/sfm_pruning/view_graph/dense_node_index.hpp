// Node ids <-> dense indices 0..n-1 in increasing id order, the layout union-find and igraph
// need. Increasing order makes index-based tie-breaks equal to "smallest view id wins".
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

class DenseNodeIndex {
 public:
  explicit DenseNodeIndex(const ViewGraph& graph) : ids_(graph.Nodes().begin(), graph.Nodes().end()) {}

  size_t size() const { return ids_.size(); }
  IndexT IdOf(size_t index) const { return ids_.at(index); }
  // Throws std::out_of_range for an id that is not a node.
  size_t IndexOf(IndexT id) const {
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
    if (it == ids_.end() || *it != id)
      throw std::out_of_range("not a view graph node: " + std::to_string(id));
    return static_cast<size_t>(it - ids_.begin());
  }

 private:
  std::vector<IndexT> ids_;  // sorted (copied from a std::set)
};

}  // namespace sfm_pruning
