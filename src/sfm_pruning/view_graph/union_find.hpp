// Disjoint sets over dense indices 0..n-1 (union by size + path compression, so a sequence of
// operations costs almost O(1) each). Used by Kruskal and by track building, which maps its own
// ids (views, observations) to dense indices first.
#pragma once

#include <cstddef>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace sfm_pruning {

template <typename Index = size_t>
class UnionFind {
  static_assert(std::is_integral_v<Index> && std::is_unsigned_v<Index>,
                "UnionFind indices are unsigned integers (IndexT or size_t)");

 public:
  explicit UnionFind(size_t num_elements = 0) { Reset(num_elements); }

  // n singleton sets {0}, ..., {n-1}.
  void Reset(size_t num_elements) {
    parent_.resize(num_elements);
    std::iota(parent_.begin(), parent_.end(), Index{0});
    size_.assign(num_elements, 1);
    num_sets_ = num_elements;
  }

  // Representative of x's set. Compresses the path so later queries are O(1).
  Index Find(Index x) {
    Index root = x;
    while (parent_[root] != root) root = parent_[root];
    while (parent_[x] != root) x = std::exchange(parent_[x], root);
    return root;
  }

  // Merges the sets of a and b; returns false when they were already one set. The larger set's
  // root survives (ties: the smaller root index), so the result does not depend on the order
  // of a and b.
  bool Union(Index a, Index b) {
    Index root_a = Find(a);
    Index root_b = Find(b);
    if (root_a == root_b) return false;
    if (size_[root_a] < size_[root_b] || (size_[root_a] == size_[root_b] && root_b < root_a)) {
      std::swap(root_a, root_b);
    }
    parent_[root_b] = root_a;
    size_[root_a] += size_[root_b];
    --num_sets_;
    return true;
  }

  bool Connected(Index a, Index b) { return Find(a) == Find(b); }
  size_t SetSize(Index x) { return size_[Find(x)]; }
  size_t NumSets() const { return num_sets_; }
  size_t NumElements() const { return parent_.size(); }

 private:
  std::vector<Index> parent_;
  std::vector<size_t> size_;  // meaningful at roots only
  size_t num_sets_ = 0;
};

}  // namespace sfm_pruning
