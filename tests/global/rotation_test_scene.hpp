// Synthetic rotation-averaging scenes for the rotation_* tests and the benchmark: random
// absolute rotations, a connected graph (ring + random chords), relative rotations computed
// from the truth, optional noise and corrupted edges, and the alignment of an estimate onto the
// truth (rotation averaging only recovers rotations up to a global rotation).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/global/rotation_averaging.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning::testing {

inline Eigen::Vector3d RandomUnitVector(std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d v;
  do {
    v = Eigen::Vector3d(normal(*rng), normal(*rng), normal(*rng));
  } while (v.norm() < 1e-6);
  return v.normalized();
}

// Uniform on SO(3): a normalised 4D Gaussian is a uniform unit quaternion.
inline Eigen::Matrix3d UniformRandomRotation(std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(*rng), normal(*rng), normal(*rng), normal(*rng));
  return q.normalized().toRotationMatrix();
}

// A rotation by exactly `angle_rad` about a random axis.
inline Eigen::Matrix3d RandomRotationOfAngle(std::mt19937* rng, double angle_rad) {
  return ExpSO3(angle_rad * RandomUnitVector(rng));
}

struct RotationSceneOptions {
  size_t num_views = 100;
  // The ring links each view to the next `ring_neighbors` views (a video-like band when there
  // are no chords).
  size_t ring_neighbors = 1;
  // Besides the ring, each view gets this many chords to random other views
  // (duplicates skipped), so the average degree is about 2 * (ring_neighbors + chords_per_view).
  size_t chords_per_view = 3;
  // Inlier edges: R_ij perturbed by a rotation of angle uniform in [0, noise_deg].
  double noise_deg = 0.0;
  // This fraction of the edges is replaced by R_ij times a rotation of angle uniform in
  // [min_outlier_angle_deg, 180].
  double outlier_fraction = 0.0;
  double min_outlier_angle_deg = 30.0;
  // View ids are first_id, first_id + id_step, ... (not 0..n-1, to exercise the id mapping).
  IndexT first_id = 10;
  IndexT id_step = 3;
  uint32_t seed = 1;
};

// The common case: ring + chords, uniform noise on inliers, a fraction of corrupted edges.
inline RotationSceneOptions SceneOptions(size_t num_views, size_t chords_per_view, double noise_deg = 0.0,
                                         double outlier_fraction = 0.0) {
  RotationSceneOptions options;
  options.num_views = num_views;
  options.chords_per_view = chords_per_view;
  options.noise_deg = noise_deg;
  options.outlier_fraction = outlier_fraction;
  return options;
}

struct RotationScene {
  std::map<IndexT, Eigen::Matrix3d> truth;  // world -> camera
  ViewGraph graph;
  std::set<ViewPair> corrupted;
};

