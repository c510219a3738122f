#include "sfm_pruning/sfm/sfm_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include <Eigen/Dense>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

bool SfmData::IsPosed(const View& view) const {
  return poses.count(view.id_pose) != 0 && intrinsics.count(view.id_intrinsic) != 0;
}

const CameraIntrinsics* SfmData::FindIntrinsics(IndexT view_id) const {
  const auto view = views.find(view_id);
  if (view == views.end()) return nullptr;
  const auto it = intrinsics.find(view->second.id_intrinsic);
  return it == intrinsics.end() ? nullptr : &it->second;
}

bool SfmData::IsPosed(IndexT view_id) const {
  const auto it = views.find(view_id);
  return it != views.end() && IsPosed(it->second);
}

std::vector<IndexT> SfmData::PosedViewIds() const {
  std::vector<IndexT> ids;
  for (const auto& [id, view] : views) {
    if (IsPosed(view)) ids.push_back(id);
  }
  return ids;
}

bool SfmData::PosesEqual(const SfmData& o) const {
  if (poses.size() != o.poses.size()) return false;
  for (auto a = poses.begin(), b = o.poses.begin(); a != poses.end(); ++a, ++b) {
    if (a->first != b->first || a->second.rotation != b->second.rotation ||
        a->second.center != b->second.center) {
      return false;
    }
  }
  return true;
}

void ValidateSfmData(const SfmData& data, const std::string& source, bool intrinsics_loaded) {
  std::set<IndexT> used_intrinsics, used_poses;
  for (const auto& [key, view] : data.views) {
    if (view.id_view != key) {
      throw FileError(source, "view key " + std::to_string(key) + " holds id_view " +
                                  std::to_string(view.id_view));
    }
    if (intrinsics_loaded && view.id_intrinsic != kUndefinedIndex && !data.intrinsics.count(view.id_intrinsic)) {
      throw FileError(source, "view " + std::to_string(key) + " names intrinsic " +
                                  std::to_string(view.id_intrinsic) + ", which does not exist");
    }
    used_intrinsics.insert(view.id_intrinsic);
    used_poses.insert(view.id_pose);
  }
  for (const auto& [id, intrinsic] : data.intrinsics) {
    if (!used_intrinsics.count(id)) {
      throw FileError(source, "intrinsic " + std::to_string(id) + " is used by no view");
    }
  }
  for (const auto& [id, pose] : data.poses) {
    if (!used_poses.count(id)) throw FileError(source, "pose " + std::to_string(id) + " is used by no view");
  }
  const auto check_observations = [&](const std::map<IndexT, Landmark>& landmarks, const char* what) {
    for (const auto& [id, landmark] : landmarks) {
      for (const auto& [view_id, observation] : landmark.observations) {
        if (!data.views.count(view_id)) {
          throw FileError(source, std::string(what) + " " + std::to_string(id) +
                                      " is observed in view " + std::to_string(view_id) +
                                      ", which does not exist");
        }
      }
    }
  };
  check_observations(data.structure, "landmark");
  check_observations(data.control_points, "control point");
  ValidateSfmDataValues(data, source);
}

namespace {

constexpr double kMaxImageSidePx = 1e6;
// Focal lengths and principal-point offsets beyond this many image sides are unit mistakes, not
// lenses (a field of view under 0.06 degrees).
constexpr double kMaxImageSidesAway = 1000.0;
// Scene coordinates (any unit: metres, feet, even ECEF) stay far below this; beyond it squared
// distances lose every digit of the scene next to the offset, and 1e308 overflows to infinity.
constexpr double kMaxSceneCoordinate = 1e12;
// Pixel coordinates: kMaxImageSidesAway sides of the largest image kMaxImageSidePx allows.
constexpr double kMaxPixelCoordinate = kMaxImageSidesAway * kMaxImageSidePx;
// Rotations read from text files carry rounding: |RᵀR − I| and |det R − 1| within this are proper.
constexpr double kRotationTolerance = 1e-3;

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

bool AllFinite(const Eigen::Ref<const Eigen::MatrixXd>& values) { return values.allFinite(); }

// Finite and within ±limit in every coordinate.
bool Plausible(const Eigen::Ref<const Eigen::MatrixXd>& values, double limit) {
  return values.allFinite() && values.cwiseAbs().maxCoeff() <= limit;
}

std::string NotPlausible(double limit) { return "not finite or beyond ±" + Number(limit); }

}  // namespace

