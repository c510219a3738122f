// Helpers shared by bundle adjustment, structure filtering and retriangulation: the observations
// of a landmark that can be used (their view has a pose and intrinsics), and the reprojection
// error of one observation in double precision.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// One observation of a landmark made by a posed view. Pointers into the SfmData it came from.
struct PosedObservation {
  IndexT view_id = kUndefinedIndex;
  const View* view = nullptr;
  const Pose* pose = nullptr;
  const CameraIntrinsics* intrinsics = nullptr;
  const Observation* observation = nullptr;
};

// The observations of `landmark` whose view is posed (SfmData::IsPosed), in view id order.
// Observations naming a view that does not exist are skipped as well.
std::vector<PosedObservation> PosedObservationsOf(const SfmData& data, const Landmark& landmark);

// Reprojection error of `pixel` for the world point `X`, in pixels. Pinhole family: distance
// between CameraIntrinsics::Project and the pixel. Spherical cameras: angle between the
// observed bearing and the point times the pixels per radian (no seam at +-180 degrees).
// +infinity when the point is behind a pinhole camera or at the camera centre.
double ReprojectionErrorPx(const CameraIntrinsics& intrinsics, const Pose& pose, const Eigen::Vector3d& X,
                           const Eigen::Vector2d& pixel);

inline double ReprojectionErrorPx(const PosedObservation& obs, const Eigen::Vector3d& X) {
  return ReprojectionErrorPx(*obs.intrinsics, *obs.pose, X, obs.observation->x);
}

// Sets each landmark's `error` (COLMAP's ERROR of a point) to the mean reprojection error in
// pixels of its posed observations at its current position; -1 when it has none, or when one is
// behind its camera (an error COLMAP's readers would print as infinity).
void SetLandmarkReprojectionErrors(SfmData* data);

}  // namespace sfm_pruning
