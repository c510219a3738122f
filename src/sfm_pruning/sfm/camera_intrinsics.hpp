// CameraIntrinsics: one intrinsic calibration (a camera body at one image size), a value type.
// The maths lives in camera_models.hpp; this class adds storage and the double-precision API.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/camera_models.hpp"

namespace sfm_pruning {

class CameraIntrinsics {
 public:
  CameraIntrinsics() = default;
  // Parameters in the model's layout (camera_models.hpp); throws Error if the count is wrong.
  CameraIntrinsics(CameraModel model, uint32_t width, uint32_t height, std::vector<double> params);

  // Convenience constructors.
  static CameraIntrinsics Pinhole(uint32_t width, uint32_t height, double focal, double cx, double cy);
  // A model with zero distortion and the given focal/principal point.
  static CameraIntrinsics Undistorted(CameraModel model, uint32_t width, uint32_t height, double focal,
                                      double cx, double cy);

  CameraModel model() const { return model_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  const std::vector<double>& params() const { return params_; }
  std::vector<double>& mutable_params() { return params_; }

  // Mean focal length in pixels (for spherical cameras: pixels per radian).
  double FocalLength() const;
  double FocalX() const;
  double FocalY() const;
  Eigen::Vector2d PrincipalPoint() const;
  void SetFocalLength(double focal);
  void SetPrincipalPoint(const Eigen::Vector2d& pp);
  // Distortion coefficients (empty for undistorted models).
  std::vector<double> DistortionParams() const;
  bool HasDistortion() const;

  // Camera-frame point -> pixel. For pinhole models the point must have z > 0.
  Eigen::Vector2d Project(const Eigen::Vector3d& X_cam) const;
  // Pixel -> unit bearing vector in the camera frame (inverse of Project up to scale).
  Eigen::Vector3d Unproject(const Eigen::Vector2d& pixel) const;
  // Pixel -> point (x, y) on the undistorted normalized plane z = 1 (pinhole family only).
  Eigen::Vector2d PixelToNormalized(const Eigen::Vector2d& pixel) const;
  // Normalized plane -> pixel, with distortion (pinhole family only).
  Eigen::Vector2d NormalizedToPixel(const Eigen::Vector2d& normalized) const;

  // Exact comparison of type, size and every parameter.
  bool operator==(const CameraIntrinsics& other) const;
  bool operator!=(const CameraIntrinsics& other) const { return !(*this == other); }

 private:
  Eigen::Vector2d RemoveDistortion(const Eigen::Vector2d& distorted) const;
  Eigen::Vector2d RemoveFisheyeDistortion(const Eigen::Vector2d& distorted) const;

  CameraModel model_ = CameraModel::kPinhole;
  uint32_t width_ = 0;
  uint32_t height_ = 0;
  std::vector<double> params_ = {1.0, 0.0, 0.0};
};

}  // namespace sfm_pruning
