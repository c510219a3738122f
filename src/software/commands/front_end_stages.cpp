#include "software/commands/front_end_stages.hpp"

#include <CLI/CLI.hpp>

#include <sstream>

#include "sfm_pruning/features/descriptor_matching.hpp"
#include "sfm_pruning/features/image_listing.hpp"
#include "sfm_pruning/features/pair_selection.hpp"
#include "sfm_pruning/features/sift_extraction.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/io/camera_priors.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/k_file.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/help_format.hpp"

namespace prunesfm {
namespace fs = std::filesystem;
namespace {

using sfm_pruning::Error;

sfm_pruning::ImageListingOptions ListingOptions(const InitSettings& settings, int num_threads) {
  sfm_pruning::ImageListingOptions options;
  if (settings.focal > 0.0) options.focal_px = settings.focal;
  if (!settings.k_file.empty()) options.K = sfm_pruning::ReadKFile(settings.k_file);
  options.focal.sensor_width_mm = settings.sensor_width_mm;
  options.focal.default_focal_factor = settings.default_focal_factor;
  if (!sfm_pruning::CameraModelFromName(settings.camera_model, &options.camera_model)) {
    throw Error("unknown camera model '" + settings.camera_model + "'");
  }
  options.grouping = settings.grouping == "image" ? sfm_pruning::CameraGrouping::kPerImage
                                                  : sfm_pruning::CameraGrouping::kPerBodyAndSize;
  options.num_threads = num_threads;
  return options;
}

std::string Fixed(double value, int digits) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

sfm_pruning::PairSet SelectPairs(const MatchSettings& settings, const sfm_pruning::SfmData& scene) {
  const std::vector<sfm_pruning::IndexT> ids = sfm_pruning::ViewIdsInOrder(scene);
  if (settings.pairs == "sequential") return sfm_pruning::SequentialPairs(ids, settings.window, settings.loop);
  if (settings.pairs == "list") {
    if (settings.pair_list.empty()) throw Error("match: --pairs list needs --pair_list FILE");
    return sfm_pruning::PairsFromList(settings.pair_list, scene);
  }
  return sfm_pruning::ExhaustivePairs(ids);
}

}  // namespace

void AddInitOptions(CLI::App* cmd, InitSettings* settings) {
  cmd->add_option("--focal", settings->focal, "Focal length in pixels of every camera (a prior: refined in bundle adjustment like an EXIF focal)")
      ->check(PositiveValue());
  cmd->add_option("--k_file", settings->k_file, "K matrix file (9 numbers, e.g. Strecha's K.txt): focal and principal point (a calibration: held)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--sensor_width", settings->sensor_width_mm,
                  "Sensor width in mm, used with the EXIF focal in mm before the 35 mm equivalent")
      ->check(PositiveValue())
      ->group(kExpertOptionsGroup);
  cmd->add_option("--default_focal_factor", settings->default_focal_factor,
                  "Without --focal, K or EXIF: focal = this x max(width, height), marked as a guess")
      ->check(PositiveValue())
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--camera_model", settings->camera_model, "Intrinsic model (distortion starts at zero)")
      ->check(CLI::IsMember({"pinhole", "pinhole_radial_k1", "pinhole_radial_k3", "pinhole_brown_t2"}))
      ->capture_default_str();
  cmd->add_option("--grouping", settings->grouping,
                  "camera: one intrinsic per camera body, image size and focal; image: one per image")
      ->check(CLI::IsMember({"camera", "image"}))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
}

void AddFeatureOptions(CLI::App* cmd, FeatureSettings* settings) {
  cmd->add_option("--max_features", settings->max_features, "Strongest SIFT features kept per image")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->add_option("--max_image_size", settings->max_image_size,
                  "Images are downscaled so that max(width, height) <= this for extraction")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->add_flag("--no_root_sift", settings->no_root_sift, "Plain SIFT descriptors instead of RootSIFT")
      ->group(kExpertOptionsGroup);
}

void AddVerificationOptions(CLI::App* cmd, double* max_epipolar_error_deg, double* precision_ratio) {
  cmd->add_option("--max_epipolar_error_deg", *max_epipolar_error_deg,
                  "Inlier threshold of the two-view verification: angle between a bearing and its epipolar "
                  "plane (0.25 deg ~ 5 px at a focal of 1200 px). Lower keeps fewer matches that lie near but "
                  "not on their epipolar line, such as those between copies of a texture repeated along the "
                  "baseline (docs/global.md)")
      ->check(PositiveValue())
      ->check(RangeValue(0.0, 90.0))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--verification_precision_ratio", *precision_ratio,
                  "0 = off. With r in (0, 1), each pair's pose is also estimated at r times the threshold, and the "
                  "model that fits the matches more tightly is kept (its inliers still selected at the full "
                  "threshold): on a plane whose texture repeats along the baseline, the loose threshold can "
                  "prefer a wrong pose that fits the true matches and the repeats together. Doubles the "
                  "verification's RANSAC (docs/global.md)")
      ->check(RangeValue(0.0, 0.99))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
}

