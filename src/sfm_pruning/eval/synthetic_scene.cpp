#include "sfm_pruning/eval/synthetic_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "sfm_pruning/eval/synthetic_families.hpp"
#include "sfm_pruning/eval/synthetic_layout.hpp"
#include "sfm_pruning/eval/synthetic_matching.hpp"
#include "sfm_pruning/eval/synthetic_observations.hpp"
#include "sfm_pruning/eval/synthetic_pairs.hpp"
#include "sfm_pruning/eval/synthetic_random.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

constexpr char kOrbitSymmetric[] = "orbit_symmetric";
constexpr char kStreet[] = "street";
constexpr char kCourtyard[] = "courtyard";
constexpr char kClean[] = "clean";
constexpr char kSequentialLarge[] = "sequential_large";

// Pairs matched between two progress reports (and per batch of worker threads).
constexpr size_t kPairsPerBatch = 256;

bool IsLarge(const std::string& scene) { return scene == kSequentialLarge; }

void Require(bool condition, const std::string& problem) {
  if (!condition) throw Error("synthetic scene: " + problem);
}

SyntheticSceneOptions ResolveDefaults(SyntheticSceneOptions o, SceneDescription* description) {
  const std::vector<std::string> names = SyntheticSceneNames();
  if (std::find(names.begin(), names.end(), o.scene) == names.end()) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    throw Error("synthetic scene: unknown scene '" + o.scene + "' (expected one of: " + list + ")");
  }
  if (IsSyntheticFamily(o.scene)) DrawFamilyCapture(&o, description);
  const bool large = IsLarge(o.scene);
  if (o.num_views == 0) {
    if (large) o.num_views = 2000;
    else if (o.scene == kStreet) o.num_views = 40;
    else if (o.scene == kCourtyard) o.num_views = 48;
    else o.num_views = 36;
  }
  if (o.image_width == 0) o.image_width = large ? 640 : 1024;
  if (o.image_height == 0) o.image_height = large ? 480 : 768;
  if (o.focal_px == 0.0) o.focal_px = 1.2 * std::max(o.image_width, o.image_height);
  if (o.max_distance_m == 0.0) o.max_distance_m = large ? 25.0 : 40.0;
  if (o.sequential_window == 0) o.sequential_window = 5;
  if (o.loop_candidates == 0) o.loop_candidates = 3;
  if (o.loop_min_gap == 0) o.loop_min_gap = 50;
  if (o.laps == 0) o.laps = 2;
  if (o.twin_fraction < 0.0) o.twin_fraction = 0.25;
  if (o.loop_straight_per_radius == 0.0) o.loop_straight_per_radius = 3.0;
  if (o.num_threads == 0) o.num_threads = 1;

  const SyntheticLimits& limits = kSyntheticLimits;
  Require(o.num_views >= 2 && o.num_views <= limits.max_views,
          "num_views must be in [2, " + std::to_string(limits.max_views) + "]");
  Require(!(large || o.scene == "family_loop") || o.num_views >= 4 * o.laps,
          o.scene + " needs at least 4 views per lap");
  Require(o.image_width <= limits.max_image_side_px && o.image_height <= limits.max_image_side_px,
          "image_width and image_height must be at most " + std::to_string(limits.max_image_side_px));
  // The comparisons are written so that NaN fails each of them.
  Require(o.focal_px > 0.0 && o.focal_px <= limits.max_focal_image_sides * std::max(o.image_width, o.image_height),
          "focal_px must be positive and at most 1000 image sides");
  Require(o.noise_px >= 0.0 && o.noise_px <= limits.max_noise_px, "noise_px must be in [0, 1000]");
  Require(o.descriptor_noise >= 0.0 && o.descriptor_noise <= limits.max_descriptor_noise,
          "descriptor_noise must be in [0, 10]");
  Require(o.dropout >= 0.0 && o.dropout < 1.0, "dropout must be in [0, 1)");
  Require(o.clutter_ratio >= 0.0 && o.clutter_ratio <= limits.max_clutter_ratio, "clutter_ratio must be in [0, 100]");
  Require(o.max_incidence_deg > 0.0 && o.max_incidence_deg <= 180.0, "max_incidence_deg must be in (0, 180]");
  Require(o.max_distance_m > 0.0 && std::isfinite(o.max_distance_m), "max_distance_m must be positive");
  Require(o.point_density_scale > 0.0 && o.point_density_scale <= limits.max_point_density_scale,
          "point_density_scale must be in (0, 100]");
  Require(o.ratio_test > 0.0 && o.ratio_test <= 1.0, "ratio_test must be in (0, 1]");
  Require(o.outlier_ratio >= 0.0 && o.outlier_ratio < 1.0, "outlier_ratio must be in [0, 1)");
  Require(o.min_matches >= 0, "min_matches must be >= 0");
  Require(o.sequential_window > 0 && o.loop_candidates >= 0 && o.loop_min_gap > 0,
          "sequential_window and loop_min_gap must be positive, loop_candidates >= 0");
  Require(o.laps >= 1, "laps must be at least 1");
  Require(o.loop_straight_per_radius > 0.0 && o.loop_straight_per_radius <= 100.0,
          "loop_straight_per_radius must be in (0, 100]");
  Require(o.twin_fraction <= 0.9, "twin_fraction must be in [0, 0.9]");
  Require(o.street_module_width_m >= 2.0 && o.street_module_width_m <= limits.max_street_module_width_m,
          "street_module_width must be in [2, 1000] m (the shop sign is 2 m wide)");
  Require(o.num_threads >= 1, "num_threads must be at least 1");
  return o;
}

