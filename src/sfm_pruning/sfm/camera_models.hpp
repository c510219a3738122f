// Camera models: the maths of each intrinsic type, templated on the scalar so the same code
// serves the library (double) and Ceres' automatic differentiation (ceres::Jet).
//
// Pixel convention (OpenMVG's): the centre of the top-left pixel is (0, 0). COLMAP uses (0.5, 0.5);
// io/colmap_* shift by 0.5 at the boundary.
//
// Every pinhole-family model maps a camera point to a pixel as
//   (x, y) = (X / Z, Y / Z)           normalized image plane
//   (xd, yd) = Distort(x, y)          distortion, applied in the normalized plane
//   pixel = (fx * xd + cx, fy * yd + cy)
// Parameter layouts (the order of CameraIntrinsics::params):
//   kPinhole            f, cx, cy
//   kPinholeRadialK1    f, cx, cy, k1
//   kPinholeRadialK3    f, cx, cy, k1, k2, k3
//   kPinholeBrownT2     f, cx, cy, k1, k2, k3, t1, t2
//   kFisheye            f, cx, cy, k1, k2, k3, k4
//   kPinholeFxFy        fx, fy, cx, cy   (COLMAP's PINHOLE with fx != fy; no OpenMVG counterpart)
//   kSpherical          (none: the mapping is fixed by width and height)
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

namespace sfm_pruning {

enum class CameraModel {
  kPinhole,
  kPinholeRadialK1,
  kPinholeRadialK3,
  kPinholeBrownT2,
  kFisheye,
  kPinholeFxFy,
  kSpherical,
};

// Number of entries of CameraIntrinsics::params for a model.
size_t NumCameraParams(CameraModel model);
// OpenMVG's polymorphic name ("pinhole_radial_k3", ...); kPinholeFxFy is "pinhole_fx_fy".
std::string CameraModelName(CameraModel model);
// Inverse of CameraModelName; returns false for an unknown name.
bool CameraModelFromName(const std::string& name, CameraModel* model);
// True for the models that project through a pinhole (everything but kSpherical).
inline bool IsPinholeFamily(CameraModel model) { return model != CameraModel::kSpherical; }

namespace camera_models {

// Index of the first distortion coefficient in params for the single-focal pinhole models.
inline constexpr int kFirstDistortionParam = 3;

// Applies the model's distortion to a normalized point. `params` is the whole parameter block.
template <typename T>
void Distort(CameraModel model, const T* params, const T& x, const T& y, T* xd, T* yd) {
  using std::atan;
  using std::sqrt;
  const T* k = params + kFirstDistortionParam;
  const T r2 = x * x + y * y;
  switch (model) {
    case CameraModel::kPinhole:
    case CameraModel::kPinholeFxFy:
    case CameraModel::kSpherical:
      *xd = x;
      *yd = y;
      return;
    case CameraModel::kPinholeRadialK1: {
      const T radial = T(1) + k[0] * r2;
      *xd = x * radial;
      *yd = y * radial;
      return;
    }
    case CameraModel::kPinholeRadialK3: {
      const T radial = T(1) + r2 * (k[0] + r2 * (k[1] + r2 * k[2]));
      *xd = x * radial;
      *yd = y * radial;
      return;
    }
    case CameraModel::kPinholeBrownT2: {
      // Radial K3 plus tangential terms; OpenMVG's t2 drives x and t1 drives y:
      //   dx = t2 (r^2 + 2 x^2) + 2 t1 x y,   dy = t1 (r^2 + 2 y^2) + 2 t2 x y.
      const T radial = T(1) + r2 * (k[0] + r2 * (k[1] + r2 * k[2]));
      const T t1 = k[3];
      const T t2 = k[4];
      *xd = x * radial + t2 * (r2 + T(2) * x * x) + T(2) * t1 * x * y;
      *yd = y * radial + t1 * (r2 + T(2) * y * y) + T(2) * t2 * x * y;
      return;
    }
    case CameraModel::kFisheye: {
      // Equidistant: theta = atan(r), theta_d = theta (1 + k1 theta^2 + ... + k4 theta^8).
      if (r2 < T(1e-16)) {  // at the centre the scale theta_d / r tends to 1
        *xd = x;
        *yd = y;
        return;
      }
      const T r = sqrt(r2);
      const T theta = atan(r);
      const T t2 = theta * theta;
      const T theta_d = theta * (T(1) + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
      const T scale = theta_d / r;
      *xd = x * scale;
      *yd = y * scale;
      return;
    }
  }
}

// Focal lengths and principal point of a pinhole-family parameter block.
template <typename T>
void FocalAndPrincipalPoint(CameraModel model, const T* params, T* fx, T* fy, T* cx, T* cy) {
  if (model == CameraModel::kPinholeFxFy) {
    *fx = params[0];
    *fy = params[1];
    *cx = params[2];
    *cy = params[3];
  } else {
    *fx = params[0];
    *fy = params[0];
    *cx = params[1];
    *cy = params[2];
  }
}

// Projects a point in camera coordinates to a pixel (pinhole family only).
template <typename T>
void ProjectPinhole(CameraModel model, const T* params, const T* X_cam, T* pixel) {
  const T x = X_cam[0] / X_cam[2];
  const T y = X_cam[1] / X_cam[2];
  T xd = x, yd = y, fx, fy, cx, cy;
  Distort(model, params, x, y, &xd, &yd);
  FocalAndPrincipalPoint(model, params, &fx, &fy, &cx, &cy);
  pixel[0] = fx * xd + cx;
  pixel[1] = fy * yd + cy;
}

}  // namespace camera_models
}  // namespace sfm_pruning
