// family_object: one object whose opposite faces print alike, drawn per seed: a cup whose print
// covers half its circumference twice (Yan et al.'s cup), a box whose back copies its front and
// whose right side copies its left, or a package whose four sides carry one print. The unique
// texture (2-30 % of the points) is the ground around it, its top, or a sticker on one face.
// Cameras orbit it fully, partly, or on two rings at different heights.
#include <algorithm>
#include <cmath>

#include "sfm_pruning/eval/synthetic_families.hpp"

namespace sfm_pruning {
namespace {

constexpr double kObjectDensityPerM2 = 90.0;
constexpr double kObjectReliefM = 0.02;
constexpr double kStickerStandOffM = 0.005;
constexpr double kGroundReliefM = 0.01;
constexpr double kMaxUniqueDensityPerM2 = 1500.0;
constexpr double kMinUniqueDensityPerM2 = 0.5;
constexpr double kRadiusJitterFraction = 0.03;
constexpr double kAngleJitterDeg = 1.5;
constexpr double kTargetJitterFraction = 0.05;

}  // namespace

SceneLayout BuildObjectFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                    std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const std::string kind = draw.Choice("object", {"cup", "box", "package"});
  const double scale = draw.Uniform("object_size_m", 1.0, 2.0);
  const double unique_share = draw.Uniform("unique_share_target", 0.02, 0.30);
  const std::string placement =
      kind == "cup" ? draw.Choice("unique_placement", {"ground", "sticker"})
                    : draw.Choice("unique_placement", {"ground", "top", "sticker"});
  auto print = [&](double width, double height) {
    return MakeTexture(width, height, kObjectDensityPerM2 * s, kObjectReliefM, &layout, rng);
  };

