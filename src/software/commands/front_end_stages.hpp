// The image front end's stages as `prunesfm init`, `features`, `match` and `run IMAGES OUT` share
// them: their command-line options, and each stage from its input files to its output files.
//
// Files (OpenMVG's layout, so OpenMVG tools can take over at any point):
//   <matches_dir>/sfm_data.json         views + intrinsics (init)
//   <matches_dir>/camera_priors.json    focal source per camera, skipped images (init)
//   <matches_dir>/<image>.feat/.desc, image_describer.json   SIFT (features)
//   <matches_dir>/matches.putative.bin  descriptor matches (match)
//   <matches_dir>/matches.e.bin         their inliers after the two-view verification (match)
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

struct InitSettings {
  double focal = 0.0;  // > 0: every camera's focal in pixels
  std::string k_file;
  double sensor_width_mm = 0.0;
  double default_focal_factor = 1.2;
  std::string camera_model = "pinhole_radial_k1";
  std::string grouping = "camera";  // or "image"
};

struct FeatureSettings {
  int max_features = 12288;  // SiftOptions::max_features
  int max_image_size = 1600;  // SiftOptions::max_image_size
  bool no_root_sift = false;
};

struct MatchSettings {
  std::string pairs = "exhaustive";  // or "sequential", "list"
  int window = 10;
  bool loop = false;
  std::string pair_list;
  std::string matcher = "AUTO";  // or "FLANN", "BRUTE_FORCE"
  double ratio = 0.8;
  bool no_mutual = false;
  int flann_checks = 64;
  uint64_t seed = 0;
  double max_epipolar_error_deg = 0.25;  // the verification's inlier threshold
  double verification_precision_ratio = 0.5;  // RelativePoseOptions::precision_check_ratio
};

// --max_epipolar_error_deg, the verification's inlier threshold, and --verification_precision_ratio
// (RelativePoseOptions::precision_check_ratio): in `match`, and among the engine options of
// reconstruct, run and prune.
void AddVerificationOptions(CLI::App* cmd, double* max_epipolar_error_deg, double* precision_ratio);

void AddInitOptions(CLI::App* cmd, InitSettings* settings);
void AddFeatureOptions(CLI::App* cmd, FeatureSettings* settings);
// `standalone`: false when the command has the engine's options (run), which give --seed and
// --max_epipolar_error_deg.
void AddMatchOptions(CLI::App* cmd, MatchSettings* settings, bool standalone);

// One line per setting, the key of a stage in run's manifest (a changed option reruns it).
std::string SettingsKey(const InitSettings& settings);
std::string SettingsKey(const FeatureSettings& settings);
std::string SettingsKey(const MatchSettings& settings);

// image_dir -> sfm_path (sfm_data.json) + camera_priors.json beside it. Reports skipped images
// and the cameras on stderr.
void RunInitStage(const InitSettings& settings, const std::filesystem::path& image_dir,
                  const std::filesystem::path& sfm_path, int num_threads);

// The scene's images -> .feat/.desc in matches_dir. Returns the features.
sfm_pruning::FeaturesPerView RunFeatureStage(const FeatureSettings& settings, const sfm_pruning::SfmData& scene,
                                             const std::filesystem::path& matches_dir, int num_threads);

struct MatchStageSummary {
  size_t num_pairs = 0;             // pairs selected
  size_t num_putative_pairs = 0;    // pairs with enough descriptor matches
  size_t num_putative_matches = 0;
  size_t num_verified_pairs = 0;
  size_t num_verified_inliers = 0;
};

// The valid edges of `graph` as COLMAP two-view geometries: inliers, E and the relative pose,
// config CALIBRATED (`run IMAGES OUT`'s database.db, `prune` of a database of matches only).
std::map<sfm_pruning::ViewPair, sfm_pruning::ColmapTwoViewGeometry> ColmapGeometriesOf(
    const sfm_pruning::ViewGraph& graph);

// Features (with descriptors) -> matches.putative.bin and matches.e.bin in matches_dir. With a
// `colmap_database` path, also the same features, matches and verified pairs as a COLMAP 3.8
// database (WriteColmapDatabase: keypoints, descriptors, matches, two_view_geometries with the
// inliers, E and the relative pose, config CALIBRATED; cameras whose focal `init` guessed, per
// matches_dir/camera_priors.json, get prior_focal_length 0), for colmap mapper, glomap mapper
// and prunesfm prune. `features` is left as it was.
MatchStageSummary RunMatchStage(const MatchSettings& settings, const sfm_pruning::SfmData& scene,
                                sfm_pruning::FeaturesPerView* features, const std::filesystem::path& matches_dir,
                                int num_threads, const std::filesystem::path& colmap_database = {});

}  // namespace prunesfm