void AddMatchOptions(CLI::App* cmd, MatchSettings* settings, bool standalone) {
  cmd->add_option("--pairs", settings->pairs, "Pair selection")
      ->check(CLI::IsMember({"exhaustive", "sequential", "list"}))
      ->capture_default_str();
  cmd->add_option("--window", settings->window, "sequential: each image with the next N images")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->add_flag("--loop", settings->loop, "sequential: the last images are also paired with the first (a ring)");
  cmd->add_option("--pair_list", settings->pair_list, "list: OpenMVG pair file (lines 'I J K ...')")
      ->check(CLI::ExistingFile);
  cmd->add_option("--matcher", settings->matcher,
                  "FLANN kd-trees (approximate), exact BRUTE_FORCE, or AUTO: per pair the cheaper of the two "
                  "(brute force up to ~10000 features per image)")
      ->check(CLI::IsMember({"AUTO", "FLANN", "BRUTE_FORCE"}))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--ratio", settings->ratio, "Lowe's ratio test on descriptor distances")
      ->check(RangeValue(0.1, 1.0))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_flag("--no_mutual", settings->no_mutual, "Keep one-directional matches (no mutual check)")
      ->group(kExpertOptionsGroup);
  cmd->add_option("--flann_checks", settings->flann_checks, "FLANN: leaves visited per query")
      ->check(PositiveValue())
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  if (standalone) {
    cmd->add_option("--seed", settings->seed, "Seed of the kd-trees and of the verification's RANSAC")
        ->check(SeedValue())
        ->capture_default_str();
    AddVerificationOptions(cmd, &settings->max_epipolar_error_deg, &settings->verification_precision_ratio);
  }
}

std::string SettingsKey(const InitSettings& s) {
  return "focal=" + Fixed(s.focal, 6) + "\nk_file=" + s.k_file + "\nsensor_width=" + Fixed(s.sensor_width_mm, 6) +
         "\ndefault_focal_factor=" + Fixed(s.default_focal_factor, 6) + "\ncamera_model=" + s.camera_model +
         "\ngrouping=" + s.grouping + "\n";
}

std::string SettingsKey(const FeatureSettings& s) {
  return "max_features=" + std::to_string(s.max_features) + "\nmax_image_size=" + std::to_string(s.max_image_size) +
         "\nroot_sift=" + std::to_string(!s.no_root_sift) + "\n";
}

std::string SettingsKey(const MatchSettings& s) {
  return "pairs=" + s.pairs + "\nwindow=" + std::to_string(s.window) + "\nloop=" + std::to_string(s.loop) +
         "\npair_list=" + s.pair_list + "\nmatcher=" + s.matcher + "\nratio=" + Fixed(s.ratio, 6) +
         "\nmutual=" + std::to_string(!s.no_mutual) + "\nflann_checks=" + std::to_string(s.flann_checks) +
         "\nseed=" + std::to_string(s.seed) + "\nmax_epipolar_error_deg=" + Fixed(s.max_epipolar_error_deg, 6) +
         "\nverification_precision_ratio=" + Fixed(s.verification_precision_ratio, 6) + "\n";
}

