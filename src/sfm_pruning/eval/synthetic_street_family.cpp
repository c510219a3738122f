// family_street: facades along a street, drawn per seed. 1-3 facade designs repeat along one or
// two sides, in a periodic or random order, with or without gaps between the buildings. The
// unique texture (2-30 % of the points) sits in one place: shop signs on some facades, recessed
// walls in the gaps, or only the street surface. The camera walks sideways, zig-zags, looks
// obliquely ahead, or (two sides) walks down the middle looking ahead.
#include <algorithm>
#include <cmath>

#include "sfm_pruning/eval/synthetic_families.hpp"

namespace sfm_pruning {
namespace {

constexpr double kFacadeDensityPerM2 = 12.0;
constexpr double kFacadeReliefM = 0.05;
constexpr double kSignWidthM = 2.0;
constexpr double kSignHeightM = 1.2;
constexpr double kSignElevationM = 2.5;
constexpr double kSignStandOffM = 0.1;
constexpr double kGapRecessM = 2.0;       // the wall in a gap stands this far behind the facades
constexpr double kGroundReliefM = 0.01;
constexpr double kBehindCameraM = 3.0;    // the street surface extends this far behind the path
constexpr double kMaxUniqueDensityPerM2 = 400.0;
constexpr double kMinUniqueDensityPerM2 = 0.5;
constexpr double kCameraHeightM = 1.7;
constexpr double kPositionJitterM = 0.15;
constexpr double kHeadingJitterDeg = 3.0;

struct StreetSide {
  double distance_m = 0.0;  // |y| of the facade line
  bool left = true;         // true: y = +distance, facing -y; false: y = -distance, facing +y
};

// Places a texture on a side's facade line from x0 on (u along the street, v up), at `stand_m`
// in front of the facades and `elevation_m` above the ground.
void PlaceOnSide(const Texture& texture, const StreetSide& side, double x0, double width_m, double stand_m,
                 double elevation_m, SceneLayout* layout) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  if (side.left) {
    PlaceTexture(texture, {x0, side.distance_m - stand_m, elevation_m}, Eigen::Vector3d::UnitX(), z, layout);
  } else {  // u = -x keeps the normal towards the street (+y)
    PlaceTexture(texture, {x0 + width_m, -side.distance_m + stand_m, elevation_m}, -Eigen::Vector3d::UnitX(), z,
                 layout);
  }
}

}  // namespace

