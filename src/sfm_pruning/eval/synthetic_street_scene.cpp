// street: a row of identical facades along a street (Roberts et al. 2011 "street"), filmed by a
// camera walking along the street and looking at them. A view and a view one facade module
// further see the same picture, so their matches agree on a wrong translation of one module
// width. The street surface and shop signs on every other facade are unique.
#include <algorithm>
#include <cmath>

#include "sfm_pruning/eval/synthetic_layout.hpp"

namespace sfm_pruning {
namespace {

constexpr double kFacadeDistanceM = 7.0;  // facades stand at y = 7 m, the camera walks along y = 0
constexpr double kFacadeHeightM = 9.0;
constexpr double kFacadeDensityPerM2 = 12.0;
constexpr double kFacadeReliefM = 0.05;
constexpr double kSignWidthM = 2.0;
constexpr double kSignHeightM = 1.2;
constexpr double kSignElevationM = 2.5;
constexpr double kSignDensityPerM2 = 60.0;
constexpr double kSignStandOffM = 0.1;  // signs hang in front of the facade
constexpr double kGroundDensityPerM2 = 10.0;
constexpr double kGroundReliefM = 0.01;
constexpr double kStreetBehindCameraM = 3.0;  // street surface extends this far behind the path
constexpr double kMarginM = 12.0;             // facades beyond the ends of the path
constexpr double kStepM = 0.75;
constexpr double kCameraHeightM = 1.7;
constexpr double kPitchDeg = -5.0;
constexpr double kYawSwingDeg = 20.0;  // the camera pans smoothly left and right of the facade normal
constexpr double kYawJitterDeg = 4.0;
constexpr double kPositionJitterM = 0.2;

}  // namespace

SceneLayout BuildStreetLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  const double module_width = options.street_module_width_m;
  const double path_length = kStepM * std::max(0, options.num_views - 1);
  const double x_begin = -kMarginM;
  const int num_modules = static_cast<int>(std::ceil((path_length + 2 * kMarginM) / module_width));

  // One facade texture, repeated; u along +x and v up give a normal towards the street (-y).
  const Texture facade = MakeTexture(module_width, kFacadeHeightM, kFacadeDensityPerM2 * s, kFacadeReliefM, &layout, rng);
  for (int k = 0; k < num_modules; ++k) {
    const double x0 = x_begin + k * module_width;
    PlaceTexture(facade, {x0, kFacadeDistanceM, 0.0}, x, z, &layout);
    if (k % 2 == 1) {  // a unique shop sign on every other facade
      const Texture sign = MakeTexture(kSignWidthM, kSignHeightM, kSignDensityPerM2 * s, 0.0, &layout, rng);
      const double sx = x0 + 0.5 * (module_width - kSignWidthM);
      PlaceTexture(sign, {sx, kFacadeDistanceM - kSignStandOffM, kSignElevationM}, x, z, &layout);
    }
  }
  // The street surface, unique, between the facades and a little behind the camera path.
  const double street_width = kFacadeDistanceM + kStreetBehindCameraM;
  const Texture street = MakeTexture(num_modules * module_width, street_width, kGroundDensityPerM2 * s, kGroundReliefM, &layout, rng);
  PlaceTexture(street, {x_begin, -kStreetBehindCameraM, 0.0}, x, y, &layout);

  std::uniform_real_distribution<double> position_jitter(-kPositionJitterM, kPositionJitterM);
  std::uniform_real_distribution<double> yaw_jitter(-DegToRad(kYawJitterDeg), DegToRad(kYawJitterDeg));
  for (int i = 0; i < options.num_views; ++i) {
    const double jx = position_jitter(rng);
    const double jy = position_jitter(rng);
    const Eigen::Vector3d center(i * kStepM + jx, jy, kCameraHeightM);
    const double yaw = DegToRad(kYawSwingDeg) * std::sin(0.35 * i) + yaw_jitter(rng);
    layout.poses.push_back(HeadingPitchPose(center, M_PI / 2 + yaw, DegToRad(kPitchDeg)));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
