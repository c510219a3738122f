#include "sfm_pruning/eval/synthetic_families.hpp"

#include <algorithm>
#include <cmath>

#include "sfm_pruning/eval/synthetic_random.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

constexpr char kStreetFamily[] = "family_street";
constexpr char kCourtyardFamily[] = "family_courtyard";
constexpr char kObjectFamily[] = "family_object";
constexpr char kDeskFamily[] = "family_desk";
constexpr char kLoopFamily[] = "family_loop";
constexpr char kControlFamily[] = "family_control";

// The parameter streams of a family scene (SyntheticStream::kParameters, first id).
constexpr uint64_t kCaptureDraws = 0;
constexpr uint64_t kGeometryDraws = 1;
constexpr uint64_t kControlGeometryDraw = 2;

// The geometries a twin-free control scene takes its shape from.
const std::vector<std::string>& ControlGeometries() {
  static const std::vector<std::string> geometries = {"street", "courtyard", "object", "desk"};
  return geometries;
}

// FNV-1a of the family's name: its draws differ from another family's under the same seed.
uint64_t FamilyStreamId(const std::string& family) {
  uint64_t hash = 0xCBF29CE484222325ULL;
  for (const char c : family) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001B3ULL;
  return hash;
}

std::string ControlGeometry(uint64_t seed) {
  std::mt19937_64 rng =
      MakeSyntheticRng(seed, SyntheticStream::kParameters, kControlGeometryDraw, FamilyStreamId(kControlFamily));
  std::uniform_int_distribution<size_t> pick(0, ControlGeometries().size() - 1);
  return ControlGeometries()[pick(rng)];
}

// The geometry a family scene is built as: its own, or for a control the drawn one.
std::string GeometryOf(const SyntheticSceneOptions& options) {
  if (options.scene == kControlFamily) return ControlGeometry(options.seed);
  return options.scene.substr(std::string("family_").size());
}

struct ViewCountRange {
  int low = 0;
  int high = 0;
};

ViewCountRange ViewCounts(const std::string& geometry) {
  if (geometry == "street") return {30, 48};
  if (geometry == "courtyard") return {40, 56};
  if (geometry == "object") return {32, 60};
  if (geometry == "desk") return {28, 44};
  return {300, 500};  // loop: two laps of 150-250 views
}

}  // namespace

std::vector<std::string> SyntheticFamilyNames() {
  return {kStreetFamily, kCourtyardFamily, kObjectFamily, kDeskFamily, kLoopFamily, kControlFamily};
}

bool IsSyntheticFamily(const std::string& scene) {
  const std::vector<std::string> names = SyntheticFamilyNames();
  return std::find(names.begin(), names.end(), scene) != names.end();
}

double ParameterDraw::Uniform(const std::string& name, double low, double high) {
  std::uniform_real_distribution<double> distribution(low, high);
  const double value = distribution(*rng_);
  description_->values[name] = value;
  return value;
}

int ParameterDraw::Integer(const std::string& name, int low, int high) {
  std::uniform_int_distribution<int> distribution(low, high);
  const int value = distribution(*rng_);
  description_->values[name] = value;
  return value;
}

bool ParameterDraw::Chance(const std::string& name, double probability) {
  std::bernoulli_distribution distribution(probability);
  const bool value = distribution(*rng_);
  description_->values[name] = value ? 1.0 : 0.0;
  return value;
}

std::string ParameterDraw::Choice(const std::string& name, const std::vector<std::string>& choices) {
  std::uniform_int_distribution<size_t> distribution(0, choices.size() - 1);
  const std::string& value = choices[distribution(*rng_)];
  description_->labels[name] = value;
  return value;
}

