#include "sfm_pruning/io/colmap_camera.hpp"

#include <utility>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

struct ColmapModelInfo {
  int id;
  const char* name;
  size_t num_params;
};

// Every model COLMAP defines, so that unsupported ones are still named in error messages and
// their cameras.bin records can be sized.
constexpr ColmapModelInfo kColmapModels[] = {
    {0, "SIMPLE_PINHOLE", 3},
    {1, "PINHOLE", 4},
    {2, "SIMPLE_RADIAL", 4},
    {3, "RADIAL", 5},
    {4, "OPENCV", 8},
    {5, "OPENCV_FISHEYE", 8},
    {6, "FULL_OPENCV", 12},
    {7, "FOV", 5},
    {8, "SIMPLE_RADIAL_FISHEYE", 4},
    {9, "RADIAL_FISHEYE", 5},
    {10, "THIN_PRISM_FISHEYE", 12},
    {11, "RAD_TAN_THIN_PRISM_FISHEYE", 16},
};

const ColmapModelInfo* FindModel(int id) {
  for (const ColmapModelInfo& info : kColmapModels) {
    if (info.id == id) return &info;
  }
  return nullptr;
}

constexpr int Id(ColmapCameraModelId model) { return static_cast<int>(model); }

// Builds our intrinsics from COLMAP parameters: `f`, the principal point in COLMAP's pixel
// convention, and the distortion coefficients in our model's order.
CameraIntrinsics Make(CameraModel model, const ColmapCamera& camera, double f, double cx, double cy,
                      const std::vector<double>& distortion) {
  std::vector<double> params = {f, cx - kColmapPixelOffset, cy - kColmapPixelOffset};
  params.insert(params.end(), distortion.begin(), distortion.end());
  return CameraIntrinsics(model, static_cast<uint32_t>(camera.width), static_cast<uint32_t>(camera.height),
                          std::move(params));
}

}  // namespace

std::string ColmapCameraModelName(int model_id) {
  const ColmapModelInfo* info = FindModel(model_id);
  return info ? info->name : "UNKNOWN_MODEL_" + std::to_string(model_id);
}

bool ColmapCameraModelIdFromName(const std::string& name, int* model_id) {
  for (const ColmapModelInfo& info : kColmapModels) {
    if (name == info.name) {
      *model_id = info.id;
      return true;
    }
  }
  return false;
}

size_t ColmapCameraNumParams(int model_id) {
  const ColmapModelInfo* info = FindModel(model_id);
  return info ? info->num_params : 0;
}

CameraIntrinsics FromColmapCamera(const ColmapCamera& camera, const std::string& source) {
  const std::string name = ColmapCameraModelName(camera.model_id);
  const size_t expected = ColmapCameraNumParams(camera.model_id);
  if (expected != 0 && camera.params.size() != expected) {
    throw FileError(source, "camera model " + name + " takes " + std::to_string(expected) +
                                " parameters, got " + std::to_string(camera.params.size()));
  }
  if (camera.width > UINT32_MAX || camera.height > UINT32_MAX) {
    throw FileError(source, "camera size " + std::to_string(camera.width) + "x" +
                                std::to_string(camera.height) + " is out of range");
  }
  const std::vector<double>& p = camera.params;
  // Our distorted models share one focal length; COLMAP's two-focal ones only map when fx == fy.
  auto require_single_focal = [&]() {
    if (p[0] != p[1]) {
      throw FileError(source,
                      "camera model " + name +
                          " with fx != fy is not supported (PruneSfM's distorted models have one focal)");
    }
  };
  switch (camera.model_id) {
    case Id(ColmapCameraModelId::kSimplePinhole):
      return Make(CameraModel::kPinhole, camera, p[0], p[1], p[2], {});
    case Id(ColmapCameraModelId::kPinhole):
      if (p[0] == p[1]) return Make(CameraModel::kPinhole, camera, p[0], p[2], p[3], {});
      return CameraIntrinsics(CameraModel::kPinholeFxFy, static_cast<uint32_t>(camera.width),
                              static_cast<uint32_t>(camera.height),
                              {p[0], p[1], p[2] - kColmapPixelOffset, p[3] - kColmapPixelOffset});
    case Id(ColmapCameraModelId::kSimpleRadial):
      return Make(CameraModel::kPinholeRadialK1, camera, p[0], p[1], p[2], {p[3]});
    case Id(ColmapCameraModelId::kRadial):
      return Make(CameraModel::kPinholeRadialK3, camera, p[0], p[1], p[2], {p[3], p[4], 0.0});
    case Id(ColmapCameraModelId::kOpenCv):
      // OpenCV's p1, p2 play the roles of our t1, t2 (see camera_models.hpp).
      require_single_focal();
      return Make(CameraModel::kPinholeBrownT2, camera, p[0], p[2], p[3], {p[4], p[5], 0.0, p[6], p[7]});
    case Id(ColmapCameraModelId::kOpenCvFisheye):
      require_single_focal();
      return Make(CameraModel::kFisheye, camera, p[0], p[2], p[3], {p[4], p[5], p[6], p[7]});
    case Id(ColmapCameraModelId::kFullOpenCv):
      // fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6; k4..k6 form a rational denominator we do not model.
      require_single_focal();
      if (p[9] != 0.0 || p[10] != 0.0 || p[11] != 0.0) {
        throw FileError(source, "camera model FULL_OPENCV with non-zero k4, k5 or k6 is not supported");
      }
      return Make(CameraModel::kPinholeBrownT2, camera, p[0], p[2], p[3], {p[4], p[5], p[8], p[6], p[7]});
    default:
      throw FileError(source, "camera model " + name + " is not supported");
  }
}

