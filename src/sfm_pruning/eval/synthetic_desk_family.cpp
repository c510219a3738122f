// family_desk: a desk with duplicated objects (Yan et al.'s books), drawn per seed: one or two
// box designs (books, boxes), each present in two or three identical copies at random places and
// turns. The unique texture (2-30 % of the points) is the desk's surface or one or two unique
// objects. Cameras move on an arc round the desk or sweep along its front at changing heights.
#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "sfm_pruning/eval/synthetic_families.hpp"

namespace sfm_pruning {
namespace {

constexpr double kObjectDensityPerM2 = 1500.0;
constexpr double kObjectReliefM = 0.002;
constexpr double kDeskReliefM = 0.001;
constexpr double kMaxUniqueDensityPerM2 = 3000.0;
constexpr double kMinUniqueDensityPerM2 = 1.0;
constexpr double kObjectClearanceM = 0.05;  // between the footprints of two objects
constexpr int kPlacementTries = 200;
constexpr double kPositionJitterM = 0.02;
constexpr double kTargetJitterM = 0.05;

// A box design: its dimensions and the five textures (four sides, top) every copy carries.
struct BoxDesign {
  double length = 0.0, depth = 0.0, height = 0.0;
  std::vector<Texture> faces;  // sides 0..3 (front, right, back, left), then the top
};

BoxDesign MakeBoxDesign(double length, double depth, double height, double density, SceneLayout* layout,
                        std::mt19937_64& rng) {
  BoxDesign design{length, depth, height, {}};
  const double widths[4] = {length, depth, length, depth};
  for (double width : widths) design.faces.push_back(MakeTexture(width, height, density, kObjectReliefM, layout, rng));
  design.faces.push_back(MakeTexture(length, depth, density, kObjectReliefM, layout, rng));
  return design;
}

// Places a copy of the design on the desk at `center`, turned by `yaw` about z.
void PlaceBox(const BoxDesign& design, const Eigen::Vector3d& center, double yaw, SceneLayout* layout) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d x = R.col(0), y = R.col(1), z = Eigen::Vector3d::UnitZ();
  const std::array<BoxSide, 4> sides = BoxSideFaces(center, x, design.length, design.depth);
  for (int k = 0; k < 4; ++k) PlaceTexture(design.faces[k], sides[k].origin, sides[k].u_axis, z, layout);
  PlaceTexture(design.faces[4], sides[0].origin + design.height * z, x, y, layout);
}

}  // namespace