SceneLayout BuildStreetFamilyLayout(const SyntheticSceneOptions& options, bool twins, ParameterDraw& draw,
                                    std::mt19937_64& rng) {
  SceneLayout layout;
  const double s = options.point_density_scale;
  const bool two_sides = draw.Chance("two_sides", 0.3);
  const int num_designs = draw.Integer("num_designs", 1, 3);
  const bool random_order = draw.Choice("design_order", {"periodic", "random"}) == "random";
  const double module_width = draw.Uniform("module_width_m", 4.0, 10.0);
  const bool gaps = draw.Chance("gaps", 0.5);
  const double gap_width = gaps ? draw.Uniform("gap_width_m", 1.0, 4.0) : 0.0;
  const double facade_height = draw.Uniform("facade_height_m", 6.0, 12.0);
  const double distance = draw.Uniform("facade_distance_m", 6.0, 12.0);
  const double unique_share = draw.Uniform("unique_share_target", 0.02, 0.30);
  std::vector<std::string> placements = {"signs", "ground"};
  if (gaps) placements.push_back("gap_walls");
  const std::string placement = draw.Choice("unique_placement", placements);
  const std::string path =
      two_sides ? draw.Choice("path", {"forward"}) : draw.Choice("path", {"sideways", "zigzag", "oblique"});
  const bool forward = path == "forward";
  const double step = forward ? draw.Uniform("step_m", 0.8, 1.5) : draw.Uniform("step_m", 0.5, 1.2);
  const double swing_deg = draw.Uniform("pan_swing_deg", 5.0, 25.0);
  const double pitch_deg = draw.Uniform("pitch_deg", -5.0, 10.0);
  const double sign_probability = draw.Uniform("sign_probability", 0.3, 0.7);

  std::vector<StreetSide> sides = {{distance, true}};
  if (two_sides) sides.push_back({draw.Uniform("second_side_distance_m", 6.0, 12.0), false});

  const double path_length = step * std::max(0, options.num_views - 1);
  const double margin = forward || path == "oblique" ? 30.0 : 12.0;
  const double x_begin = -margin;
  const double pitch = module_width + gap_width;
  const int num_modules = static_cast<int>(std::ceil((path_length + 2 * margin) / pitch));

  // Facades: the designs repeat (or, for a control, every building is its own).
  std::vector<Texture> designs;
  for (int d = 0; d < num_designs; ++d) {
    designs.push_back(MakeTexture(module_width, facade_height, kFacadeDensityPerM2 * s, kFacadeReliefM, &layout, rng));
  }
  std::uniform_int_distribution<int> pick_design(0, num_designs - 1);
  std::bernoulli_distribution has_sign(sign_probability);
  std::vector<std::pair<const StreetSide*, double>> sign_spots, gap_spots;  // (side, x)
  size_t facade_points = 0;
  for (const StreetSide& side : sides) {
    for (int k = 0; k < num_modules; ++k) {
      const double x0 = x_begin + k * pitch;
      const int design = random_order ? pick_design(rng) : k % num_designs;
      if (twins) {
        PlaceOnSide(designs[design], side, x0, module_width, 0.0, 0.0, &layout);
        facade_points += designs[design].uvw.size();
      } else {
        const Texture own = MakeTexture(module_width, facade_height, kFacadeDensityPerM2 * s, kFacadeReliefM, &layout, rng);
        PlaceOnSide(own, side, x0, module_width, 0.0, 0.0, &layout);
        facade_points += own.uvw.size();
      }
      if (has_sign(rng)) sign_spots.emplace_back(&side, x0 + 0.5 * (module_width - kSignWidthM));
      if (gaps) gap_spots.emplace_back(&side, x0 + module_width);
    }
  }

  // The unique texture, all in one placement.
  if (placement == "signs") {
    if (sign_spots.empty()) sign_spots.emplace_back(&sides[0], x_begin + 0.5 * (module_width - kSignWidthM));
    const double density = UniqueTextureDensity(unique_share, facade_points, sign_spots.size() * kSignWidthM * kSignHeightM,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    for (const auto& [side, x] : sign_spots) {
      const Texture sign = MakeTexture(kSignWidthM, kSignHeightM, density * s, 0.0, &layout, rng);
      PlaceOnSide(sign, *side, x, kSignWidthM, kSignStandOffM, kSignElevationM, &layout);
    }
  } else if (placement == "gap_walls") {
    const double density = UniqueTextureDensity(unique_share, facade_points, gap_spots.size() * gap_width * facade_height,
                                                kMinUniqueDensityPerM2, kMaxUniqueDensityPerM2);
    for (const auto& [side, x] : gap_spots) {
      const Texture wall = MakeTexture(gap_width, facade_height, density * s, kFacadeReliefM, &layout, rng);
      PlaceOnSide(wall, *side, x, gap_width, -kGapRecessM, 0.0, &layout);
    }
  } else {
    const double y0 = two_sides ? -sides[1].distance_m : -kBehindCameraM;
    const double width = distance - y0;
    const double length = num_modules * pitch;
    const double density = UniqueTextureDensity(unique_share, facade_points, length * width, kMinUniqueDensityPerM2,
                                                kMaxUniqueDensityPerM2);
    const Texture ground = MakeTexture(length, width, density * s, kGroundReliefM, &layout, rng);
    PlaceTexture(ground, {x_begin, y0, 0.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), &layout);
  }
  draw.Record("unique_share", UniquePointShare(layout));

  // The camera path. Heading pi/2 faces the left facades (+y); 0 looks down the street.
  const double zigzag_amplitude = path == "zigzag" ? draw.Uniform("zigzag_amplitude_m", 1.0, 3.0) : 0.0;
  const int zigzag_period = path == "zigzag" ? draw.Integer("zigzag_period_views", 4, 8) : 1;
  const double oblique_deg = path == "oblique" ? draw.Uniform("oblique_deg", 25.0, 50.0) : 0.0;
  std::uniform_real_distribution<double> position_jitter(-kPositionJitterM, kPositionJitterM);
  std::uniform_real_distribution<double> heading_jitter(-DegToRad(kHeadingJitterDeg), DegToRad(kHeadingJitterDeg));
  for (int i = 0; i < options.num_views; ++i) {
    const double jx = position_jitter(rng);
    const double jy = position_jitter(rng);
    double y = jy;
    double heading = M_PI / 2 + DegToRad(swing_deg) * std::sin(0.35 * i);
    if (path == "zigzag") {
      const double phase = std::fmod(static_cast<double>(i), zigzag_period) / zigzag_period;  // [0, 1)
      y += zigzag_amplitude * (phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase);                 // triangle wave
      heading = M_PI / 2 + DegToRad(swing_deg) * std::cos(2 * M_PI * i / zigzag_period);
    } else if (path == "oblique") {
      heading = M_PI / 2 - DegToRad(oblique_deg) + DegToRad(0.3 * swing_deg) * std::sin(0.35 * i);
    } else if (forward) {
      y += 0.5 * (distance - sides[1].distance_m);  // the middle of the street
      heading = DegToRad(0.4 * swing_deg) * std::sin(0.35 * i);
    }
    const Eigen::Vector3d center(i * step + jx, y, kCameraHeightM);
    layout.poses.push_back(HeadingPitchPose(center, heading + heading_jitter(rng), DegToRad(pitch_deg)));
  }
  layout.pairs = PairSelection::kExhaustive;
  return layout;
}

}  // namespace sfm_pruning
