// A seeded force-directed layout (Fruchterman-Reingold with weighted springs and a weak pull to
// the centre, so separate components stay in view) for drawing view graphs.
//
// Deterministic: initial positions come from the seed, every loop runs in index order.
// O(iterations * n^2): fine for the few thousand views a report page can show.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sfm_pruning {

struct LayoutEdge {
  size_t a = 0;  // node indices
  size_t b = 0;
  double weight = 1.0;  // > 0; the spring force scales with weight / largest weight
};

struct GraphLayoutOptions {
  uint64_t seed = 0;
  int iterations = 400;
  double gravity = 0.3;  // a spring to the centre, as strong as this fraction of an edge spring

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Positions in the unit square [0, 1]^2 (rescaled to fill it, aspect kept), one per node.
std::vector<Eigen::Vector2d> ForceDirectedLayout(size_t num_nodes, const std::vector<LayoutEdge>& edges,
                                                 const GraphLayoutOptions& options = {});

}  // namespace sfm_pruning
