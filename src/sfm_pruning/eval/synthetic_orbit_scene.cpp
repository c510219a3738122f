// orbit_symmetric and clean: a box-shaped object on a textured ground, seen by cameras on a 360
// degree orbit. In orbit_symmetric the object is point-symmetric about its vertical axis: the
// back is a copy of the front and the right side a copy of the left, so a camera and the camera
// opposite it see the same object picture (the "cup" of Roberts et al. 2011). Only the ground
// tells them apart. In clean every face has its own texture.
#include <cmath>

#include "sfm_pruning/eval/synthetic_layout.hpp"

namespace sfm_pruning {
namespace {

// Object: a box of 2 x 1.2 x 1.5 m standing on the ground, centred on the z axis.
constexpr double kHalfLengthM = 1.0;
constexpr double kHalfDepthM = 0.6;
constexpr double kHeightM = 1.5;
constexpr double kObjectDensityPerM2 = 90.0;
constexpr double kObjectReliefM = 0.02;
// Ground: a textured square around the object.
constexpr double kGroundHalfSizeM = 9.0;
constexpr double kGroundDensityPerM2 = 8.0;
constexpr double kGroundReliefM = 0.01;
// Orbit: radius, camera height and the point all cameras aim at.
constexpr double kOrbitRadiusM = 6.0;
constexpr double kCameraHeightM = 2.5;
constexpr double kTargetHeightM = 0.5;
constexpr double kRadiusJitterM = 0.2;
constexpr double kAngleJitterDeg = 1.5;
constexpr double kTargetJitterM = 0.15;

// Adds a ground rectangle [x0, x1] x [y0, y1] with its own texture, normal up.
void AddGround(double x0, double x1, double y0, double y1, double density, SceneLayout* layout,
               std::mt19937_64& rng) {
  const Texture texture = MakeTexture(x1 - x0, y1 - y0, density, kGroundReliefM, layout, rng);
  PlaceTexture(texture, {x0, y0, 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), layout);
}

}  // namespace

SceneLayout BuildOrbitLayout(const SyntheticSceneOptions& options, bool symmetric, std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();

  // Front (normal -y) and back (normal +y); the back is the front turned 180 degrees about z.
  const Texture front = MakeTexture(2 * kHalfLengthM, kHeightM, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  const Texture back = symmetric ? front
                                 : MakeTexture(2 * kHalfLengthM, kHeightM, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  PlaceTexture(front, {-kHalfLengthM, -kHalfDepthM, 0.0}, x, z, &layout);
  PlaceTexture(back, {kHalfLengthM, kHalfDepthM, 0.0}, -x, z, &layout);
  // Left (normal -x) and right (normal +x), related the same way.
  const Texture left = MakeTexture(2 * kHalfDepthM, kHeightM, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  const Texture right = symmetric ? left
                                  : MakeTexture(2 * kHalfDepthM, kHeightM, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  PlaceTexture(left, {-kHalfLengthM, kHalfDepthM, 0.0}, -y, z, &layout);
  PlaceTexture(right, {kHalfLengthM, -kHalfDepthM, 0.0}, y, z, &layout);
  // Top: unique in both variants (the cameras look down on it only slightly).
  const Texture top = MakeTexture(2 * kHalfLengthM, 2 * kHalfDepthM, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  PlaceTexture(top, {-kHalfLengthM, -kHalfDepthM, kHeightM}, x, y, &layout);

  // Ground around the object's footprint (four rectangles, none under the box).
  const double g = kGroundHalfSizeM, d = kGroundDensityPerM2 * s;
  AddGround(-g, g, -g, -kHalfDepthM, d, &layout, rng);
  AddGround(-g, g, kHalfDepthM, g, d, &layout, rng);
  AddGround(-g, -kHalfLengthM, -kHalfDepthM, kHalfDepthM, d, &layout, rng);
  AddGround(kHalfLengthM, g, -kHalfDepthM, kHalfDepthM, d, &layout, rng);

  std::uniform_real_distribution<double> radius_jitter(-kRadiusJitterM, kRadiusJitterM);
  std::uniform_real_distribution<double> angle_jitter(-DegToRad(kAngleJitterDeg), DegToRad(kAngleJitterDeg));
  std::uniform_real_distribution<double> target_jitter(-kTargetJitterM, kTargetJitterM);
  for (int i = 0; i < options.num_views; ++i) {
    const double angle = 2.0 * M_PI * i / options.num_views + angle_jitter(rng);
    const double radius = kOrbitRadiusM + radius_jitter(rng);
    const Eigen::Vector3d center(radius * std::cos(angle), radius * std::sin(angle), kCameraHeightM);
    // One draw per statement: argument evaluation order is unspecified in C++.
    Eigen::Vector3d target(0.0, 0.0, kTargetHeightM);
    for (int k = 0; k < 3; ++k) target[k] += target_jitter(rng);
    layout.poses.push_back(LookAtPose(center, target));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
