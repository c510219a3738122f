#include "pruning/pruning_test_scene.hpp"

#include <cmath>
#include <random>

#include "sfm_pruning/geometry/so3.hpp"

namespace sfm_pruning::testing {
namespace {

Eigen::Matrix3d LookAt(const Eigen::Vector3d& center, const Eigen::Vector3d& target) {
  const Eigen::Vector3d up(0.0, 0.0, 1.0);
  const Eigen::Vector3d z = (target - center).normalized();
  const Eigen::Vector3d y = -(up - up.dot(z) * z).normalized();
  const Eigen::Vector3d x = y.cross(z);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return R;
}

Eigen::Vector2d ProjectPoint(const PruningTestScene& scene, IndexT view, const Eigen::Vector3d& X) {
  return scene.views_and_intrinsics.intrinsics.at(0).Project(scene.poses[view].ToCamera(X));
}

Keypoint MakeKeypoint(const Eigen::Vector2d& pixel) {
  Keypoint keypoint;
  keypoint.x = static_cast<float>(pixel.x());
  keypoint.y = static_cast<float>(pixel.y());
  return keypoint;
}

}  // namespace

Similarity RandomSimilarity(uint64_t seed, double scale) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Similarity similarity;
  similarity.scale = scale;
  similarity.rotation = ExpSO3(Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
  similarity.translation = 3.0 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  return similarity;
}

PruningTestScene MakePruningTestScene(size_t num_views, size_t num_points, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  PruningTestScene scene;
  scene.views_and_intrinsics.intrinsics[0] = CameraIntrinsics::Pinhole(1000, 1000, 800.0, 500.0, 500.0);
  while (scene.points.size() < num_points) {
    const Eigen::Vector3d X(2.0 * uniform(rng), 2.0 * uniform(rng), 2.0 * uniform(rng));
    if (X.norm() <= 2.0) scene.points.push_back(X);
  }
  for (size_t v = 0; v < num_views; ++v) {
    const double angle = 2.0 * M_PI * static_cast<double>(v) / static_cast<double>(num_views) * 0.5;
    const Eigen::Vector3d center(8.0 * std::cos(angle), 8.0 * std::sin(angle), 1.0 + 0.5 * uniform(rng));
    const Eigen::Vector3d target(0.3 * uniform(rng), 0.3 * uniform(rng), 0.3 * uniform(rng));
    scene.poses.emplace_back(LookAt(center, target), center);
    View view;
    view.id_view = view.id_pose = static_cast<IndexT>(v);
    view.id_intrinsic = 0;
    view.width = view.height = 1000;
    scene.views_and_intrinsics.views[view.id_view] = view;
    FeatureSet& features = scene.features[view.id_view];
    for (const Eigen::Vector3d& X : scene.points) features.keypoints.push_back(MakeKeypoint(ProjectPoint(scene, view.id_view, X)));
    scene.graph.AddNode(view.id_view);
  }
  return scene;
}

void PruningTestScene::AddExactEdge(IndexT a, IndexT b, size_t num_points) {
  RelativePose relative = RelativePoseBetween(poses[a], poses[b]);
  relative.translation.normalize();
  std::vector<FeatureMatch> matches;
  const size_t n = num_points == 0 ? points.size() : num_points;
  for (IndexT p = 0; p < n; ++p) matches.push_back({p, p});
  graph.AddEdge(a, b, matches, relative);
}

void PruningTestScene::AddTwinEdge(IndexT i, IndexT j, const Similarity& twin, size_t num_points) {
  RelativePose relative = RelativePoseBetween(poses[i], poses[j]);
  relative.translation.normalize();
  std::vector<FeatureMatch> matches;
  FeatureSet& features_j = features.at(j);
  const size_t n = num_points == 0 ? points.size() : num_points;
  for (IndexT p = 0; p < n; ++p) {
    const auto feature = static_cast<IndexT>(features_j.size());
    features_j.keypoints.push_back(MakeKeypoint(ProjectPoint(*this, j, twin.Apply(points[p]))));
    matches.push_back({p, feature});
  }
  graph.AddEdge(i, j, matches, relative);
}

SubgraphSolution PruningTestScene::Solution(const std::vector<IndexT>& view_ids, const Similarity& frame) const {
  SubgraphSolution solution;
  for (IndexT view : view_ids) {
    solution.view_ids.insert(view);
    solution.poses[view] = frame.Apply(poses[view]);
  }
  for (IndexT p = 0; p < points.size(); ++p) {
    Landmark& landmark = solution.landmarks[p];
    landmark.X = frame.Apply(points[p]);
    for (IndexT view : view_ids) {
      const Eigen::Vector2d pixel = features.at(view).Position(p);
      landmark.observations[view] = Observation{pixel, p};
    }
  }
  return solution;
}

SfmData GroundTruthModel(const PruningTestScene& scene) {
  SfmData model = scene.views_and_intrinsics;
  for (const auto& [view_id, view] : model.views) model.poses[view.id_pose] = scene.poses[view_id];
  for (size_t p = 0; p < scene.points.size(); ++p) {
    Landmark landmark;
    landmark.X = scene.points[p];
    for (const auto& [view_id, view] : model.views) {
      landmark.observations[view_id] = {scene.features.at(view_id).Position(p), static_cast<IndexT>(p)};
    }
    model.structure[static_cast<IndexT>(p)] = landmark;
  }
  return model;
}

}  // namespace sfm_pruning::testing