SceneLayout BuildLayout(const SyntheticSceneOptions& options) {
  std::mt19937_64 rng = MakeSyntheticRng(options.seed, SyntheticStream::kLayout);
  if (options.scene == kOrbitSymmetric) return BuildOrbitLayout(options, /*symmetric=*/true, rng);
  if (options.scene == kClean) return BuildOrbitLayout(options, /*symmetric=*/false, rng);
  if (options.scene == kStreet) return BuildStreetLayout(options, rng);
  if (options.scene == kCourtyard) return BuildCourtyardLayout(options, rng);
  if (IsSyntheticFamily(options.scene)) return BuildFamilyLayout(options, rng);
  return BuildLoopLayout(options, rng);
}

SfmData MakeGroundTruth(const SceneLayout& layout, const CameraIntrinsics& intrinsics,
                        std::map<IndexT, Landmark> landmarks) {
  SfmData data;
  data.intrinsics[0] = intrinsics;
  for (size_t v = 0; v < layout.poses.size(); ++v) {
    const auto id = static_cast<IndexT>(v);
    View view;
    view.id_view = id;
    view.id_intrinsic = 0;
    view.id_pose = id;
    char name[32];
    std::snprintf(name, sizeof(name), "view_%05u.jpg", id);
    view.filename = name;
    view.width = intrinsics.width();
    view.height = intrinsics.height();
    data.views[id] = view;
    data.poses[id] = layout.poses[v];
  }
  // Only points seen twice could ever be triangulated.
  for (auto& [id, landmark] : landmarks) {
    if (landmark.observations.size() >= 2) data.structure.emplace(id, std::move(landmark));
  }
  return data;
}

std::vector<ViewPair> SelectPairs(const SyntheticScene& scene, const SceneLayout& layout) {
  const auto num_views = static_cast<IndexT>(layout.poses.size());
  if (layout.pairs == PairSelection::kExhaustive) return ExhaustivePairs(num_views);
  std::vector<std::vector<IndexT>> view_appearances(num_views);
  for (const auto& [view_id, landmarks] : scene.feature_landmarks) {
    for (IndexT landmark : landmarks) {
      if (landmark != kUndefinedIndex) view_appearances[view_id].push_back(layout.points[landmark].appearance);
    }
  }
  const SyntheticSceneOptions& o = scene.options;
  return SequentialAndRetrievalPairs(view_appearances, layout.num_appearances, o.sequential_window,
                                     o.loop_min_gap, o.loop_candidates, o.min_matches);
}

struct PairResult {
  std::vector<FeatureMatch> matches;
  PairMatchStats stats;
  bool kept = false;
};