SceneLayout BuildDeskFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                  std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const double desk_width = draw.Uniform("desk_width_m", 2.0, 3.0);
  const double desk_depth = draw.Uniform("desk_depth_m", 1.2, 1.8);
  const int num_designs = draw.Integer("num_designs", 1, 2);
  const double unique_share = draw.Uniform("unique_share_target", 0.02, 0.30);
  const std::string placement = draw.Choice("unique_placement", {"desk_surface", "unique_objects"});
  const int num_unique_objects = placement == "unique_objects" ? draw.Integer("num_unique_objects", 1, 2) : 0;

  // Objects: each design in 2-3 copies (a control makes each copy its own design).
  struct Item {
    const BoxDesign* design = nullptr;
    bool unique = false;
  };
  std::deque<BoxDesign> designs;  // items point into it: a deque never moves what it holds
  std::vector<Item> items;
  std::uniform_real_distribution<double> side(0.2, 0.45), thickness(0.05, 0.25);
  for (int d = 0; d < num_designs; ++d) {
    const int copies = draw.Integer("copies_of_design_" + std::to_string(d), 2, 3);
    const double length = side(rng), depth = 0.7 * side(rng), height = thickness(rng);
    designs.push_back(MakeBoxDesign(length, depth, height, kObjectDensityPerM2 * s, &layout, rng));
    const BoxDesign* original = &designs.back();
    for (int c = 0; c < copies; ++c) {
      if (!twins && c > 0) {
        designs.push_back(MakeBoxDesign(length, depth, height, kObjectDensityPerM2 * s, &layout, rng));
        items.push_back({&designs.back(), false});
      } else {
        items.push_back({original, false});
      }
    }
  }
  size_t repeated_points = 0;
  for (const Item& item : items) {
    for (const Texture& face : item.design->faces) repeated_points += face.uvw.size();
  }
  for (int u = 0; u < num_unique_objects; ++u) {
    const double length = side(rng), depth = 0.7 * side(rng), height = thickness(rng);
    const double area = 2 * (length + depth) * height + length * depth;
    const double density = UniqueTextureDensity(unique_share / num_unique_objects, repeated_points, area,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    designs.push_back(MakeBoxDesign(length, depth, height, density * s, &layout, rng));
    items.push_back({&designs.back(), true});
  }

  // Random places and turns on the desk, footprints apart.
  std::vector<std::pair<Eigen::Vector3d, double>> placed;  // centre, footprint radius
  std::uniform_real_distribution<double> yaw(0.0, 2 * M_PI);
  for (const Item& item : items) {
    const double radius = 0.5 * std::hypot(item.design->length, item.design->depth);
    // The middle 70 % of the width, which every view of the sweep below sees.
    std::uniform_real_distribution<double> px(-0.35 * desk_width + radius, 0.35 * desk_width - radius);
    std::uniform_real_distribution<double> py(-0.5 * desk_depth + radius, 0.5 * desk_depth - radius);
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (int attempt = 0; attempt < kPlacementTries; ++attempt) {
      center = Eigen::Vector3d(px(rng), py(rng), 0.0);
      const bool free = std::all_of(placed.begin(), placed.end(), [&](const auto& other) {
        return (other.first - center).norm() > other.second + radius + kObjectClearanceM;
      });
      if (free) break;
    }
    placed.emplace_back(center, radius);
    PlaceBox(*item.design, center, yaw(rng), &layout);
  }
  if (placement == "desk_surface") {
    const double density = UniqueTextureDensity(unique_share, repeated_points, desk_width * desk_depth,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    const Texture desk = MakeTexture(desk_width, desk_depth, density * s, kDeskReliefM, &layout, rng);
    PlaceTexture(desk, {-0.5 * desk_width, -0.5 * desk_depth, 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                 &layout);
  }
  draw.Record("unique_share", UniquePointShare(layout));

  // Cameras: an arc round the desk centre (seen from the front, -y), or a sweep along its front.
  const std::string path = draw.Choice("path", {"arc", "sweep"});
  const double distance = draw.Uniform("camera_distance_m", 1.2, 2.0);
  const double elevation = draw.Uniform("camera_elevation_m", 0.5, 1.0);
  const double arc = DegToRad(draw.Uniform("arc_deg", 120.0, 240.0));
  const double sweep_height = path == "sweep" ? draw.Uniform("sweep_height_swing_m", 0.1, 0.4) : 0.0;
  std::uniform_real_distribution<double> position_jitter(-kPositionJitterM, kPositionJitterM);
  std::uniform_real_distribution<double> target_jitter(-kTargetJitterM, kTargetJitterM);
  const int n = options.num_views;
  for (int i = 0; i < n; ++i) {
    const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.5;  // [0, 1] along the path
    Eigen::Vector3d center;
    if (path == "arc") {
      const double angle = -M_PI / 2 - 0.5 * arc + t * arc;
      center = Eigen::Vector3d(distance * std::cos(angle), distance * std::sin(angle), elevation);
    } else {
      center = Eigen::Vector3d((t - 0.5) * 0.6 * desk_width, -distance,
                               elevation + sweep_height * std::sin(2 * M_PI * 3 * t));
    }
    for (int c = 0; c < 3; ++c) center[c] += position_jitter(rng);
    Eigen::Vector3d target = path == "arc" ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.5 * center.x(), 0.0, 0.0);
    for (int c = 0; c < 3; ++c) target[c] += target_jitter(rng);
    layout.poses.push_back(LookAtPose(center, target));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
