// Undistortion to a pinhole camera: what every dense tool (COLMAP patch-match, OpenMVS, Gaussian
// splatting, NeRF) needs as input.
//
// The undistorted camera keeps the image size and the fx/fy ratio of the original and has no
// distortion; its focal length and principal point are chosen from the undistorted image of the
// original frame's border (the outermost pixel centres, sampled densely along the four edges):
//   kNoBlackBorders (default): the largest pinhole view inside the original frame, so every output
//     pixel has a source pixel; the corners that barrel distortion pushes out are cropped.
//   kKeepAllPixels: the smallest pinhole view containing the whole original frame, so no source
//     pixel is lost; the output has black borders where no source pixel lands.
// The kept region is centred in the output. The focal scale (new / old focal) is clamped to
// [min_focal_scale, max_focal_scale]: wide fisheye lenses have no finite pinhole view keeping all
// pixels, and a border sample whose undistortion does not converge is ignored.
//
// A spherical (equirectangular) camera has no single pinhole view: it becomes six cube faces,
// square pinhole views of 90 degrees looking along +z, +x, -z, -x, -y (up) and +y (down) of the
// camera, of max(width, height) / 4 pixels (the panorama's resolution at the face centres).
#pragma once

#include <array>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"

namespace sfm_pruning {

enum class UndistortFit { kNoBlackBorders, kKeepAllPixels };

struct UndistortOptions {
  UndistortFit fit = UndistortFit::kNoBlackBorders;
  double min_focal_scale = 0.2;
  double max_focal_scale = 2.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// The pinhole camera (kPinholeFxFy, COLMAP's PINHOLE) that undistorted images of `camera` use.
// A camera without distortion maps to itself (same focal lengths and principal point); a
// spherical camera maps to its cube face camera.
CameraIntrinsics UndistortedIntrinsics(const CameraIntrinsics& camera, const UndistortOptions& options = {});

// The cube faces of a spherical camera: the rotation from the spherical camera's frame to each
// face's frame (x right, y down, z forward), and the names given to the face images.
inline constexpr int kNumCubeFaces = 6;
const std::array<Eigen::Matrix3d, kNumCubeFaces>& CubeFaceRotations();
const std::array<std::string, kNumCubeFaces>& CubeFaceNames();  // "front", "right", ...
// The face whose view contains the camera-frame direction `bearing` (its largest component).
int CubeFaceOf(const Eigen::Vector3d& bearing);

// True when the two cameras project every ray to the same pixel (the image can be copied as is).
bool SameProjection(const CameraIntrinsics& a, const CameraIntrinsics& b);

// Position in the original image of a pixel of the undistorted one, and the reverse (pixels in
// our convention: the centre of the top-left pixel is (0, 0), as OpenCV's remap).
Eigen::Vector2d DistortedPixel(const CameraIntrinsics& original, const CameraIntrinsics& undistorted,
                               const Eigen::Vector2d& undistorted_pixel);
Eigen::Vector2d UndistortedPixel(const CameraIntrinsics& original, const CameraIntrinsics& undistorted,
                                 const Eigen::Vector2d& distorted_pixel);

// Lookup maps for cv::remap: for every pixel of the undistorted image (undistorted.width() x
// height()), the float position of its source in the original image. `rotation` turns the
// original camera's frame into the undistorted camera's (a cube face's; identity otherwise).
struct UndistortionMaps {
  cv::Mat map_x;  // CV_32FC1
  cv::Mat map_y;  // CV_32FC1
};
UndistortionMaps ComputeUndistortionMaps(const CameraIntrinsics& original,
                                         const CameraIntrinsics& undistorted,
                                         const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity());

// Resamples `image` (any depth and channel count OpenCV's remap takes) bilinearly; pixels whose
// source lies outside the image are black.
cv::Mat UndistortImage(const cv::Mat& image, const UndistortionMaps& maps);

}  // namespace sfm_pruning