PairResult MatchPair(const SyntheticScene& scene, const ViewPair& pair) {
  const SyntheticSceneOptions& o = scene.options;
  const FeatureSet& a = scene.features.at(pair.first);
  const FeatureSet& b = scene.features.at(pair.second);
  PairResult result;
  result.matches = MatchDescriptorsBruteForce(a, b, o.ratio_test, o.mutual_check);
  if (result.matches.size() < static_cast<size_t>(std::max(1, o.min_matches))) return result;
  const MatchTruth truth{&scene.feature_landmarks.at(pair.first), &scene.feature_landmarks.at(pair.second),
                         &scene.landmark_appearance};
  const PairMatchStats found = ClassifyMatches(result.matches, truth);
  std::mt19937_64 rng = MakeSyntheticRng(o.seed, SyntheticStream::kPair, pair.first, pair.second);
  const size_t injected = InjectRandomWrongMatches(found, o.outlier_ratio, a.size(), b.size(), truth, rng, &result.matches);
  result.stats = found;
  result.stats.num_random += injected;
  result.stats.num_injected = injected;
  result.kept = true;
  return result;
}

// Matches every pair; pairs are independent, so worker threads change nothing in the output.
void MatchAllPairs(const std::vector<ViewPair>& pairs, SyntheticScene* scene, const ProgressCallback& progress) {
  const auto num_threads = static_cast<size_t>(scene->options.num_threads);
  for (size_t begin = 0; begin < pairs.size(); begin += kPairsPerBatch) {
    const size_t end = std::min(pairs.size(), begin + kPairsPerBatch);
    std::vector<PairResult> results(end - begin);
    auto work = [&](size_t first) {
      for (size_t k = begin + first; k < end; k += num_threads) results[k - begin] = MatchPair(*scene, pairs[k]);
    };
    std::vector<std::thread> workers;
    for (size_t t = 1; t < num_threads; ++t) workers.emplace_back(work, t);
    work(0);
    for (std::thread& worker : workers) worker.join();
    for (size_t k = begin; k < end; ++k) {
      PairResult& result = results[k - begin];
      if (!result.kept) continue;
      scene->putative_matches[pairs[k]] = std::move(result.matches);
      scene->pair_stats[pairs[k]] = result.stats;
    }
    ReportProgress(progress, "synth: match pairs", end, pairs.size());
  }
}

}  // namespace

std::vector<std::string> SyntheticSceneNames() {
  std::vector<std::string> names = {kOrbitSymmetric, kStreet, kCourtyard, kClean, kSequentialLarge};
  for (const std::string& family : SyntheticFamilyNames()) names.push_back(family);
  return names;
}

SyntheticScene GenerateSyntheticScene(const SyntheticSceneOptions& options, const ProgressCallback& progress) {
  // An option out of range is the Error this function documents, as for the resolved values.
  try {
    options.Check();
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("synthetic scene: ") + e.what());
  }
  SyntheticScene scene;
  scene.options = ResolveDefaults(options, &scene.description);
  scene.name = scene.options.scene;
  const SyntheticSceneOptions& o = scene.options;

  const SceneLayout layout = BuildLayout(o);
  for (const auto& [name, value] : layout.description.values) scene.description.values[name] = value;
  for (const auto& [name, label] : layout.description.labels) scene.description.labels[name] = label;
  const CameraIntrinsics intrinsics = CameraIntrinsics::Undistorted(
      CameraModel::kPinholeRadialK3, o.image_width, o.image_height, o.focal_px, 0.5 * o.image_width, 0.5 * o.image_height);
  const AppearanceTable appearances = MakeAppearanceTable(layout.num_appearances, o.seed);
  RenderedViews rendered = RenderViews(layout, intrinsics, appearances, o, progress);

  std::vector<size_t> copies(layout.num_appearances, 0);
  for (const SurfacePoint& point : layout.points) ++copies[point.appearance];
  for (size_t id = 0; id < layout.points.size(); ++id) {
    const IndexT appearance = layout.points[id].appearance;
    scene.landmark_appearance[static_cast<IndexT>(id)] = appearance;
    if (copies[appearance] > 1) scene.twin_landmarks.insert(static_cast<IndexT>(id));
  }
  scene.features = std::move(rendered.features);
  scene.feature_landmarks = std::move(rendered.feature_landmarks);
  scene.ground_truth = MakeGroundTruth(layout, intrinsics, std::move(rendered.landmarks));

  MatchAllPairs(SelectPairs(scene, layout), &scene, progress);
  return scene;
}

