// family_courtyard: an enclosure whose wall print repeats with 2-, 3-, 4- or 6-fold symmetry,
// drawn per seed: a polygonal courtyard (a rectangle with alike opposite walls for 2-fold, a
// hexagon with alternating walls for 3-fold, a square or hexagon of one wall for 4- and 6-fold)
// or a round rotunda whose print covers 1/n of the circle. Cameras stand on a ring inside (0.2-0.35
// of the radius) and look outward and slightly down over a full or partial turn. The unique
// texture (2-30 % of the points) is the paving, a door on one wall, or an object standing in the
// enclosure (then the paving is sparse).
#include <algorithm>
#include <cmath>
#include <string>

#include "sfm_pruning/eval/synthetic_families.hpp"

namespace sfm_pruning {
namespace {

constexpr double kWallDensityPerM2 = 10.0;
constexpr double kWallReliefM = 0.05;
constexpr double kDoorWidthM = 3.0;
constexpr double kDoorHeightM = 2.5;
constexpr double kDoorStandOffM = 0.1;
constexpr double kObjectSideM = 1.5;
constexpr double kObjectHeightM = 2.0;
constexpr double kGroundReliefM = 0.01;
constexpr double kSparseGroundDensityPerM2 = 1.0;
constexpr double kMaxUniqueDensityPerM2 = 400.0;
constexpr double kMinUniqueDensityPerM2 = 0.5;
constexpr double kCameraHeightM = 1.7;
constexpr double kRadiusJitterM = 0.3;
constexpr double kHeadingJitterDeg = 8.0;


// A wall of the polygon: from `start` along `along` (unit) for `length` metres; the print's u
// runs along it and its normal points into the enclosure (counter-clockwise walls).
struct Wall {
  Eigen::Vector3d start;
  Eigen::Vector3d along;
  double length = 0.0;
};

// Walls of a regular m-gon with the given apothem, or of a rectangle (m = 4, half sizes a and b),
// listed clockwise seen from above so that u x z points inward.
std::vector<Wall> PolygonWalls(int m, double apothem, double aspect) {
  std::vector<Eigen::Vector3d> corners;
  if (m == 4) {
    const double a = apothem * aspect, b = apothem;
    corners = {{a, -b, 0}, {-a, -b, 0}, {-a, b, 0}, {a, b, 0}};
  } else {
    const double circumradius = apothem / std::cos(M_PI / m);
    for (int k = 0; k < m; ++k) {
      const double angle = -2 * M_PI * k / m - M_PI / 2 + M_PI / m;
      corners.emplace_back(circumradius * std::cos(angle), circumradius * std::sin(angle), 0.0);
    }
  }
  std::vector<Wall> walls;
  for (size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector3d& a = corners[k];
    const Eigen::Vector3d& b = corners[(k + 1) % corners.size()];
    walls.push_back({a, (b - a).normalized(), (b - a).norm()});
  }
  return walls;
}

// A box of the given footprint and height on the ground, every face its own texture; `yaw`
// turns its right face's normal from +x.
void PlaceUniqueBox(const Eigen::Vector3d& center, double side_m, double height_m, double yaw, double density,
                    SceneLayout* layout, std::mt19937_64& rng) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d length_axis = z.cross(RotateAboutZ(Eigen::Vector3d::UnitX(), yaw));
  for (const BoxSide& face : BoxSideFaces(center, length_axis, side_m, side_m)) {
    const Texture texture = MakeTexture(side_m, height_m, density, 0.02, layout, rng);
    PlaceTexture(texture, face.origin, face.u_axis, z, layout);
  }
}

}  // namespace

