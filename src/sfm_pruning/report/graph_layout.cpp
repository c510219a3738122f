#include "sfm_pruning/report/graph_layout.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {

std::vector<Eigen::Vector2d> ForceDirectedLayout(size_t num_nodes, const std::vector<LayoutEdge>& edges,
                                                 const GraphLayoutOptions& options) {
  options.Check();
  std::vector<Eigen::Vector2d> position(num_nodes, Eigen::Vector2d(0.5, 0.5));
  if (num_nodes <= 1) return position;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (Eigen::Vector2d& p : position) p = Eigen::Vector2d(uniform(rng), uniform(rng));

  double max_weight = 0.0;
  for (const LayoutEdge& edge : edges) max_weight = std::max(max_weight, edge.weight);
  const double ideal = std::sqrt(1.0 / static_cast<double>(num_nodes));  // k of Fruchterman-Reingold
  const Eigen::Vector2d center(0.5, 0.5);
  std::vector<Eigen::Vector2d> displacement(num_nodes);
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    // Temperature: the largest step, cooled linearly so the layout settles.
    const double temperature = 0.1 * (1.0 - static_cast<double>(iteration) / options.iterations) + 1e-4;
    std::fill(displacement.begin(), displacement.end(), Eigen::Vector2d::Zero());
    for (size_t i = 0; i < num_nodes; ++i) {
      for (size_t j = i + 1; j < num_nodes; ++j) {
        Eigen::Vector2d delta = position[i] - position[j];
        double distance = delta.norm();
        if (distance < 1e-9) {  // coincident: push apart along a fixed, index-derived direction
          delta = Eigen::Vector2d(std::cos(static_cast<double>(i + j)), std::sin(static_cast<double>(i + j)));
          distance = 1e-9;
        }
        const Eigen::Vector2d push = delta / distance * (ideal * ideal / distance);
        displacement[i] += push;
        displacement[j] -= push;
      }
    }
    for (const LayoutEdge& edge : edges) {
      if (edge.a == edge.b || edge.a >= num_nodes || edge.b >= num_nodes) continue;
      const Eigen::Vector2d delta = position[edge.a] - position[edge.b];
      const double distance = delta.norm();
      const double strength = max_weight > 0.0 ? edge.weight / max_weight : 1.0;
      const Eigen::Vector2d pull = delta * (distance / ideal) * strength;
      displacement[edge.a] -= pull;
      displacement[edge.b] += pull;
    }
    for (size_t i = 0; i < num_nodes; ++i) {
      const Eigen::Vector2d to_center = center - position[i];
      displacement[i] += options.gravity * to_center * (to_center.norm() / ideal);
      const double length = displacement[i].norm();
      if (length > 0.0) position[i] += displacement[i] / length * std::min(length, temperature);
    }
  }

  // Fill the unit square, keeping the aspect ratio.
  Eigen::Vector2d low = position[0], high = position[0];
  for (const Eigen::Vector2d& p : position) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = std::max((high - low).maxCoeff(), 1e-12);
  const Eigen::Vector2d offset = (Eigen::Vector2d::Ones() - (high - low) / extent) / 2.0;
  for (Eigen::Vector2d& p : position) p = (p - low) / extent + offset;
  return position;
}

void GraphLayoutOptions::Check() const {
  // 0 iterations leaves the seeded random positions.
  RequireAtLeast(iterations, 0, "GraphLayoutOptions::iterations");
  // Far stronger pulls overflow the displacements and turn the positions into NaN; a million times
  // an edge spring is already far past any useful layout.
  RequireInRange(gravity, 0.0, 1e6, "GraphLayoutOptions::gravity");
}

}  // namespace sfm_pruning