std::string IntrinsicsProblem(const CameraIntrinsics& intrinsics) {
  const double width = intrinsics.width(), height = intrinsics.height();
  if (width <= 0 || height <= 0 || width > kMaxImageSidePx || height > kMaxImageSidePx) {
    return "image size " + Number(width) + "x" + Number(height) + " is not a real image's";
  }
  for (const double value : intrinsics.params()) {
    if (!std::isfinite(value)) return "a parameter is not a finite number (" + Number(value) + ")";
  }
  const double focal_x = intrinsics.FocalX(), focal_y = intrinsics.FocalY();
  if (!(focal_x > 0.0) || !(focal_y > 0.0)) {
    return "focal length must be positive, got " + Number(std::min(focal_x, focal_y));
  }
  const double limit = kMaxImageSidesAway * std::max(width, height);
  if (std::max(focal_x, focal_y) > limit) {
    return "focal length " + Number(std::max(focal_x, focal_y)) + " px is over " + Number(kMaxImageSidesAway) +
           " image sides";
  }
  const Eigen::Vector2d principal_point = intrinsics.PrincipalPoint();
  if ((principal_point - Eigen::Vector2d(width / 2, height / 2)).cwiseAbs().maxCoeff() > limit) {
    return "principal point (" + Number(principal_point.x()) + ", " + Number(principal_point.y()) + ") is over " +
           Number(kMaxImageSidesAway) + " image sides from the image";
  }
  return {};
}

void ValidateSfmDataValues(const SfmData& data, const std::string& source) {
  for (const auto& [id, intrinsics] : data.intrinsics) {
    const std::string problem = IntrinsicsProblem(intrinsics);
    if (!problem.empty()) throw FileError(source, "intrinsic " + std::to_string(id) + ": " + problem);
  }
  for (const auto& [id, pose] : data.poses) {
    const std::string name = "pose " + std::to_string(id);
    if (!Plausible(pose.center, kMaxSceneCoordinate)) {
      throw FileError(source, name + ": the centre is " + NotPlausible(kMaxSceneCoordinate));
    }
    if (!AllFinite(pose.rotation)) throw FileError(source, name + ": the rotation is not finite");
    const double orthogonality =
        (pose.rotation.transpose() * pose.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (orthogonality > kRotationTolerance || std::abs(pose.rotation.determinant() - 1.0) > kRotationTolerance) {
      throw FileError(source, name + ": the rotation is not a rotation matrix (orthonormal, determinant 1)");
    }
  }
  const auto check_landmarks = [&](const std::map<IndexT, Landmark>& landmarks, const char* what) {
    for (const auto& [id, landmark] : landmarks) {
      if (!Plausible(landmark.X, kMaxSceneCoordinate)) {
        throw FileError(source, std::string(what) + " " + std::to_string(id) + ": the position is " +
                                    NotPlausible(kMaxSceneCoordinate));
      }
      for (const auto& [view_id, observation] : landmark.observations) {
        if (!Plausible(observation.x, kMaxPixelCoordinate)) {
          throw FileError(source, std::string(what) + " " + std::to_string(id) + ": its observation in view " +
                                      std::to_string(view_id) + " is " + NotPlausible(kMaxPixelCoordinate) +
                                      " pixels");
        }
      }
    }
  };
  check_landmarks(data.structure, "landmark");
  check_landmarks(data.control_points, "control point");
}

}  // namespace sfm_pruning
