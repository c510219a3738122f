#include "sfm_pruning/view_graph/cycles.hpp"

#include <algorithm>
#include <deque>
#include <set>
#include <stdexcept>

#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/view_graph/dense_node_index.hpp"

namespace sfm_pruning {
namespace {

// Rotates the loop to start at its smallest id and orients it towards the smaller neighbour,
// so the same loop found from different edges compares equal.
ViewCycle Canonical(ViewCycle cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  if (cycle.size() > 2 && cycle.back() < cycle[1]) std::reverse(cycle.begin() + 1, cycle.end());
  return cycle;
}

// Accumulates distinct canonical cycles up to the cap.
class CycleCollector {
 public:
  explicit CycleCollector(size_t max_num_cycles) : max_num_cycles_(max_num_cycles) {}

  // Returns false once the cap is reached: the caller stops searching.
  bool Add(const ViewCycle& cycle) {
    ViewCycle canonical = Canonical(cycle);
    if (seen_.count(canonical) > 0) return true;  // a duplicate does not hit the cap
    if (result_.cycles.size() >= max_num_cycles_) {
      result_.truncated = true;
      return false;
    }
    seen_.insert(canonical);
    result_.cycles.push_back(std::move(canonical));
    return true;
  }
  bool Full() const { return result_.truncated; }
  CycleSearchResult& result() { return result_; }

 private:
  size_t max_num_cycles_;
  std::set<ViewCycle> seen_;
  CycleSearchResult result_;
};

using DenseAdjacency = std::vector<std::vector<size_t>>;

// Valid adjacency over dense indices; lists are increasing because ids map monotonically.
DenseAdjacency BuildDenseAdjacency(const ViewGraph& graph, const DenseNodeIndex& index) {
  DenseAdjacency adjacency(index.size());
  for (const auto& [id, neighbors] : graph.ValidAdjacency()) {
    for (IndexT other : neighbors) adjacency[index.IndexOf(id)].push_back(index.IndexOf(other));
  }
  return adjacency;
}

// Step 2: each triangle a < b < c once, from its edge (a, b).
void CollectTriangles(const DenseAdjacency& adjacency, const DenseNodeIndex& index,
                      CycleCollector* collector) {
  for (size_t a = 0; a < adjacency.size(); ++a) {
    for (size_t b : adjacency[a]) {
      if (b <= a) continue;
      const auto& list_a = adjacency[a];
      const auto& list_b = adjacency[b];
      // Both lists are sorted: a merge finds the common neighbours c > b.
      auto it_a = std::upper_bound(list_a.begin(), list_a.end(), b);
      auto it_b = std::upper_bound(list_b.begin(), list_b.end(), b);
      while (it_a != list_a.end() && it_b != list_b.end()) {
        if (*it_a < *it_b) {
          ++it_a;
        } else if (*it_b < *it_a) {
          ++it_b;
        } else {
          if (!collector->Add({index.IdOf(a), index.IdOf(b), index.IdOf(*it_a)})) return;
          ++it_a;
          ++it_b;
        }
      }
    }
  }
}

// Breadth-first search state reused across edges; only touched entries are reset.
class BoundedBfs {
 public:
  explicit BoundedBfs(size_t num_nodes) : parent_(num_nodes, kUnvisited), depth_(num_nodes, 0) {}

  // Shortest path source -> target of at most max_edges edges that avoids the direct edge
  // source-target, as dense indices from source to target; empty when there is none.
  std::vector<size_t> ShortestDetour(const DenseAdjacency& adjacency, size_t source, size_t target,
                                     size_t max_edges) {
    std::vector<size_t> path;
    Visit(source, source, 0);
    std::deque<size_t> queue = {source};
    while (!queue.empty() && parent_[target] == kUnvisited) {
      const size_t node = queue.front();
      queue.pop_front();
      if (depth_[node] == max_edges) continue;
      for (size_t next : adjacency[node]) {
        if (parent_[next] != kUnvisited || (node == source && next == target)) continue;
        Visit(next, node, depth_[node] + 1);
        if (next == target) break;
        queue.push_back(next);
      }
    }
    if (parent_[target] != kUnvisited) {
      for (size_t node = target; node != source; node = parent_[node]) path.push_back(node);
      path.push_back(source);
      std::reverse(path.begin(), path.end());
    }
    for (size_t node : touched_) parent_[node] = kUnvisited;
    touched_.clear();
    return path;
  }

