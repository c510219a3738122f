// Synthetic scenes at the level of features: the input on which every engine is tested and
// benchmarked. A scene is a set of textured surfaces and a camera trajectory; the generator
// renders each camera's keypoints and SIFT-like descriptors and matches them as a real matcher
// would, so the whole pipeline after feature extraction runs on it, with exact ground truth.
//
// Duplicate structure: "twin" points in several places of the scene share one base descriptor
// (they are copies of one texture). Images of different copies match, and those matches agree on
// a wrong relative pose: the false consensus that view-graph pruning must defeat. Every scene
// also has unique texture (ground, distinctive objects), so the truth is recoverable.
//
// Scenes (docs/synthetic_scenes.md): orbit_symmetric, street, courtyard, clean, sequential_large,
// and the procedural families family_* (synthetic_families.hpp), where the seed draws the whole
// scene. Same options (seed included) give byte-identical scenes.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/matches.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Every option with a value of 0 (or a negative value where noted) takes the scene's default.
// Bounds of the options that GenerateSyntheticScene checks (and the CLI's validators quote): past them
// a scene is no camera's (a focal of a million image sides) or the generator runs out of memory
// or time (infinitely many clutter keypoints).
struct SyntheticLimits {
  int max_views = 1000000;
  uint32_t max_image_side_px = 100000;
  double max_focal_image_sides = 1000.0;
  double max_noise_px = 1000.0;
  double max_descriptor_noise = 10.0;
  double max_clutter_ratio = 100.0;
  double max_point_density_scale = 100.0;
  double max_street_module_width_m = 1000.0;
};
inline constexpr SyntheticLimits kSyntheticLimits;

struct SyntheticSceneOptions {
  std::string scene = "orbit_symmetric";
  uint64_t seed = 0;

  // ---- Cameras
  int num_views = 0;             // scene default: 36 to 48 for the small scenes, 2000 for sequential_large
  uint32_t image_width = 0;      // scene default 1024x768 (small scenes) or 640x480 (sequential_large)
  uint32_t image_height = 0;
  double focal_px = 0.0;         // default 1.2 * max(width, height)

  // ---- Observations
  double noise_px = 1.0;                 // sigma of the Gaussian noise on keypoint positions
  double descriptor_noise = 0.25;        // expected norm of the descriptor noise (unit-norm histogram)
  double dropout = 0.2;                  // probability that a visible point is not detected
  double clutter_ratio = 0.3;            // clutter keypoints per view, relative to its detected points
  double max_incidence_deg = 75.0;       // max angle between surface normal and ray to the camera;
                                         // >= 90 observes surfaces from behind too (no facing test)
  double max_distance_m = 0.0;           // points farther than this are not detected (scene default)
  double point_density_scale = 1.0;      // multiplies every surface's point density

  // ---- Matching
  double ratio_test = 0.8;   // Lowe's ratio on descriptor distances (not squared)
  bool mutual_check = true;  // keep i->j only when i is also j's nearest neighbour
  // Target fraction of random (geometrically inconsistent) wrong matches among the putative
  // matches of each pair. Wrong matches are injected until
  //   random / (true + twin + random) = outlier_ratio,
  // counting the random wrong matches the descriptor matcher already made (clutter, noise). When
  // those already exceed the target, nothing is injected. Twin matches (cross-copy, consistent with
  // a wrong pose) are not random outliers and come on top, from the scene's duplicate structure.
  double outlier_ratio = 0.2;
  int min_matches = 15;  // pairs with fewer descriptor matches are dropped (before injection)

  // ---- Pair set (sequential_large; the small scenes match every pair)
  int sequential_window = 0;  // default 5: view i is paired with i+1 .. i+window
  int loop_candidates = 0;    // default 3: per view, the best-ranked non-sequential views by
                              // shared appearance (what image retrieval would propose)
  int loop_min_gap = 0;       // default 50: loop candidates are at least this many frames apart
  // sequential_large: laps of the loop (>= 2 revisits places, giving loop closures) and the
  // fraction of facade segments that repeat another segment (duplicates).
  int laps = 0;                 // default 2
  double twin_fraction = -1.0;  // default 0.25; 0 is allowed (negative = default)
  // Length of each straight of the stadium-shaped loop over the radius of its end arcs (default
  // 3): longer straights carry more building fronts that can repeat.
  double loop_straight_per_radius = 0.0;
  // street: width of the facade module that repeats. At the default 6 m a view (45° across, 7 m
  // from the facades) sees one whole period, so every pair of views matches the facade and even
  // neighbours carry twin matches along their epipolar lines (docs/synthetic_scenes.md).
  double street_module_width_m = 6.0;

  // Worker threads for matching; the output does not depend on it.
  int num_threads = 1;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  // Checks the values as given; GenerateSyntheticScene also checks them once the scene's
  // defaults (and a family's draws) are resolved, e.g. num_views against laps.
  void Check() const;
};

// What a family scene drew from its seed (synthetic_families.hpp): named numbers and labels.
// Empty for the fixed scenes.
struct SceneDescription {
  std::string family;
  std::map<std::string, double> values;
  std::map<std::string, std::string> labels;
};

// What the matcher did on one image pair, judged against the ground truth.
struct PairMatchStats {
  size_t num_true = 0;      // both features observe the same landmark
  size_t num_twin = 0;      // the features observe different copies of one texture (false, consistent)
  size_t num_random = 0;    // any other false match (clutter, confusion, injected)
  size_t num_injected = 0;  // of num_random: injected to reach outlier_ratio
  size_t num_false() const { return num_twin + num_random; }
  size_t total() const { return num_true + num_twin + num_random; }
};

struct SyntheticScene {
  std::string name;
  SyntheticSceneOptions options;  // with every default resolved (a family's draws included)
  SceneDescription description;   // a family scene's drawn parameters
  // Views, the intrinsic, true poses, and landmarks observed at least twice, each observation
  // referencing its feature id and noisy pixel position.
  SfmData ground_truth;
  FeaturesPerView features;
  PairwiseMatches putative_matches;

  // For every view, the landmark id of each feature (row = feature id); kUndefinedIndex for
  // clutter. Landmarks detected only once are not in ground_truth.structure.
  std::map<IndexT, std::vector<IndexT>> feature_landmarks;
  // Landmark id -> appearance (base descriptor) id, for every landmark of the scene.
  std::map<IndexT, IndexT> landmark_appearance;
  // Landmarks that share their appearance with another landmark (duplicate structure).
  std::set<IndexT> twin_landmarks;
  // For every pair of putative_matches.
  std::map<ViewPair, PairMatchStats> pair_stats;
};

// The scene names GenerateSyntheticScene accepts, in documentation order.
std::vector<std::string> SyntheticSceneNames();

// Generates a scene. Throws Error for an unknown scene name or an option out of range.
SyntheticScene GenerateSyntheticScene(const SyntheticSceneOptions& options,
                                      const ProgressCallback& progress = {});

}  // namespace sfm_pruning