SceneLayout BuildCourtyardFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                       std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const int fold = std::stoi(draw.Choice("fold", {"2", "3", "4", "6"}));
  const bool round = draw.Choice("shape", {"polygon", "round"}) == "round";
  const double apothem = draw.Uniform("radius_m", 7.0, 14.0);
  const double wall_height = draw.Uniform("wall_height_m", 5.0, 10.0);
  const double unique_share = draw.Uniform("unique_share_target", 0.02, 0.30);
  const std::string placement = draw.Choice("unique_placement", {"ground", "door", "object"});
  // A ring of 0.2-0.35 of the radius, as a courtyard is photographed from near its middle: a
  // ring much closer to the centre gives baselines too short to measure translation directions,
  // one close to the walls a view graph so thin that the solve drifts even without twins.
  const double ring_radius = draw.Uniform("camera_ring_fraction", 0.2, 0.35) * apothem;
  const bool full_turn = draw.Chance("full_turn", 0.6);
  const double arc = full_turn ? 2 * M_PI : DegToRad(draw.Uniform("arc_deg", std::min(360.0, 1.2 * 360.0 / fold), 360.0));
  // Looking slightly down, as from a person's height: the paving shows at the bottom of a view.
  const double pitch_deg = draw.Uniform("pitch_deg", -15.0, -5.0);
  const double start_angle = draw.Uniform("start_angle_deg", 0.0, 360.0);

  // The walls: `fold` copies of one print (a control gives every copy its own print).
  size_t wall_points = 0;
  auto next_print = [&](double width, const Texture* shared) {
    if (twins && shared != nullptr) return *shared;
    return MakeTexture(width, wall_height, kWallDensityPerM2 * s, kWallReliefM, &layout, rng);
  };
  if (round) {
    const double print_width = 2 * M_PI * apothem / fold;
    const Texture print = MakeTexture(print_width, wall_height, kWallDensityPerM2 * s, kWallReliefM, &layout, rng);
    for (int k = 0; k < fold; ++k) {
      const Texture copy = next_print(print_width, &print);
      PlaceTextureOnCylinder(copy, Eigen::Vector3d::Zero(), apothem, 2 * M_PI * k / fold, /*outward=*/false, &layout);
      wall_points += copy.uvw.size();
    }
  } else {
    const int sides = fold == 2 ? 4 : fold == 3 ? 6 : fold;
    const double aspect = fold == 2 ? draw.Uniform("aspect", 1.1, 1.6) : 1.0;
    const std::vector<Wall> walls = PolygonWalls(sides, apothem, aspect);
    const int prints = sides / fold;  // alternating prints for the 2- and 3-fold enclosures
    std::vector<Texture> originals;
    for (int p = 0; p < prints; ++p) {
      originals.push_back(MakeTexture(walls[p].length, wall_height, kWallDensityPerM2 * s, kWallReliefM, &layout, rng));
    }
    for (size_t k = 0; k < walls.size(); ++k) {
      const Texture copy = next_print(walls[k].length, &originals[k % prints]);
      PlaceTexture(copy, walls[k].start, walls[k].along, z, &layout);
      wall_points += copy.uvw.size();
    }
  }

  // The unique texture, all in one placement.
  if (placement == "door") {
    const double density = UniqueTextureDensity(unique_share, wall_points, kDoorWidthM * kDoorHeightM,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    const Texture door = MakeTexture(kDoorWidthM, kDoorHeightM, density * s, 0.0, &layout, rng);
    // In the middle of the wall at -y (the first wall of the polygons, the print start of the round).
    const double y = -(round ? apothem * std::cos(M_PI / 20) : apothem) + kDoorStandOffM;
    PlaceTexture(door, {0.5 * kDoorWidthM, y, 0.0}, -Eigen::Vector3d::UnitX(), z, &layout);
  } else if (placement == "object") {
    // Halfway between the ring and the wall, small enough to leave room on both sides.
    const double side = std::min(kObjectSideM, 0.4 * (apothem - ring_radius));
    const double density = UniqueTextureDensity(unique_share, wall_points, 4 * side * kObjectHeightM,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    const double distance = 0.5 * (ring_radius + apothem);
    const double angle = DegToRad(draw.Uniform("object_angle_deg", 0.0, 360.0));
    const Eigen::Vector3d center(distance * std::cos(angle), distance * std::sin(angle), 0.0);
    PlaceUniqueBox(center, side, kObjectHeightM, angle, density * s, &layout, rng);
  }
  // The paving: the drawn share of unique texture when it is the placement, else sparse. Every
  // view sees some of it, so that none sees a single wall plane only (a degenerate case for the
  // two-view geometry of any pipeline, not a question of repetition).
  const double half = apothem * (round ? 1.0 : 1.6);  // covers the rectangle's long side too
  const double ground_density =
      placement == "ground" ? UniqueTextureDensity(unique_share, wall_points, 4 * half * half, kMinUniqueDensityPerM2,
                                                   kMaxUniqueDensityPerM2)
                            : kSparseGroundDensityPerM2;
  const Texture ground = MakeTexture(2 * half, 2 * half, ground_density * s, kGroundReliefM, &layout, rng);
  PlaceTexture(ground, {-half, -half, 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), &layout);
  draw.Record("unique_share", UniquePointShare(layout));

  // Cameras on a ring inside, looking outward, over the drawn arc.
  std::uniform_real_distribution<double> radius_jitter(-kRadiusJitterM, kRadiusJitterM);
  std::uniform_real_distribution<double> heading_jitter(-DegToRad(kHeadingJitterDeg), DegToRad(kHeadingJitterDeg));
  const double spacing = full_turn ? arc / options.num_views : arc / std::max(1, options.num_views - 1);
  for (int i = 0; i < options.num_views; ++i) {
    const double angle = DegToRad(start_angle) + i * spacing;
    const double radius = ring_radius + radius_jitter(rng);
    const Eigen::Vector3d center(radius * std::cos(angle), radius * std::sin(angle), kCameraHeightM);
    layout.poses.push_back(HeadingPitchPose(center, angle + heading_jitter(rng), DegToRad(pitch_deg)));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