void RunInitStage(const InitSettings& settings, const fs::path& image_dir, const fs::path& sfm_path,
                  int num_threads) {
  const sfm_pruning::ImageListing listing =
      sfm_pruning::ListImages(image_dir, ListingOptions(settings, num_threads), ProgressOnStderr());
  sfm_pruning::CameraPriors priors;
  for (const sfm_pruning::SkippedImage& skipped : listing.skipped) {
    Info("skipped " + (image_dir / skipped.filename).string() + ": " + skipped.reason);
    priors.skipped_images.push_back({skipped.filename, skipped.reason});
  }
  for (const auto& [intrinsic_id, camera] : listing.cameras) {
    const sfm_pruning::CameraIntrinsics& intrinsics = listing.scene.intrinsics.at(intrinsic_id);
    priors.cameras.push_back({intrinsic_id, camera.body, intrinsics.FocalLength(),
                              sfm_pruning::FocalSourceName(camera.focal_source),
                              sfm_pruning::IsFocalTrusted(camera.focal_source), camera.num_views});
    Info("camera " + std::to_string(intrinsic_id) + (camera.body.empty() ? "" : " (" + camera.body + ")") + ": " +
         std::to_string(intrinsics.width()) + "x" + std::to_string(intrinsics.height()) + ", focal " +
         Fixed(intrinsics.FocalLength(), 1) + " px from " + sfm_pruning::FocalSourceName(camera.focal_source) +
         (sfm_pruning::IsFocalTrusted(camera.focal_source) ? "" : " (a guess)") + ", " +
         std::to_string(camera.num_views) + " images");
  }
  if (!sfm_path.parent_path().empty()) fs::create_directories(sfm_path.parent_path());
  sfm_pruning::WriteSfmData(listing.scene, sfm_path);
  sfm_pruning::WriteCameraPriors(sfm_path.parent_path() / sfm_pruning::kCameraPriorsFileName, priors);
  Info("listed " + std::to_string(listing.scene.views.size()) + " images (" + std::to_string(listing.skipped.size()) +
       " skipped) into " + sfm_path.string());
}

sfm_pruning::FeaturesPerView RunFeatureStage(const FeatureSettings& settings, const sfm_pruning::SfmData& scene,
                                             const fs::path& matches_dir, int num_threads) {
  sfm_pruning::SiftOptions options;
  options.max_features = settings.max_features;
  options.max_image_size = settings.max_image_size;
  options.root_sift = !settings.no_root_sift;
  options.num_threads = num_threads;
  sfm_pruning::FeatureExtractionReport report;
  sfm_pruning::FeaturesPerView features =
      sfm_pruning::ExtractFeatures(scene, options, &report, ProgressOnStderr());
  for (const auto& [view_id, problem] : report.failed_views) {
    Info("no features for view " + std::to_string(view_id) + " (" + scene.views.at(view_id).RelativeImagePath() +
         "): " + problem);
  }
  if (features.empty()) throw Error(scene.root_path + ": no image of the scene decodes");
  fs::create_directories(matches_dir);
  sfm_pruning::WriteOpenMvgFeatures(scene, features, matches_dir, ProgressOnStderr());
  Info("extracted " + std::to_string(report.total_features) + " SIFT features in " + std::to_string(features.size()) +
       " images (" + Fixed(static_cast<double>(report.total_features) / features.size(), 0) + " per image) into " +
       matches_dir.string());
  return features;
}

namespace {

// The verified graph as COLMAP's database holds it; `features` are moved in and must be moved back.
void WriteMatchDatabase(const sfm_pruning::SfmData& scene, const sfm_pruning::ViewGraph& graph,
                        const sfm_pruning::PairwiseMatches& putative, const fs::path& matches_dir,
                        sfm_pruning::FeaturesPerView* features, const fs::path& path) {
  sfm_pruning::ColmapDatabase database;
  database.sfm_data = scene;
  database.sfm_data.root_path.clear();
  const fs::path priors = matches_dir / sfm_pruning::kCameraPriorsFileName;
  if (fs::exists(priors)) {
    database.intrinsics_with_guessed_focal = sfm_pruning::ReadCameraPriors(priors).IntrinsicsWithGuessedFocal();
  }
  database.putative = putative;
  database.verified = ColmapGeometriesOf(graph);
  database.features = std::move(*features);
  try {
    sfm_pruning::WriteColmapDatabase(database, path);
  } catch (...) {
    *features = std::move(database.features);
    throw;
  }
  *features = std::move(database.features);
}

}  // namespace

