// COLMAP camera models <-> CameraIntrinsics, and the pixel convention shift between the two.
//
// Pixel convention. COLMAP puts the centre of the top-left pixel at (0.5, 0.5); PruneSfM (like
// OpenMVG) puts it at (0, 0). Both map a normalized point to a pixel as  u = f * xd + c, so the
// same ray lands on the same pixel centre only if the two principal points differ by the same
// half pixel:  u_colmap = u_ours + 0.5  and  c_colmap = c_ours + 0.5. Hence reading COLMAP data
// subtracts 0.5 from principal points and keypoints, writing adds 0.5. Focal lengths and
// distortion coefficients act on normalized coordinates and are unchanged.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/camera_intrinsics.hpp"

namespace sfm_pruning {

// u_colmap = u_ours + kColmapPixelOffset (see above).
inline constexpr double kColmapPixelOffset = 0.5;

inline Eigen::Vector2d FromColmapPixel(const Eigen::Vector2d& colmap_pixel) {
  return colmap_pixel.array() - kColmapPixelOffset;
}
inline Eigen::Vector2d ToColmapPixel(const Eigen::Vector2d& pixel) {
  return pixel.array() + kColmapPixelOffset;
}

// COLMAP's numeric camera model ids (the `model` column of cameras, the int32 of cameras.bin).
enum class ColmapCameraModelId : int {
  kSimplePinhole = 0,
  kPinhole = 1,
  kSimpleRadial = 2,
  kRadial = 3,
  kOpenCv = 4,
  kOpenCvFisheye = 5,
  kFullOpenCv = 6,
};

// A camera exactly as COLMAP stores it: parameters in COLMAP's order and pixel convention.
struct ColmapCamera {
  int model_id = 0;
  uint64_t width = 0;
  uint64_t height = 0;
  std::vector<double> params;
};

// COLMAP's name of a model id ("PINHOLE"), or "UNKNOWN_MODEL_<id>" for ids COLMAP does not define.
std::string ColmapCameraModelName(int model_id);
// Model id from its COLMAP name, for every model COLMAP defines; false for an unknown name.
bool ColmapCameraModelIdFromName(const std::string& name, int* model_id);
// Number of parameters of a COLMAP model id; 0 for an unknown id.
size_t ColmapCameraNumParams(int model_id);

// COLMAP -> ours (principal point shifted). Throws Error "<source>: ..." naming the model when
// it has no PruneSfM counterpart (FOV, THIN_PRISM_FISHEYE, ..., or fx != fy with distortion).
CameraIntrinsics FromColmapCamera(const ColmapCamera& camera, const std::string& source);
// Ours -> COLMAP, choosing the smallest COLMAP model that represents the intrinsics exactly.
// Throws Error for kSpherical, which COLMAP cannot represent.
ColmapCamera ToColmapCamera(const CameraIntrinsics& intrinsics);

}  // namespace sfm_pruning
