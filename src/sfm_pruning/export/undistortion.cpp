#include "sfm_pruning/export/undistortion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

constexpr int kSamplesPerEdge = 256;
// A border sample counts only if redistorting its undistorted position lands this close (pixels).
constexpr double kRoundTripTolerance = 0.01;

// The undistorted border of the original frame in normalized coordinates, divided by the original
// focal lengths' ratio so that one scale factor serves both axes: x_n * fx, y_n * fy (pixels
// relative to the principal point of a focal-scale-1 pinhole).
struct BorderExtent {
  // Innermost extent of each edge (the inscribed rectangle) and outermost extent of all samples.
  double inner_left = -std::numeric_limits<double>::infinity();
  double inner_right = std::numeric_limits<double>::infinity();
  double inner_top = -std::numeric_limits<double>::infinity();
  double inner_bottom = std::numeric_limits<double>::infinity();
  double outer_left = std::numeric_limits<double>::infinity();
  double outer_right = -std::numeric_limits<double>::infinity();
  double outer_top = std::numeric_limits<double>::infinity();
  double outer_bottom = -std::numeric_limits<double>::infinity();
  bool valid = false;
};

enum class Edge { kLeft, kRight, kTop, kBottom };

BorderExtent MeasureBorder(const CameraIntrinsics& camera) {
  BorderExtent extent;
  // The frame of pixel centres, [0, width - 1] x [0, height - 1]: bilinear sampling inside it never
  // blends in the black outside the image.
  const double left = 0.0, right = camera.width() - 1.0, top = 0.0, bottom = camera.height() - 1.0;
  const auto sample = [&](Edge edge, double t) {
    const Eigen::Vector2d pixel = edge == Edge::kLeft    ? Eigen::Vector2d(left, top + t * (bottom - top))
                                  : edge == Edge::kRight ? Eigen::Vector2d(right, top + t * (bottom - top))
                                  : edge == Edge::kTop   ? Eigen::Vector2d(left + t * (right - left), top)
                                                         : Eigen::Vector2d(left + t * (right - left), bottom);
    const Eigen::Vector2d normalized = camera.PixelToNormalized(pixel);
    if (!normalized.allFinite() ||
        (camera.NormalizedToPixel(normalized) - pixel).norm() > kRoundTripTolerance) {
      return;  // outside the domain where the distortion is invertible
    }
    const double x = normalized.x() * camera.FocalX();
    const double y = normalized.y() * camera.FocalY();
    extent.valid = true;
    extent.outer_left = std::min(extent.outer_left, x);
    extent.outer_right = std::max(extent.outer_right, x);
    extent.outer_top = std::min(extent.outer_top, y);
    extent.outer_bottom = std::max(extent.outer_bottom, y);
    if (edge == Edge::kLeft) extent.inner_left = std::max(extent.inner_left, x);
    if (edge == Edge::kRight) extent.inner_right = std::min(extent.inner_right, x);
    if (edge == Edge::kTop) extent.inner_top = std::max(extent.inner_top, y);
    if (edge == Edge::kBottom) extent.inner_bottom = std::min(extent.inner_bottom, y);
  };
  for (Edge edge : {Edge::kLeft, Edge::kRight, Edge::kTop, Edge::kBottom}) {
    for (int k = 0; k <= kSamplesPerEdge; ++k) sample(edge, static_cast<double>(k) / kSamplesPerEdge);
  }
  return extent;
}

}  // namespace

const std::array<Eigen::Matrix3d, kNumCubeFaces>& CubeFaceRotations() {
  // Rows: the face's x (right), y (down) and z (forward) axes in the spherical camera's frame.
  static const std::array<Eigen::Matrix3d, kNumCubeFaces> rotations = [] {
    const auto face = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
      Eigen::Matrix3d R;
      R << x.transpose(), y.transpose(), x.cross(y).transpose();
      return R;
    };
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                          Z = Eigen::Vector3d::UnitZ();
    return std::array<Eigen::Matrix3d, kNumCubeFaces>{face(X, Y), face(-Z, Y), face(-X, Y),
                                                      face(Z, Y), face(X, Z),  face(X, -Z)};
  }();
  return rotations;
}

const std::array<std::string, kNumCubeFaces>& CubeFaceNames() {
  static const std::array<std::string, kNumCubeFaces> names = {"front", "right", "back",
                                                               "left",  "up",    "down"};
  return names;
}

int CubeFaceOf(const Eigen::Vector3d& bearing) {
  int best = 0;
  for (int face = 1; face < kNumCubeFaces; ++face) {
    if (CubeFaceRotations()[face].row(2).dot(bearing) > CubeFaceRotations()[best].row(2).dot(bearing))
      best = face;
  }
  return best;
}