std::map<sfm_pruning::ViewPair, sfm_pruning::ColmapTwoViewGeometry> ColmapGeometriesOf(
    const sfm_pruning::ViewGraph& graph) {
  std::map<sfm_pruning::ViewPair, sfm_pruning::ColmapTwoViewGeometry> geometries;
  graph.ForEachValidEdge([&](const sfm_pruning::ViewPair& pair, const sfm_pruning::ViewGraphEdge& edge) {
    sfm_pruning::ColmapTwoViewGeometry& geometry = geometries[pair];
    geometry.inliers = edge.matches;
    geometry.config = static_cast<int>(sfm_pruning::ColmapTwoViewConfig::kCalibrated);
    geometry.E = sfm_pruning::SkewMatrix(edge.relative_pose.translation) * edge.relative_pose.rotation;
    geometry.relative_pose = edge.relative_pose;
  });
  return geometries;
}

MatchStageSummary RunMatchStage(const MatchSettings& settings, const sfm_pruning::SfmData& scene,
                                sfm_pruning::FeaturesPerView* features, const fs::path& matches_dir, int num_threads,
                                const fs::path& colmap_database) {
  MatchStageSummary summary;
  const sfm_pruning::PairSet pairs = SelectPairs(settings, scene);
  summary.num_pairs = pairs.size();

  sfm_pruning::DescriptorMatchingOptions options;
  options.matcher = settings.matcher == "BRUTE_FORCE" ? sfm_pruning::DescriptorMatcher::kBruteForce
                    : settings.matcher == "FLANN"     ? sfm_pruning::DescriptorMatcher::kFlann
                                                      : sfm_pruning::DescriptorMatcher::kAuto;
  options.max_ratio = settings.ratio;
  options.mutual_check = !settings.no_mutual;
  options.flann_checks = settings.flann_checks;
  options.seed = settings.seed;
  options.num_threads = num_threads;
  const sfm_pruning::PairwiseMatches putative =
      sfm_pruning::MatchDescriptors(*features, pairs, options, ProgressOnStderr());
  summary.num_putative_pairs = putative.size();
  for (const auto& [pair, matches] : putative) summary.num_putative_matches += matches.size();
  fs::create_directories(matches_dir);
  sfm_pruning::WriteOpenMvgMatches(matches_dir / "matches.putative.bin", putative);

  // The verification of the GLOBAL engine (view_graph_builder.hpp), every pair kept: the
  // selection of the largest component is the engine's job.
  sfm_pruning::ViewGraphBuildOptions verify;
  verify.seed = settings.seed;
  verify.two_view.relative_pose.max_angular_error_deg = settings.max_epipolar_error_deg;
  verify.two_view.relative_pose.precision_check_ratio = settings.verification_precision_ratio;
  verify.num_threads = num_threads;
  verify.keep_largest_component = false;
  sfm_pruning::ViewGraphBuildReport report;
  const sfm_pruning::ViewGraph graph =
      sfm_pruning::BuildViewGraphFromMatches(verify, scene, *features, putative, &report, ProgressOnStderr());
  sfm_pruning::PairwiseMatches verified;
  for (const auto& [pair, edge] : graph.Edges()) {
    if (!edge.is_valid) continue;
    verified[pair] = edge.matches;
    summary.num_verified_inliers += edge.matches.size();
  }
  summary.num_verified_pairs = verified.size();
  sfm_pruning::WriteOpenMvgMatches(matches_dir / "matches.e.bin", verified);
  Info("matched " + std::to_string(summary.num_pairs) + " pairs: " + std::to_string(summary.num_putative_pairs) +
       " with >= " + std::to_string(options.min_num_matches) + " matches (" + std::to_string(summary.num_putative_matches) + " matches), " +
       std::to_string(summary.num_verified_pairs) + " verified (" + std::to_string(summary.num_verified_inliers) +
       " inliers); wrote matches.putative.bin, matches.e.bin");
  if (!colmap_database.empty()) {
    WriteMatchDatabase(scene, graph, putative, matches_dir, features, colmap_database);
    Info("wrote " + colmap_database.string() + " (COLMAP database of the same features and matches)");
  }
  return summary;
}

}  // namespace prunesfm
