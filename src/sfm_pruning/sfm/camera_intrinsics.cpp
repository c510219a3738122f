#include "sfm_pruning/sfm/camera_intrinsics.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

struct ModelInfo {
  CameraModel model;
  const char* name;
  size_t num_params;
};

constexpr ModelInfo kModels[] = {
    {CameraModel::kPinhole, "pinhole", 3},
    {CameraModel::kPinholeRadialK1, "pinhole_radial_k1", 4},
    {CameraModel::kPinholeRadialK3, "pinhole_radial_k3", 6},
    {CameraModel::kPinholeBrownT2, "pinhole_brown_t2", 8},
    {CameraModel::kFisheye, "fisheye", 7},
    {CameraModel::kPinholeFxFy, "pinhole_fx_fy", 4},
    {CameraModel::kSpherical, "spherical", 0},
};

const ModelInfo& Info(CameraModel model) {
  for (const ModelInfo& info : kModels) {
    if (info.model == model) return info;
  }
  throw Error("internal: unknown camera model enum value");
}

// Spherical cameras: longitude/latitude image, full turn over max(width, height) pixels.
double SphericalScale(uint32_t width, uint32_t height) {
  return static_cast<double>(std::max(width, height)) / (2.0 * M_PI);
}

}  // namespace

size_t NumCameraParams(CameraModel model) { return Info(model).num_params; }
std::string CameraModelName(CameraModel model) { return Info(model).name; }

bool CameraModelFromName(const std::string& name, CameraModel* model) {
  for (const ModelInfo& info : kModels) {
    if (name == info.name) {
      *model = info.model;
      return true;
    }
  }
  return false;
}

CameraIntrinsics::CameraIntrinsics(CameraModel model, uint32_t width, uint32_t height,
                                   std::vector<double> params)
    : model_(model), width_(width), height_(height), params_(std::move(params)) {
  if (params_.size() != NumCameraParams(model)) {
    throw Error("camera model " + CameraModelName(model) + " takes " +
                std::to_string(NumCameraParams(model)) + " parameters, got " +
                std::to_string(params_.size()));
  }
}

CameraIntrinsics CameraIntrinsics::Pinhole(uint32_t width, uint32_t height, double focal, double cx,
                                           double cy) {
  return CameraIntrinsics(CameraModel::kPinhole, width, height, {focal, cx, cy});
}

CameraIntrinsics CameraIntrinsics::Undistorted(CameraModel model, uint32_t width, uint32_t height,
                                               double focal, double cx, double cy) {
  std::vector<double> params(NumCameraParams(model), 0.0);
  if (model == CameraModel::kPinholeFxFy) {
    params = {focal, focal, cx, cy};
  } else if (model != CameraModel::kSpherical) {
    params[0] = focal;
    params[1] = cx;
    params[2] = cy;
  }
  return CameraIntrinsics(model, width, height, std::move(params));
}

double CameraIntrinsics::FocalX() const {
  if (model_ == CameraModel::kSpherical) return SphericalScale(width_, height_);
  return params_[0];
}

double CameraIntrinsics::FocalY() const {
  if (model_ == CameraModel::kSpherical) return SphericalScale(width_, height_);
  return model_ == CameraModel::kPinholeFxFy ? params_[1] : params_[0];
}

double CameraIntrinsics::FocalLength() const { return 0.5 * (FocalX() + FocalY()); }

Eigen::Vector2d CameraIntrinsics::PrincipalPoint() const {
  if (model_ == CameraModel::kSpherical) return {width_ / 2.0, height_ / 2.0};
  if (model_ == CameraModel::kPinholeFxFy) return {params_[2], params_[3]};
  return {params_[1], params_[2]};
}

void CameraIntrinsics::SetFocalLength(double focal) {
  if (model_ == CameraModel::kSpherical) return;
  params_[0] = focal;
  if (model_ == CameraModel::kPinholeFxFy) params_[1] = focal;
}

void CameraIntrinsics::SetPrincipalPoint(const Eigen::Vector2d& pp) {
  if (model_ == CameraModel::kSpherical) return;
  const size_t first = model_ == CameraModel::kPinholeFxFy ? 2 : 1;
  params_[first] = pp.x();
  params_[first + 1] = pp.y();
}

std::vector<double> CameraIntrinsics::DistortionParams() const {
  if (model_ == CameraModel::kSpherical || model_ == CameraModel::kPinholeFxFy) return {};
  return std::vector<double>(params_.begin() + camera_models::kFirstDistortionParam, params_.end());
}

bool CameraIntrinsics::HasDistortion() const {
  for (double k : DistortionParams()) {
    if (k != 0.0) return true;
  }
  return false;
}

