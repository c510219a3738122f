// Subgraph frames for the loop-check tests: subgraph k lives in the frame frames[k]
// (x_k = frames[k](x_world), a random similarity); its cameras sit around a world centre with
// radius 1, and exact (or deliberately wrong) links between the frames.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"

namespace sfm_pruning::testing {

struct LoopScene {
  std::vector<Similarity3> frames;
  std::vector<SubgraphFrame> subgraphs;

  // n subgraphs on a circle of radius 4 (centre k at angle k radians).
  explicit LoopScene(size_t n) {
    std::vector<Eigen::Vector3d> centres;
    for (size_t k = 0; k < n; ++k) {
      centres.emplace_back(4.0 * std::cos(static_cast<double>(k)), 4.0 * std::sin(static_cast<double>(k)), 0.0);
    }
    Build(centres);
  }
  explicit LoopScene(const std::vector<Eigen::Vector3d>& world_centres) { Build(world_centres); }

  // A motion of the world (a shift along the street, a turn about the courtyard) written in k's
  // frame, the form Link's `error` takes.
  Similarity3 WorldMotionIn(int k, const Similarity3& world_motion) const {
    const Similarity3& frame = frames[static_cast<size_t>(k)];
    return frame.Compose(world_motion).Compose(frame.Inverse());
  }

  // The exact link k1 -> k2 (k1 < k2), optionally followed by a wrong motion `error` in k1's frame.
  SubgraphLink Link(int k1, int k2, size_t support, const Similarity3& error = {},
                    double trust = std::numeric_limits<double>::infinity()) const {
    const Similarity3 exact = frames[static_cast<size_t>(k1)].Compose(frames[static_cast<size_t>(k2)].Inverse());
    return {k1, k2, error.Compose(exact), support, trust};
  }

 private:
  void Build(const std::vector<Eigen::Vector3d>& world_centres) {
    for (size_t k = 0; k < world_centres.size(); ++k) {
      frames.push_back(RandomSimilarity(100 + k, 0.5 + 0.3 * static_cast<double>(k)));
      SubgraphFrame frame;
      frame.center = frames[k].Apply(world_centres[k]);
      frame.radius = frames[k].scale;
      subgraphs.push_back(frame);
    }
  }
};

// A twin-like error: a turn about an axis through `centre` (in k1's frame).
inline Similarity3 TurnAbout(const Eigen::Vector3d& centre, double degrees) {
  Similarity3 turn;
  turn.rotation = ExpSO3(DegToRad(degrees) * Eigen::Vector3d(0.2, 0.3, 1.0).normalized());
  turn.translation = centre - turn.rotation * centre;
  return turn;
}

}  // namespace sfm_pruning::testing