void SyntheticSceneOptions::Check() const {
  const std::vector<std::string> names = SyntheticSceneNames();
  if (std::find(names.begin(), names.end(), scene) == names.end()) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    option_checks_detail::Fail("SyntheticSceneOptions::scene", "one of " + list, "'" + scene + "'");
  }
  // The bounds are those GenerateSyntheticScene applies to the resolved values (kSyntheticLimits);
  // 0 (twin_fraction: negative) takes the scene's default where the header says so. A family scene
  // replaces the capture conditions (noise, dropout, clutter, outliers) with its draws, but a value
  // out of range means nothing there either.
  const SyntheticLimits& limits = kSyntheticLimits;
  if (num_views != 0) {
    RequireInRange(num_views, 2, limits.max_views, "SyntheticSceneOptions::num_views (or 0: scene default)");
  }
  RequireInRange(image_width, 0u, limits.max_image_side_px, "SyntheticSceneOptions::image_width");
  RequireInRange(image_height, 0u, limits.max_image_side_px, "SyntheticSceneOptions::image_height");
  if (focal_px != 0.0) {
    RequirePositiveAtMost(focal_px, limits.max_focal_image_sides * limits.max_image_side_px,
                          "SyntheticSceneOptions::focal_px (or 0: scene default)");
  }
  RequireInRange(noise_px, 0.0, limits.max_noise_px, "SyntheticSceneOptions::noise_px");
  RequireInRange(descriptor_noise, 0.0, limits.max_descriptor_noise,
                 "SyntheticSceneOptions::descriptor_noise");
  // Dropping every point would leave nothing to detect.
  RequireInHalfOpenRange(dropout, 0.0, 1.0, "SyntheticSceneOptions::dropout");
  RequireInRange(clutter_ratio, 0.0, limits.max_clutter_ratio, "SyntheticSceneOptions::clutter_ratio");
  // 90 or more turns the facing test off; 0 would detect nothing.
  RequirePositiveAtMost(max_incidence_deg, 180.0, "SyntheticSceneOptions::max_incidence_deg");
  if (max_distance_m != 0.0) {
    RequirePositiveFinite(max_distance_m, "SyntheticSceneOptions::max_distance_m (or 0: scene default)");
  }
  RequirePositiveAtMost(point_density_scale, limits.max_point_density_scale,
                        "SyntheticSceneOptions::point_density_scale");
  RequirePositiveAtMost(ratio_test, 1.0, "SyntheticSceneOptions::ratio_test");
  // Only wrong matches would have to be injected among no true one.
  RequireInHalfOpenRange(outlier_ratio, 0.0, 1.0, "SyntheticSceneOptions::outlier_ratio");
  RequireAtLeast(min_matches, 0, "SyntheticSceneOptions::min_matches");
  RequireAtLeast(sequential_window, 0, "SyntheticSceneOptions::sequential_window (0: scene default)");
  RequireAtLeast(loop_candidates, 0, "SyntheticSceneOptions::loop_candidates (0: scene default)");
  RequireAtLeast(loop_min_gap, 0, "SyntheticSceneOptions::loop_min_gap (0: scene default)");
  RequireAtLeast(laps, 0, "SyntheticSceneOptions::laps (0: scene default)");
  if (!(twin_fraction < 0.0)) {
    RequireInRange(twin_fraction, 0.0, 0.9,
                   "SyntheticSceneOptions::twin_fraction (or negative: scene default)");
  }
  if (loop_straight_per_radius != 0.0) {
    RequirePositiveAtMost(loop_straight_per_radius, 100.0,
                          "SyntheticSceneOptions::loop_straight_per_radius (or 0: scene default)");
  }
  // The shop sign on each facade module is 2 m wide.
  RequireInRange(street_module_width_m, 2.0, limits.max_street_module_width_m,
                 "SyntheticSceneOptions::street_module_width_m");
  RequireAtLeast(num_threads, 0, "SyntheticSceneOptions::num_threads (0: one)");
}

}  // namespace sfm_pruning
