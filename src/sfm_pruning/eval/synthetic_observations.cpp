#include "sfm_pruning/eval/synthetic_observations.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "sfm_pruning/eval/synthetic_random.hpp"

namespace sfm_pruning {
namespace {

// Points closer than this to the camera plane are not imaged (near clipping plane).
constexpr double kNearPlaneM = 0.1;
// Physical size of the image patch a keypoint describes, to give keypoints a scale that shrinks
// with distance, as SIFT's does.
constexpr double kPatchSizeM = 0.05;
constexpr float kMinKeypointScale = 1.2f;
constexpr float kMaxKeypointScale = 40.f;
constexpr double kOrientationNoiseRad = 0.05;

// Buckets the points on a horizontal grid so that each view tests only the points within reach
// (sequential_large has far more points than one view can see).
class PointGrid {
 public:
  PointGrid(const std::vector<SurfacePoint>& points, double cell_m) : cell_m_(cell_m) {
    for (size_t k = 0; k < points.size(); ++k) cells_[CellOf(points[k].X)].push_back(static_cast<IndexT>(k));
  }

  // Ids of the points within `radius` (in x and y) of `center`, ascending, plus a few more.
  std::vector<IndexT> Near(const Eigen::Vector3d& center, double radius) const {
    const auto lo = CellOf(center - Eigen::Vector3d(radius, radius, 0.0));
    const auto hi = CellOf(center + Eigen::Vector3d(radius, radius, 0.0));
    std::vector<IndexT> ids;
    for (auto it = cells_.lower_bound({lo.first, lo.second}); it != cells_.end() && it->first.first <= hi.first; ++it) {
      if (it->first.second < lo.second || it->first.second > hi.second) continue;
      ids.insert(ids.end(), it->second.begin(), it->second.end());
    }
    std::sort(ids.begin(), ids.end());
    return ids;
  }

 private:
  std::pair<long, long> CellOf(const Eigen::Vector3d& X) const {
    return {std::lround(std::floor(X.x() / cell_m_)), std::lround(std::floor(X.y() / cell_m_))};
  }