Eigen::Vector2d CameraIntrinsics::Project(const Eigen::Vector3d& X_cam) const {
  if (model_ == CameraModel::kSpherical) {
    const double lon = std::atan2(X_cam.x(), X_cam.z());
    const double lat = std::atan2(-X_cam.y(), std::hypot(X_cam.x(), X_cam.z()));
    const double scale = SphericalScale(width_, height_);
    return {lon * scale + width_ / 2.0, -lat * scale + height_ / 2.0};
  }
  Eigen::Vector2d pixel;
  camera_models::ProjectPinhole(model_, params_.data(), X_cam.data(), pixel.data());
  return pixel;
}

Eigen::Vector2d CameraIntrinsics::NormalizedToPixel(const Eigen::Vector2d& normalized) const {
  return Project(Eigen::Vector3d(normalized.x(), normalized.y(), 1.0));
}

Eigen::Vector2d CameraIntrinsics::PixelToNormalized(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d pp = PrincipalPoint();
  const Eigen::Vector2d distorted((pixel.x() - pp.x()) / FocalX(), (pixel.y() - pp.y()) / FocalY());
  return RemoveDistortion(distorted);
}

Eigen::Vector3d CameraIntrinsics::Unproject(const Eigen::Vector2d& pixel) const {
  if (model_ == CameraModel::kSpherical) {
    const double scale = SphericalScale(width_, height_);
    const double lon = (pixel.x() - width_ / 2.0) / scale;
    const double lat = -(pixel.y() - height_ / 2.0) / scale;
    return {std::cos(lat) * std::sin(lon), -std::sin(lat), std::cos(lat) * std::cos(lon)};
  }
  const Eigen::Vector2d xy = PixelToNormalized(pixel);
  return Eigen::Vector3d(xy.x(), xy.y(), 1.0).normalized();
}

// Inverts the distortion by Gauss-Newton on Distort(x) = distorted, with a numerical Jacobian.
// Converges in a handful of iterations for every realistic coefficient set; the iteration count
// is bounded so that a pathological calibration degrades instead of hanging.
Eigen::Vector2d CameraIntrinsics::RemoveDistortion(const Eigen::Vector2d& distorted) const {
  if (model_ == CameraModel::kFisheye) return RemoveFisheyeDistortion(distorted);
  if (!HasDistortion()) return distorted;
  const auto distort = [this](const Eigen::Vector2d& p) {
    Eigen::Vector2d out;
    camera_models::Distort(model_, params_.data(), p.x(), p.y(), &out.x(), &out.y());
    return out;
  };
  Eigen::Vector2d x = distorted;
  constexpr int kMaxIterations = 100;
  constexpr double kStep = 1e-7;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Eigen::Vector2d residual = distort(x) - distorted;
    if (residual.squaredNorm() < 1e-30) break;
    Eigen::Matrix2d J;
    for (int axis = 0; axis < 2; ++axis) {
      Eigen::Vector2d dx = Eigen::Vector2d::Zero();
      dx[axis] = kStep;
      J.col(axis) = (distort(x + dx) - distort(x - dx)) / (2.0 * kStep);
    }
    const Eigen::Vector2d step = J.fullPivLu().solve(residual);
    if (!step.allFinite()) break;
    x -= step;
    if (step.squaredNorm() < 1e-30) break;
  }
  return x;
}

// The fisheye model is radial in the angle theta off the optical axis: solve the 1-D equation
// theta_d = theta (1 + k1 theta^2 + ...) by Newton, then r = tan(theta). Rays at 90 degrees or more
// off axis have no point on the plane z = 1; they are clamped just inside it.
Eigen::Vector2d CameraIntrinsics::RemoveFisheyeDistortion(const Eigen::Vector2d& distorted) const {
  const double theta_d = distorted.norm();
  if (theta_d < 1e-12) return distorted;
  const double* k = params_.data() + camera_models::kFirstDistortionParam;
  double theta = theta_d;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double t2 = theta * theta;
    const double f = theta * (1 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3])))) - theta_d;
    const double df = 1 + t2 * (3 * k[0] + t2 * (5 * k[1] + t2 * (7 * k[2] + t2 * 9 * k[3])));
    if (df == 0.0) break;
    const double step = f / df;
    theta -= step;
    if (std::abs(step) < 1e-15) break;
  }
  theta = std::clamp(theta, 0.0, M_PI / 2 - 1e-9);
  return distorted * (std::tan(theta) / theta_d);
}

bool CameraIntrinsics::operator==(const CameraIntrinsics& other) const {
  return model_ == other.model_ && width_ == other.width_ && height_ == other.height_ &&
         params_ == other.params_;
}

}  // namespace sfm_pruning