inline RotationScene MakeRotationScene(const RotationSceneOptions& options) {
  std::mt19937 rng(options.seed);
  RotationScene scene;
  std::vector<IndexT> ids;
  for (size_t k = 0; k < options.num_views; ++k) {
    ids.push_back(options.first_id + static_cast<IndexT>(k) * options.id_step);
    scene.truth[ids.back()] = UniformRandomRotation(&rng);
  }
  std::set<ViewPair> pairs;
  const size_t n = ids.size();
  for (size_t k = 0; n >= 2 && k < n; ++k) {
    for (size_t step = 1; step <= options.ring_neighbors && step < n; ++step) {
      pairs.insert(MakeViewPair(ids[k], ids[(k + step) % n]));
    }
  }
  std::uniform_int_distribution<size_t> any_view(0, n - 1);
  for (size_t k = 0; k < n; ++k) {
    for (size_t c = 0; c < options.chords_per_view; ++c) {
      const size_t other = any_view(rng);
      if (other != k) pairs.insert(MakeViewPair(ids[k], ids[other]));
    }
  }
  std::vector<ViewPair> shuffled(pairs.begin(), pairs.end());
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  const auto num_outliers = static_cast<size_t>(options.outlier_fraction * shuffled.size() + 0.5);
  scene.corrupted.insert(shuffled.begin(), shuffled.begin() + num_outliers);

  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> inliers(30, 300);
  const double min_outlier_rad = DegToRad(options.min_outlier_angle_deg);
  for (const ViewPair& pair : pairs) {
    Eigen::Matrix3d R_ij = scene.truth.at(pair.second) * scene.truth.at(pair.first).transpose();
    if (scene.corrupted.count(pair) > 0) {
      const double angle = min_outlier_rad + unit(rng) * (M_PI - min_outlier_rad);
      R_ij = R_ij * RandomRotationOfAngle(&rng, angle);
    } else if (options.noise_deg > 0.0) {
      R_ij = RandomRotationOfAngle(&rng, DegToRad(options.noise_deg) * unit(rng)) * R_ij;
    }
    ViewGraphEdge edge;
    edge.relative_pose = RelativePose(R_ij, Eigen::Vector3d::UnitX());
    edge.weight = inliers(rng);
    scene.graph.AddEdge(pair, edge);
  }
  return scene;
}

// Angle (deg) of each estimated rotation to the truth after the best global alignment G
// (R_est ~ R_true G): G is the chordal mean of R_true^T R_est over the estimated views.
inline std::map<IndexT, double> AlignedRotationErrorsDeg(const std::map<IndexT, Eigen::Matrix3d>& truth,
                                                         const std::map<IndexT, Eigen::Matrix3d>& estimate) {
  std::vector<Eigen::Matrix3d> offsets;
  for (const auto& [id, R_est] : estimate) offsets.push_back(truth.at(id).transpose() * R_est);
  const Eigen::Matrix3d G = ChordalMeanRotation(offsets);
  std::map<IndexT, double> errors;
  for (const auto& [id, R_est] : estimate) {
    errors[id] = RadToDeg(LogSO3((truth.at(id) * G).transpose() * R_est).norm());
  }
  return errors;
}

inline double MaxValue(const std::map<IndexT, double>& values) {
  double largest = 0.0;
  for (const auto& [id, value] : values) largest = std::max(largest, value);
  return largest;
}

inline double MeanValue(const std::map<IndexT, double>& values) {
  double sum = 0.0;
  for (const auto& [id, value] : values) sum += value;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

struct TimedRotationAveraging {
  RotationAveragingResult result;
  std::map<IndexT, Eigen::Matrix3d> rotations;
  double seconds = 0.0;
  std::map<IndexT, double> errors_deg;  // AlignedRotationErrorsDeg against the scene's truth

  // One line for the test log: size, time, iterations, accuracy, filtering.
  std::string Summary(const RotationScene& scene) const {
    std::ostringstream out;
    out << scene.truth.size() << " views, " << scene.graph.NumEdges() << " edges: " << seconds << " s ("
        << result.num_l1_iterations << " L1 + " << result.num_irls_iterations << " IRLS iterations, "
        << result.num_linear_solver_iterations << " CG iterations); error mean " << MeanValue(errors_deg)
        << " deg, max " << MaxValue(errors_deg) << " deg; " << result.filtered_edges.size()
        << " edges filtered, " << scene.corrupted.size() << " corrupted";
    return out.str();
  }
};

// EstimateGlobalRotations on the scene's graph (modified: filtered edges), timed.
inline TimedRotationAveraging RunTimedRotationAveraging(RotationScene* scene,
                                                        const RotationAveragingOptions& options = {}) {
  TimedRotationAveraging run;
  const auto start = std::chrono::steady_clock::now();
  run.result = EstimateGlobalRotations(&scene->graph, options, &run.rotations);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (run.result.success) run.errors_deg = AlignedRotationErrorsDeg(scene->truth, run.rotations);
  return run;
}

}  // namespace sfm_pruning::testing