  size_t object_points = 0;
  double height = 0.0, footprint_radius = 0.0;
  double sticker_size = draw.Uniform("sticker_fraction", 0.2, 0.4) * scale;
  if (kind == "cup") {
    const double radius = draw.Uniform("cup_radius_fraction", 0.3, 0.5) * scale;
    height = scale;
    footprint_radius = radius;
    const double half = M_PI * radius;
    const Texture front = print(half, height);
    const Texture back = twins ? front : print(half, height);
    PlaceTextureOnCylinder(front, Eigen::Vector3d::Zero(), radius, 0.0, /*outward=*/true, &layout);
    PlaceTextureOnCylinder(back, Eigen::Vector3d::Zero(), radius, M_PI, /*outward=*/true, &layout);
    object_points = front.uvw.size() + back.uvw.size();
    if (placement == "sticker") {
      const double density = UniqueTextureDensity(unique_share, object_points, sticker_size * sticker_size,
                                                  kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
      const Texture sticker = MakeTexture(sticker_size, sticker_size, density * s, 0.0, &layout, rng);
      const double angle = DegToRad(draw.Uniform("sticker_angle_deg", 0.0, 360.0));
      PlaceTextureOnCylinder(sticker, {0, 0, 0.5 * (height - sticker_size)}, radius + kStickerStandOffM, angle,
                             /*outward=*/true, &layout);
    }
  } else {
    const bool package = kind == "package";
    const double length = (package ? draw.Uniform("side_fraction", 0.6, 1.0) : draw.Uniform("length_fraction", 0.8, 1.2)) * scale;
    const double depth = package ? length : draw.Uniform("depth_fraction", 0.4, 0.8) * scale;
    height = draw.Uniform("height_fraction", 0.6, 1.1) * scale;
    footprint_radius = 0.5 * std::hypot(length, depth);
    const std::array<BoxSide, 4> faces = BoxSideFaces(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), length, depth);
    // box: front = back and left = right (each turned 180 degrees); package: one print all round.
    std::vector<Texture> prints;
    for (int k = 0; k < 4; ++k) {
      const int source = package ? 0 : k % 2;
      const bool copy = twins && k > source;
      prints.push_back(copy ? prints[source] : print(faces[k].width_m, height));
      PlaceTexture(prints.back(), faces[k].origin, faces[k].u_axis, z, &layout);
      object_points += prints.back().uvw.size();
    }
    if (placement == "top") {
      const double density = UniqueTextureDensity(unique_share, object_points, length * depth, kMinUniqueDensityPerM2,
                                                  kMaxUniqueDensityPerM2);
      const Texture top = MakeTexture(length, depth, density * s, kObjectReliefM, &layout, rng);
      PlaceTexture(top, {-0.5 * length, -0.5 * depth, height}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                   &layout);
    } else if (placement == "sticker") {
      const double density = UniqueTextureDensity(unique_share, object_points, sticker_size * sticker_size,
                                                  kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
      const BoxSide& face = faces[draw.Integer("sticker_face", 0, 3)];
      const Eigen::Vector3d normal = face.u_axis.cross(z);
      sticker_size = std::min(sticker_size, 0.8 * face.width_m);
      const Texture sticker = MakeTexture(sticker_size, sticker_size, density * s, 0.0, &layout, rng);
      const Eigen::Vector3d origin = face.origin + 0.5 * (face.width_m - sticker_size) * face.u_axis +
                                     0.5 * (height - sticker_size) * z + kStickerStandOffM * normal;
      PlaceTexture(sticker, origin, face.u_axis, z, &layout);
    }
  }
  const double ground_half = 4.5 * scale;
  if (placement == "ground") {
    // The ground around the object's footprint (a ring of four rectangles, none under it).
    const double area = 4 * ground_half * ground_half;
    const double density = UniqueTextureDensity(unique_share, object_points, area, kMinUniqueDensityPerM2,
                                                kMaxUniqueDensityPerM2);
    const double g = ground_half, f = footprint_radius;
    const double rects[4][4] = {{-g, g, -g, -f}, {-g, g, f, g}, {-g, -f, -f, f}, {f, g, -f, f}};
    for (const auto& r : rects) {
      const Texture ground = MakeTexture(r[1] - r[0], r[3] - r[2], density * s, kGroundReliefM, &layout, rng);
      PlaceTexture(ground, {r[0], r[2], 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), &layout);
    }
  }
  draw.Record("unique_share", UniquePointShare(layout));

  // The orbit.
  const std::string path = draw.Choice("path", {"full_orbit", "partial_orbit", "two_rings"});
  const double orbit_radius = draw.Uniform("orbit_radius_fraction", 2.5, 4.0) * scale;
  const double camera_height = height + draw.Uniform("camera_elevation_fraction", 0.0, 1.0) * scale;
  const double second_height = path == "two_rings" ? draw.Uniform("second_ring_height_fraction", 0.2, 0.6) * scale : 0.0;
  const double arc = path == "partial_orbit" ? DegToRad(draw.Uniform("arc_deg", 200.0, 320.0)) : 2 * M_PI;
  const double start = DegToRad(draw.Uniform("start_angle_deg", 0.0, 360.0));
  const int per_ring = path == "two_rings" ? (options.num_views + 1) / 2 : options.num_views;
  std::uniform_real_distribution<double> radius_jitter(-kRadiusJitterFraction * scale, kRadiusJitterFraction * scale);
  std::uniform_real_distribution<double> angle_jitter(-DegToRad(kAngleJitterDeg), DegToRad(kAngleJitterDeg));
  std::uniform_real_distribution<double> target_jitter(-kTargetJitterFraction * scale, kTargetJitterFraction * scale);
  for (int i = 0; i < options.num_views; ++i) {
    const int ring = i / per_ring;
    const int k = i % per_ring;
    const double spacing = path == "partial_orbit" ? arc / std::max(1, per_ring - 1) : arc / per_ring;
    const double angle = start + k * spacing + 0.5 * ring * spacing + angle_jitter(rng);
    const double radius = orbit_radius + radius_jitter(rng);
    const double z_camera = ring == 0 ? camera_height : second_height;
    const Eigen::Vector3d center(radius * std::cos(angle), radius * std::sin(angle), z_camera);
    Eigen::Vector3d target(0.0, 0.0, 0.5 * height);
    for (int c = 0; c < 3; ++c) target[c] += target_jitter(rng);
    layout.poses.push_back(LookAtPose(center, target));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
