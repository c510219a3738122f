// sequential_large: a long sequence around a closed loop (a stadium-shaped street, driven
// several times), with textured building walls on the outer side and a textured ground. The
// camera looks outward at the walls, so each lap revisits the places of the previous ones: loop
// closures. A fraction of the straight wall segments repeat the texture of another segment
// (identical buildings), so retrieval also proposes false loops whose matches agree on a wrong
// pose.
#include <algorithm>
#include <cmath>
#include <utility>

#include "sfm_pruning/eval/synthetic_layout.hpp"

namespace sfm_pruning {
namespace {

constexpr double kStepM = 0.6;              // camera spacing along the path
constexpr double kWallDistanceM = 8.0;      // outer walls stand this far outside the path
constexpr double kWallHeightM = 6.0;
constexpr double kSegmentLengthM = 6.0;     // one building front
constexpr double kWallDensityPerM2 = 8.0;
constexpr double kWallReliefM = 0.05;
constexpr double kGroundDensityPerM2 = 6.0;
constexpr double kGroundReliefM = 0.01;
constexpr double kGroundInsideM = 3.0;      // ground extends this far inside the path
constexpr double kCameraHeightM = 1.7;
constexpr double kPitchDeg = -5.0;
constexpr double kHeadingJitterDeg = 10.0;
constexpr double kLaneJitterM = 0.3;
constexpr double kLapLaneOffsetM = 0.8;     // each lap drives a slightly different lane

// A stadium centred at the origin, traversed counter-clockwise starting at the beginning of the
// bottom straight, parametrised by arc length.
struct Stadium {
  double straight = 0.0;
  double radius = 0.0;

  double Perimeter() const { return 2 * straight + 2 * M_PI * radius; }

  // Point at arc length s (any real; wraps around).
  Eigen::Vector3d Point(double s) const {
    const double p = Perimeter();
    s = std::fmod(std::fmod(s, p) + p, p);
    const double half = 0.5 * straight;
    const double arc = M_PI * radius;
    if (s < straight) return {-half + s, -radius, 0.0};
    s -= straight;
    if (s < arc) {
      const double a = -M_PI / 2 + s / radius;
      return {half + radius * std::cos(a), radius * std::sin(a), 0.0};
    }
    s -= arc;
    if (s < straight) return {half - s, radius, 0.0};
    s -= straight;
    const double a = M_PI / 2 + s / radius;
    return {-half + radius * std::cos(a), radius * std::sin(a), 0.0};
  }

  // True when arc length s (in [0, perimeter)) lies on one of the straights.
  bool OnStraight(double s) const { return s <= straight || (s >= straight + M_PI * radius && s <= 2 * straight + M_PI * radius); }
};

}  // namespace

SceneLayout BuildLoopLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng) {
  SceneLayout layout;
  const double density_scale = options.point_density_scale;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const int views_per_lap = (options.num_views + options.laps - 1) / options.laps;
  const double perimeter = views_per_lap * kStepM;
  const double straight_per_radius = options.loop_straight_per_radius;
  const double radius = perimeter / (2 * straight_per_radius + 2 * M_PI);
  const Stadium path{straight_per_radius * radius, radius};
  const Stadium wall_line{path.straight, radius + kWallDistanceM};

  // Wall segments: chords of the wall line, all of (almost) the same length.
  const int num_segments = std::max(4, static_cast<int>(std::lround(wall_line.Perimeter() / kSegmentLengthM)));
  const double segment_arc = wall_line.Perimeter() / num_segments;
  std::vector<Eigen::Vector3d> corners(num_segments + 1);
  std::vector<bool> straight(num_segments);
  for (int k = 0; k <= num_segments; ++k) corners[k] = wall_line.Point(k * segment_arc);
  for (int k = 0; k < num_segments; ++k) {
    straight[k] = wall_line.OnStraight(k * segment_arc) && wall_line.OnStraight((k + 1) * segment_arc);
  }

  // Choose which straight segments copy another one. Segments on straights all have the same
  // width, so a copy is an exact rigid duplicate.
  std::vector<int> straight_ids;
  for (int k = 0; k < num_segments; ++k) {
    if (straight[k]) straight_ids.push_back(k);
  }
  std::shuffle(straight_ids.begin(), straight_ids.end(), rng);
  const auto num_copies = static_cast<size_t>(std::floor(options.twin_fraction * straight_ids.size()));
  std::vector<int> source_of(num_segments, -1);
  for (size_t c = 0; c < num_copies && num_copies < straight_ids.size(); ++c) {
    std::uniform_int_distribution<size_t> pick(num_copies, straight_ids.size() - 1);
    source_of[straight_ids[c]] = straight_ids[pick(rng)];
  }

  // Textures of the original segments first (copies need their source's texture).
  std::vector<Texture> wall_textures(num_segments);
  for (int k = 0; k < num_segments; ++k) {
    if (source_of[k] >= 0) continue;
    const double width = (corners[k + 1] - corners[k]).norm();
    wall_textures[k] = MakeTexture(width, kWallHeightM, kWallDensityPerM2 * density_scale, kWallReliefM, &layout, rng);
  }
  for (int k = 0; k < num_segments; ++k) {
    const Eigen::Vector3d along = (corners[k + 1] - corners[k]).normalized();
    const Eigen::Vector3d inward = z.cross(along);  // counter-clockwise: the centre is on the left
    // u = -along from the segment's end gives the normal (-along) x z = inward.
    const Texture& texture = source_of[k] >= 0 ? wall_textures[source_of[k]] : wall_textures[k];
    PlaceTexture(texture, corners[k + 1], -along, z, &layout);
    // The ground in front of the wall, unique everywhere.
    const double width = (corners[k + 1] - corners[k]).norm();
    const Texture ground = MakeTexture(width, kWallDistanceM + kGroundInsideM, kGroundDensityPerM2 * density_scale,
                                       kGroundReliefM, &layout, rng);
    PlaceTexture(ground, corners[k], along, inward, &layout);
  }

  std::uniform_real_distribution<double> lane_jitter(-kLaneJitterM, kLaneJitterM);
  std::uniform_real_distribution<double> heading_jitter(-DegToRad(kHeadingJitterDeg), DegToRad(kHeadingJitterDeg));
  for (int i = 0; i < options.num_views; ++i) {
    const int lap = i / views_per_lap;
    const double s = (i % views_per_lap) * kStepM;
    const Eigen::Vector3d along = (path.Point(s + 0.01) - path.Point(s - 0.01)).normalized();
    const Eigen::Vector3d outward = along.cross(z);
    const double lane = lap * kLapLaneOffsetM + lane_jitter(rng);
    const Eigen::Vector3d center = path.Point(s) - lane * outward + kCameraHeightM * z;
    const double heading = std::atan2(outward.y(), outward.x()) + heading_jitter(rng);
    layout.poses.push_back(HeadingPitchPose(center, heading, DegToRad(kPitchDeg)));
  }
  layout.pairs = PairSelection::kSequentialAndRetrieval;
  return layout;
}

}  // namespace sfm_pruning