  double cell_m_;
  std::map<std::pair<long, long>, std::vector<IndexT>> cells_;
};

struct ViewRender {
  FeatureSet features;
  std::vector<IndexT> feature_landmarks;
};

ViewRender RenderView(IndexT view_id, const Pose& pose, const SceneLayout& layout, const PointGrid& grid,
                      const CameraIntrinsics& intrinsics, const AppearanceTable& appearances,
                      const SyntheticSceneOptions& options) {
  std::mt19937_64 rng = MakeSyntheticRng(options.seed, SyntheticStream::kView, view_id);
  std::bernoulli_distribution dropped(options.dropout);
  std::normal_distribution<double> pixel_noise(0.0, options.noise_px);
  std::normal_distribution<float> orientation_noise(0.f, static_cast<float>(kOrientationNoiseRad));
  const bool facing_test = options.max_incidence_deg < 90.0;
  const double min_cos_incidence = std::cos(DegToRad(options.max_incidence_deg));
  const double max_x = intrinsics.width() - 1.0, max_y = intrinsics.height() - 1.0;
  const double focal = intrinsics.FocalLength();

  ViewRender out;
  for (IndexT id : grid.Near(pose.center, options.max_distance_m)) {
    const SurfacePoint& point = layout.points[id];
    const Eigen::Vector3d to_camera = pose.center - point.X;
    const double distance = to_camera.norm();
    if (distance > options.max_distance_m) continue;
    if (facing_test && point.normal.dot(to_camera) < min_cos_incidence * distance) continue;
    const Eigen::Vector3d X_cam = pose.ToCamera(point.X);
    if (X_cam.z() < kNearPlaneM) continue;
    const Eigen::Vector2d projected = intrinsics.Project(X_cam);
    if (projected.x() < 0.0 || projected.y() < 0.0 || projected.x() > max_x || projected.y() > max_y) continue;
    // A fixed number of draws per visible point keeps each draw tied to its point.
    const bool is_dropped = dropped(rng);
    const double nx = pixel_noise(rng);
    const double ny = pixel_noise(rng);
    const float dtheta = orientation_noise(rng);
    const Descriptor descriptor = ObserveDescriptor(appearances.histograms[point.appearance], options.descriptor_noise, rng);
    const Eigen::Vector2d noisy = projected + Eigen::Vector2d(nx, ny);
    if (is_dropped || noisy.x() < 0.0 || noisy.y() < 0.0 || noisy.x() > max_x || noisy.y() > max_y) continue;
    Keypoint keypoint;
    keypoint.x = static_cast<float>(noisy.x());
    keypoint.y = static_cast<float>(noisy.y());
    keypoint.scale = std::clamp(static_cast<float>(kPatchSizeM * focal / X_cam.z()), kMinKeypointScale, kMaxKeypointScale);
    keypoint.orientation = appearances.orientations[point.appearance] + dtheta;
    out.features.keypoints.push_back(keypoint);
    out.features.descriptors.push_back(descriptor);
    out.feature_landmarks.push_back(id);
  }

  // Clutter: keypoints on texture that no other view detects again (foliage, reflections).
  const auto num_clutter = static_cast<size_t>(std::lround(options.clutter_ratio * out.features.size()));
  std::uniform_real_distribution<double> clutter_x(0.0, max_x), clutter_y(0.0, max_y);
  std::uniform_real_distribution<float> clutter_scale(kMinKeypointScale, 8.f);
  std::uniform_real_distribution<float> clutter_angle(static_cast<float>(-M_PI), static_cast<float>(M_PI));
  for (size_t k = 0; k < num_clutter; ++k) {
    Keypoint keypoint;
    keypoint.x = static_cast<float>(clutter_x(rng));
    keypoint.y = static_cast<float>(clutter_y(rng));
    keypoint.scale = clutter_scale(rng);
    keypoint.orientation = clutter_angle(rng);
    out.features.keypoints.push_back(keypoint);
    out.features.descriptors.push_back(QuantizeSiftHistogram(RandomDescriptorHistogram(rng)));
    out.feature_landmarks.push_back(kUndefinedIndex);
  }

  // Shuffle: a detector's output order (by scale-space octave) is unrelated to the landmarks.
  std::vector<size_t> order(out.features.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  ViewRender shuffled;
  shuffled.features.keypoints.reserve(order.size());
  shuffled.features.descriptors.reserve(order.size());
  shuffled.feature_landmarks.reserve(order.size());
  for (size_t k : order) {
    shuffled.features.keypoints.push_back(out.features.keypoints[k]);
    shuffled.features.descriptors.push_back(out.features.descriptors[k]);
    shuffled.feature_landmarks.push_back(out.feature_landmarks[k]);
  }
  return shuffled;
}

}  // namespace

AppearanceTable MakeAppearanceTable(IndexT num_appearances, uint64_t seed) {
  AppearanceTable table;
  table.histograms.reserve(num_appearances);
  table.orientations.reserve(num_appearances);
  std::uniform_real_distribution<float> angle(static_cast<float>(-M_PI), static_cast<float>(M_PI));
  for (IndexT a = 0; a < num_appearances; ++a) {
    std::mt19937_64 rng = MakeSyntheticRng(seed, SyntheticStream::kAppearance, a);
    table.histograms.push_back(RandomDescriptorHistogram(rng));
    table.orientations.push_back(angle(rng));
  }
  return table;
}

RenderedViews RenderViews(const SceneLayout& layout, const CameraIntrinsics& intrinsics,
                          const AppearanceTable& appearances, const SyntheticSceneOptions& options,
                          const ProgressCallback& progress) {
  const PointGrid grid(layout.points, std::max(1.0, options.max_distance_m));
  RenderedViews rendered;
  const size_t num_views = layout.poses.size();
  for (size_t v = 0; v < num_views; ++v) {
    const auto view_id = static_cast<IndexT>(v);
    ViewRender view = RenderView(view_id, layout.poses[v], layout, grid, intrinsics, appearances, options);
    for (size_t f = 0; f < view.feature_landmarks.size(); ++f) {
      const IndexT landmark_id = view.feature_landmarks[f];
      if (landmark_id == kUndefinedIndex) continue;
      Landmark& landmark = rendered.landmarks[landmark_id];
      landmark.X = layout.points[landmark_id].X;
      Observation& observation = landmark.observations[view_id];
      observation.x = view.features.Position(f);
      observation.id_feat = static_cast<IndexT>(f);
    }
    rendered.features[view_id] = std::move(view.features);
    rendered.feature_landmarks[view_id] = std::move(view.feature_landmarks);
    ReportProgress(progress, "synth: render views", v + 1, num_views);
  }
  return rendered;
}

}  // namespace sfm_pruning
