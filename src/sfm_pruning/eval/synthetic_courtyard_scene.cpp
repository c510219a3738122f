// courtyard: an enclosed square courtyard whose four walls carry the same texture (castle-P19's
// repeated windows, taken to the extreme). Cameras stand near the centre and look outward all
// around, so views 90 degrees apart see the same wall picture and their matches agree on a wrong
// rotation of 90 degrees about the vertical. The paved ground and one door are unique.
#include <cmath>

#include "sfm_pruning/eval/synthetic_layout.hpp"

namespace sfm_pruning {
namespace {

constexpr double kHalfSizeM = 10.0;  // the courtyard is 20 x 20 m
constexpr double kWallHeightM = 8.0;
constexpr double kWallDensityPerM2 = 10.0;
constexpr double kWallReliefM = 0.05;
constexpr double kDoorWidthM = 3.0;
constexpr double kDoorHeightM = 2.5;
constexpr double kDoorDensityPerM2 = 40.0;
constexpr double kDoorStandOffM = 0.1;
constexpr double kGroundDensityPerM2 = 8.0;
constexpr double kGroundReliefM = 0.01;
constexpr double kCameraRadiusM = 3.0;
constexpr double kCameraHeightM = 1.7;
constexpr double kPitchDeg = -8.0;
constexpr double kRadiusJitterM = 0.5;
constexpr double kAngleJitterDeg = 2.0;
constexpr double kHeadingJitterDeg = 8.0;

}  // namespace

SceneLayout BuildCourtyardLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();

  // Wall 0 is the south wall (y = -10) facing north (u = -x, v = +z gives normal +y); walls 1..3
  // are wall 0 turned by 90, 180, 270 degrees about the courtyard's vertical axis.
  const Texture wall = MakeTexture(2 * kHalfSizeM, kWallHeightM, kWallDensityPerM2 * s, kWallReliefM, &layout, rng);
  const Eigen::Vector3d wall_origin(kHalfSizeM, -kHalfSizeM, 0.0);
  const Eigen::Vector3d wall_u = -Eigen::Vector3d::UnitX();
  for (int k = 0; k < 4; ++k) {
    const double turn = k * M_PI / 2;
    PlaceTexture(wall, RotateAboutZ(wall_origin, turn), RotateAboutZ(wall_u, turn), z, &layout);
  }
  // A unique door in the middle of the south wall.
  const Texture door = MakeTexture(kDoorWidthM, kDoorHeightM, kDoorDensityPerM2 * s, 0.0, &layout, rng);
  PlaceTexture(door, {0.5 * kDoorWidthM, -kHalfSizeM + kDoorStandOffM, 0.0}, wall_u, z, &layout);
  // Unique paving.
  const Texture ground = MakeTexture(2 * kHalfSizeM, 2 * kHalfSizeM, kGroundDensityPerM2 * s, kGroundReliefM, &layout, rng);
  PlaceTexture(ground, {-kHalfSizeM, -kHalfSizeM, 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), &layout);

  std::uniform_real_distribution<double> radius_jitter(-kRadiusJitterM, kRadiusJitterM);
  std::uniform_real_distribution<double> angle_jitter(-DegToRad(kAngleJitterDeg), DegToRad(kAngleJitterDeg));
  std::uniform_real_distribution<double> heading_jitter(-DegToRad(kHeadingJitterDeg), DegToRad(kHeadingJitterDeg));
  for (int i = 0; i < options.num_views; ++i) {
    const double angle = 2.0 * M_PI * i / options.num_views + angle_jitter(rng);
    const double radius = kCameraRadiusM + radius_jitter(rng);
    const Eigen::Vector3d center(radius * std::cos(angle), radius * std::sin(angle), kCameraHeightM);
    const double heading = angle + heading_jitter(rng);  // looking outward, towards the walls
    layout.poses.push_back(HeadingPitchPose(center, heading, DegToRad(kPitchDeg)));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