ColmapCamera ToColmapCamera(const CameraIntrinsics& intrinsics) {
  ColmapCamera camera;
  camera.width = intrinsics.width();
  camera.height = intrinsics.height();
  const Eigen::Vector2d c = ToColmapPixel(intrinsics.PrincipalPoint());
  const double fx = intrinsics.FocalX();
  const double fy = intrinsics.FocalY();
  const std::vector<double> k = intrinsics.DistortionParams();
  switch (intrinsics.model()) {
    case CameraModel::kPinhole:
      camera.model_id = Id(ColmapCameraModelId::kSimplePinhole);
      camera.params = {fx, c.x(), c.y()};
      break;
    case CameraModel::kPinholeFxFy:
      camera.model_id = Id(ColmapCameraModelId::kPinhole);
      camera.params = {fx, fy, c.x(), c.y()};
      break;
    case CameraModel::kPinholeRadialK1:
      camera.model_id = Id(ColmapCameraModelId::kSimpleRadial);
      camera.params = {fx, c.x(), c.y(), k[0]};
      break;
    case CameraModel::kPinholeRadialK3:
      if (k[2] == 0.0) {
        camera.model_id = Id(ColmapCameraModelId::kRadial);
        camera.params = {fx, c.x(), c.y(), k[0], k[1]};
      } else {
        camera.model_id = Id(ColmapCameraModelId::kFullOpenCv);
        camera.params = {fx, fy, c.x(), c.y(), k[0], k[1], 0.0, 0.0, k[2], 0.0, 0.0, 0.0};
      }
      break;
    case CameraModel::kPinholeBrownT2:  // k = k1 k2 k3 t1 t2
      if (k[2] == 0.0) {
        camera.model_id = Id(ColmapCameraModelId::kOpenCv);
        camera.params = {fx, fy, c.x(), c.y(), k[0], k[1], k[3], k[4]};
      } else {
        camera.model_id = Id(ColmapCameraModelId::kFullOpenCv);
        camera.params = {fx, fy, c.x(), c.y(), k[0], k[1], k[3], k[4], k[2], 0.0, 0.0, 0.0};
      }
      break;
    case CameraModel::kFisheye:
      camera.model_id = Id(ColmapCameraModelId::kOpenCvFisheye);
      camera.params = {fx, fy, c.x(), c.y(), k[0], k[1], k[2], k[3]};
      break;
    case CameraModel::kSpherical:
      throw Error("camera model " + CameraModelName(intrinsics.model()) + " has no COLMAP counterpart");
  }
  return camera;
}

}  // namespace sfm_pruning