void DrawFamilyCapture(SyntheticSceneOptions* options, SceneDescription* description) {
  SyntheticSceneOptions& o = *options;
  std::mt19937_64 rng = MakeSyntheticRng(o.seed, SyntheticStream::kParameters, kCaptureDraws, FamilyStreamId(o.scene));
  ParameterDraw draw(&rng, description);
  const std::string geometry = GeometryOf(o);
  description->family = o.scene;
  draw.Label("geometry", geometry);
  const bool loop = geometry == "loop";

  // Every draw happens whatever the user fixed, so that fixing one option leaves the others as
  // the seed drew them.
  const ViewCountRange views = ViewCounts(geometry);
  const int drawn_views = draw.Integer("num_views", views.low, views.high);
  const double focal_factor = draw.Uniform("focal_factor", 0.9, 1.5);  // focal / max(width, height)
  o.noise_px = draw.Uniform("noise_px", 0.5, 2.0);
  o.descriptor_noise = draw.Uniform("descriptor_noise", 0.2, 0.3);
  o.dropout = draw.Uniform("dropout", 0.1, 0.4);
  o.clutter_ratio = draw.Uniform("clutter_ratio", 0.1, 0.5);
  o.outlier_ratio = draw.Uniform("outlier_ratio", 0.05, 0.35);

  if (o.num_views == 0) o.num_views = loop ? 2 * (drawn_views / 2) : drawn_views;
  if (o.image_width == 0) o.image_width = loop ? 640 : 1024;
  if (o.image_height == 0) o.image_height = loop ? 480 : 768;
  if (o.focal_px == 0.0) o.focal_px = focal_factor * std::max(o.image_width, o.image_height);
  if (loop) {  // what the user left unset (0, or a negative twin fraction) takes the draw
    const double twin_fraction = draw.Uniform("twin_fraction", 0.3, 0.6);
    const double straight_per_radius = draw.Uniform("straight_per_radius", 5.0, 10.0);
    const int window = draw.Integer("sequential_window", 3, 6);
    const int candidates = draw.Integer("loop_candidates", 2, 4);
    if (o.laps == 0) o.laps = 2;
    if (o.twin_fraction < 0.0) o.twin_fraction = twin_fraction;
    if (o.loop_straight_per_radius == 0.0) o.loop_straight_per_radius = straight_per_radius;
    if (o.sequential_window == 0) o.sequential_window = window;
    if (o.loop_candidates == 0) o.loop_candidates = candidates;
    if (o.loop_min_gap == 0) o.loop_min_gap = 30;
    if (o.max_distance_m == 0.0) o.max_distance_m = 25.0;
  }
}

SceneLayout BuildFamilyLayout(const SyntheticSceneOptions& options, std::mt19937_64& rng) {
  const std::string geometry = GeometryOf(options);
  if (geometry == "loop") return BuildLoopLayout(options, rng);
  SceneDescription description;
  std::mt19937_64 parameter_rng =
      MakeSyntheticRng(options.seed, SyntheticStream::kParameters, kGeometryDraws, FamilyStreamId(options.scene));
  ParameterDraw draw(&parameter_rng, &description);
  const bool twins = options.scene != kControlFamily;
  SceneLayout layout;
  if (geometry == "street") layout = BuildStreetFamilyLayout(options, twins, draw, rng);
  else if (geometry == "courtyard") layout = BuildCourtyardFamilyLayout(options, twins, draw, rng);
  else if (geometry == "object") layout = BuildObjectFamilyLayout(options, twins, draw, rng);
  else if (geometry == "desk") layout = BuildDeskFamilyLayout(options, twins, draw, rng);
  else throw Error("synthetic scene: family '" + options.scene + "' has no geometry '" + geometry + "'");
  layout.description = std::move(description);
  return layout;
}

double UniqueTextureDensity(double share, size_t repeated_points, double unique_area_m2, double min_density,
                            double max_density) {
  if (unique_area_m2 <= 0.0) return min_density;
  const double unique_points = share / (1.0 - share) * static_cast<double>(repeated_points);
  return std::clamp(unique_points / unique_area_m2, min_density, max_density);
}

double UniquePointShare(const SceneLayout& layout) {
  if (layout.points.empty()) return 0.0;
  std::vector<size_t> copies(layout.num_appearances, 0);
  for (const SurfacePoint& point : layout.points) ++copies[point.appearance];
  size_t unique = 0;
  for (const SurfacePoint& point : layout.points) unique += copies[point.appearance] == 1 ? 1 : 0;
  return static_cast<double>(unique) / static_cast<double>(layout.points.size());
}

}  // namespace sfm_pruning