CameraIntrinsics UndistortedIntrinsics(const CameraIntrinsics& camera, const UndistortOptions& options) {
  options.Check();  // std::clamp below needs min <= max
  if (camera.model() == CameraModel::kSpherical) {
    // 90 degrees over `size` pixels: the face spans [-0.5, size - 0.5], tan(45) = 1 at its edges.
    const uint32_t size = std::max<uint32_t>(1, (std::max(camera.width(), camera.height()) + 2) / 4);
    const double focal = size / 2.0, centre = (size - 1.0) / 2.0;
    return CameraIntrinsics(CameraModel::kPinholeFxFy, size, size, {focal, focal, centre, centre});
  }
  const Eigen::Vector2d pp = camera.PrincipalPoint();
  if (!camera.HasDistortion()) {
    return CameraIntrinsics(CameraModel::kPinholeFxFy, camera.width(), camera.height(),
                            {camera.FocalX(), camera.FocalY(), pp.x(), pp.y()});
  }
  const BorderExtent border = MeasureBorder(camera);
  // Spans of the output's pixel centres, matched to the region's span.
  const double span_x = camera.width() - 1.0, span_y = camera.height() - 1.0;
  double scale = 1.0;
  double centre_x = 0.0, centre_y = 0.0;  // middle of the kept region, in focal-scale-1 pixels
  const bool inner = options.fit == UndistortFit::kNoBlackBorders;
  if (border.valid) {
    const double region_left = inner ? border.inner_left : border.outer_left;
    const double region_right = inner ? border.inner_right : border.outer_right;
    const double region_top = inner ? border.inner_top : border.outer_top;
    const double region_bottom = inner ? border.inner_bottom : border.outer_bottom;
    const double scale_x = span_x / (region_right - region_left);
    const double scale_y = span_y / (region_bottom - region_top);
    // Inside the frame: the output must not reach past the region in either direction, so the
    // larger scale (narrower view) wins; containing the frame: the smaller one.
    const double wanted = inner ? std::max(scale_x, scale_y) : std::min(scale_x, scale_y);
    if (std::isfinite(wanted) && wanted > 0) scale = wanted;
    centre_x = 0.5 * (region_left + region_right);
    centre_y = 0.5 * (region_top + region_bottom);
  }
  scale = std::clamp(scale, options.min_focal_scale, options.max_focal_scale);
  const double fx = scale * camera.FocalX();
  const double fy = scale * camera.FocalY();
  // Pixel (width - 1) / 2, the middle of the output, looks at the middle of the region.
  const double cx = 0.5 * span_x - scale * centre_x;
  const double cy = 0.5 * span_y - scale * centre_y;
  return CameraIntrinsics(CameraModel::kPinholeFxFy, camera.width(), camera.height(), {fx, fy, cx, cy});
}

bool SameProjection(const CameraIntrinsics& a, const CameraIntrinsics& b) {
  return IsPinholeFamily(a.model()) && IsPinholeFamily(b.model()) && !a.HasDistortion() &&
         !b.HasDistortion() && a.width() == b.width() && a.height() == b.height() &&
         a.FocalX() == b.FocalX() && a.FocalY() == b.FocalY() && a.PrincipalPoint() == b.PrincipalPoint();
}

Eigen::Vector2d DistortedPixel(const CameraIntrinsics& original, const CameraIntrinsics& undistorted,
                               const Eigen::Vector2d& undistorted_pixel) {
  return original.NormalizedToPixel(undistorted.PixelToNormalized(undistorted_pixel));
}

Eigen::Vector2d UndistortedPixel(const CameraIntrinsics& original, const CameraIntrinsics& undistorted,
                                 const Eigen::Vector2d& distorted_pixel) {
  return undistorted.NormalizedToPixel(original.PixelToNormalized(distorted_pixel));
}

UndistortionMaps ComputeUndistortionMaps(const CameraIntrinsics& original,
                                         const CameraIntrinsics& undistorted,
                                         const Eigen::Matrix3d& rotation) {
  const int width = static_cast<int>(undistorted.width());
  const int height = static_cast<int>(undistorted.height());
  UndistortionMaps maps{cv::Mat(height, width, CV_32FC1), cv::Mat(height, width, CV_32FC1)};
  // The undistorted camera has no distortion, so its pixel -> normalized step is linear.
  const double fx = undistorted.FocalX(), fy = undistorted.FocalY();
  const Eigen::Vector2d pp = undistorted.PrincipalPoint();
  const bool rotated = !rotation.isIdentity();
  const Eigen::Matrix3d to_original = rotation.transpose();
  cv::parallel_for_(cv::Range(0, height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      float* row_x = maps.map_x.ptr<float>(v);
      float* row_y = maps.map_y.ptr<float>(v);
      const double y = (v - pp.y()) / fy;
      for (int u = 0; u < width; ++u) {
        const Eigen::Vector3d ray((u - pp.x()) / fx, y, 1.0);
        const Eigen::Vector2d source = rotated ? original.Project(to_original * ray) : original.Project(ray);
        row_x[u] = static_cast<float>(source.x());
        row_y[u] = static_cast<float>(source.y());
      }
    }
  });
  return maps;
}

cv::Mat UndistortImage(const cv::Mat& image, const UndistortionMaps& maps) {
  cv::Mat undistorted;
  cv::remap(image, undistorted, maps.map_x, maps.map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
            cv::Scalar::all(0));
  return undistorted;
}

void UndistortOptions::Check() const {
  // The focal scale is positive before the clamp: a minimum of 0 or a maximum of infinity
  // clamps nothing, but an infinite minimum would give an infinite focal.
  if (!(min_focal_scale >= 0.0 && std::isfinite(min_focal_scale))) {
    option_checks_detail::Fail("UndistortOptions::min_focal_scale", "at least 0 and finite", min_focal_scale);
  }
  if (!(max_focal_scale > 0.0 && max_focal_scale >= min_focal_scale)) {
    std::ostringstream rule;
    rule << "positive and at least min_focal_scale (" << min_focal_scale << ")";
    option_checks_detail::Fail("UndistortOptions::max_focal_scale", rule.str(), max_focal_scale);
  }
}

}  // namespace sfm_pruning
