#include "sfm_pruning/global/bundle_observations.hpp"

#include <cmath>
#include <limits>

namespace sfm_pruning {

std::vector<PosedObservation> PosedObservationsOf(const SfmData& data, const Landmark& landmark) {
  std::vector<PosedObservation> posed;
  posed.reserve(landmark.observations.size());
  for (const auto& [view_id, observation] : landmark.observations) {
    const auto view_it = data.views.find(view_id);
    if (view_it == data.views.end() || !data.IsPosed(view_it->second)) continue;
    const View& view = view_it->second;
    posed.push_back({view_id, &view, &data.PoseOf(view), &data.IntrinsicsOf(view), &observation});
  }
  return posed;
}

double ReprojectionErrorPx(const CameraIntrinsics& intrinsics, const Pose& pose, const Eigen::Vector3d& X,
                           const Eigen::Vector2d& pixel) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d X_cam = pose.ToCamera(X);
  if (!IsPinholeFamily(intrinsics.model())) {
    if (X_cam.squaredNorm() == 0.0) return kInfinity;
    return AngleBetweenVectors(intrinsics.Unproject(pixel), X_cam) * intrinsics.FocalLength();
  }
  if (!(X_cam.z() > 0.0)) return kInfinity;
  return (intrinsics.Project(X_cam) - pixel).norm();
}

void SetLandmarkReprojectionErrors(SfmData* data) {
  for (auto& [id, landmark] : data->structure) {
    double sum = 0.0;
    size_t count = 0;
    for (const PosedObservation& observation : PosedObservationsOf(*data, landmark)) {
      sum += ReprojectionErrorPx(observation, landmark.X);
      ++count;
    }
    landmark.error = count > 0 && std::isfinite(sum) ? sum / static_cast<double>(count) : -1.0;
  }
}

}  // namespace sfm_pruning