 private:
  static constexpr size_t kUnvisited = static_cast<size_t>(-1);

  void Visit(size_t node, size_t parent, size_t depth) {
    parent_[node] = parent;
    depth_[node] = depth;
    touched_.push_back(node);
  }

  std::vector<size_t> parent_;
  std::vector<size_t> depth_;
  std::vector<size_t> touched_;
};

// Step 1: per edge, the shortest loop through it.
void CollectShortestAlternatives(const DenseAdjacency& adjacency, const DenseNodeIndex& index,
                                 size_t max_cycle_length, CycleCollector* collector) {
  BoundedBfs bfs(adjacency.size());
  for (size_t a = 0; a < adjacency.size(); ++a) {
    for (size_t b : adjacency[a]) {
      if (b <= a) continue;
      const std::vector<size_t> path = bfs.ShortestDetour(adjacency, a, b, max_cycle_length - 1);
      if (path.empty()) continue;  // a bridge, or only longer loops
      ViewCycle cycle;
      for (size_t node : path) cycle.push_back(index.IdOf(node));
      if (!collector->Add(cycle)) return;
    }
  }
}

}  // namespace

CycleSearchResult FindBoundedCycles(const ViewGraph& graph, const CycleSearchOptions& options) {
  options.Check();
  CycleCollector collector(options.max_num_cycles);
  if (options.max_cycle_length < 3) return collector.result();  // no simple cycle is shorter
  const DenseNodeIndex index(graph);
  const DenseAdjacency adjacency = BuildDenseAdjacency(graph, index);
  if (options.include_shortest_alternatives) {
    CollectShortestAlternatives(adjacency, index, options.max_cycle_length, &collector);
  }
  if (options.include_triangles && !collector.Full()) CollectTriangles(adjacency, index, &collector);
  CycleSearchResult& result = collector.result();
  result.num_triangles = static_cast<size_t>(std::count_if(
      result.cycles.begin(), result.cycles.end(), [](const ViewCycle& cycle) { return cycle.size() == 3; }));
  return result;
}

double LoopRotationErrorDeg(const ViewGraph& graph, const ViewCycle& cycle) {
  if (cycle.size() < 2) throw std::invalid_argument("LoopRotationErrorDeg: a loop needs at least 2 views");
  Eigen::Matrix3d composed = Eigen::Matrix3d::Identity();  // camera c0 -> camera c_k
  for (size_t k = 0; k < cycle.size(); ++k) {
    const IndexT from = cycle[k];
    const IndexT to = cycle[(k + 1) % cycle.size()];
    composed = graph.OrientedRelativePose(from, to).rotation * composed;
  }
  return RadToDeg(RotationAngleBetween(Eigen::Matrix3d::Identity(), composed));
}

double LoopRotationThresholdDeg(size_t num_cameras, double step_deg) {
  if (num_cameras < 1) return 0.0;
  return step_deg * static_cast<double>((num_cameras - 1) / 2);
}

void CycleSearchOptions::Check() const {
  // No simple cycle has fewer than 3 cameras; a cap of 0 would list none and report truncation.
  RequireAtLeast<size_t>(max_cycle_length, 3, "CycleSearchOptions::max_cycle_length");
  RequireAtLeast<size_t>(max_num_cycles, 1, "CycleSearchOptions::max_num_cycles");
}

}  // namespace sfm_pruning
