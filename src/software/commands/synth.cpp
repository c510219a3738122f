// prunesfm synth: generates a synthetic scene at the level of features (docs/synthetic_scenes.md)
// and writes it in the project's layout, so every later step runs on it as on real images:
//   DIR/sfm_data.json                     views + intrinsics (what an image listing writes)
//   DIR/matches/<view>.feat/.desc         keypoints and SIFT-like descriptors
//   DIR/matches/image_describer.json
//   DIR/matches/matches.putative.bin      putative matches
//   DIR/database.db                       the same features and matches for COLMAP 3.8
//   DIR/ground_truth/sfm_data.json        the full ground-truth model (poses, landmarks)
//   DIR/ground_truth/gt_cameras.txt       the datasets' ground-truth camera list
//   DIR/ground_truth/synthetic_scene.json options, twins and true/false matches per pair
//   DIR/ground_truth/feature_landmarks.txt per feature: the landmark it observes and that
//                                         landmark's appearance, so any match can be labelled
// The directory is written atomically: it appears complete or not at all.
#include <CLI/CLI.hpp>

#include <memory>
#include <nlohmann/json.hpp>

#include "sfm_pruning/io/ground_truth_cameras.hpp"
#include "sfm_pruning/eval/synthetic_families.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"

namespace prunesfm {
namespace {

namespace fs = std::filesystem;
using sfm_pruning::SyntheticScene;

// The options actually used and what the matcher did, for benchmarks and tests to read.
nlohmann::json SceneSummary(const SyntheticScene& scene) {
  const sfm_pruning::SyntheticSceneOptions& o = scene.options;
  nlohmann::json json;
  json["scene"] = scene.name;
  json["options"] = {{"seed", o.seed},
                     {"num_views", o.num_views},
                     {"image_width", o.image_width},
                     {"image_height", o.image_height},
                     {"focal_px", o.focal_px},
                     {"noise_px", o.noise_px},
                     {"descriptor_noise", o.descriptor_noise},
                     {"dropout", o.dropout},
                     {"clutter_ratio", o.clutter_ratio},
                     {"max_incidence_deg", o.max_incidence_deg},
                     {"max_distance_m", o.max_distance_m},
                     {"point_density_scale", o.point_density_scale},
                     {"ratio_test", o.ratio_test},
                     {"mutual_check", o.mutual_check},
                     {"outlier_ratio", o.outlier_ratio},
                     {"min_matches", o.min_matches},
                     {"sequential_window", o.sequential_window},
                     {"loop_candidates", o.loop_candidates},
                     {"loop_min_gap", o.loop_min_gap},
                     {"laps", o.laps},
                     {"twin_fraction", o.twin_fraction},
                     {"loop_straight_per_radius", o.loop_straight_per_radius},
                     {"street_module_width_m", o.street_module_width_m}};
  if (!scene.description.family.empty()) {
    json["family"] = {{"name", scene.description.family},
                      {"values", scene.description.values},
                      {"labels", scene.description.labels}};
  }
  json["num_landmarks"] = scene.ground_truth.structure.size();
  json["num_twin_landmarks"] = scene.twin_landmarks.size();
  size_t num_true = 0, num_twin = 0, num_random = 0;
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [pair, stats] : scene.pair_stats) {
    pairs.push_back({{"i", pair.first},
                     {"j", pair.second},
                     {"true", stats.num_true},
                     {"twin", stats.num_twin},
                     {"random", stats.num_random},
                     {"injected", stats.num_injected}});
    num_true += stats.num_true;
    num_twin += stats.num_twin;
    num_random += stats.num_random;
  }
  json["matches"] = {{"true", num_true}, {"twin", num_twin}, {"random", num_random}};
  json["pairs"] = std::move(pairs);
  return json;
}

// One line per view: "view_id num_features" then, per feature in id order, "landmark appearance"
// (-1 -1 for clutter). Two features of one landmark make a true match, of two landmarks with one
// appearance a twin match (copies of one texture), anything else a random one: what
// synthetic_scene.json counts per pair, here for every match (benchmarks delete the twins).
void WriteFeatureLandmarks(const SyntheticScene& scene, const fs::path& path) {
  sfm_pruning::WriteFileAtomically(path, false, [&](std::ostream& out) {
    out << "# prunesfm synth: per view, view_id num_features, then landmark_id appearance_id of each feature "
           "(-1 -1: clutter)\n";
    for (const auto& [view_id, landmarks] : scene.feature_landmarks) {
      out << view_id << ' ' << landmarks.size();
      for (const sfm_pruning::IndexT landmark : landmarks) {
        if (landmark == sfm_pruning::kUndefinedIndex) {
          out << " -1 -1";
        } else {
          out << ' ' << landmark << ' ' << scene.landmark_appearance.at(landmark);
        }
      }
      out << '\n';
    }
  });
}

void WriteScene(const SyntheticScene& scene, const fs::path& dir) {
  const sfm_pruning::SfmData& truth = scene.ground_truth;
  sfm_pruning::SfmData listing;  // what an image listing knows: images and calibration
  listing.root_path = truth.root_path;
  listing.views = truth.views;
  listing.intrinsics = truth.intrinsics;
  sfm_pruning::WriteSfmData(listing, dir / "sfm_data.json",
                            sfm_pruning::SfmDataParts::kViews | sfm_pruning::SfmDataParts::kIntrinsics);

  const fs::path matches_dir = dir / "matches";
  fs::create_directories(matches_dir);
  sfm_pruning::WriteOpenMvgFeatures(listing, scene.features, matches_dir);
  sfm_pruning::WriteOpenMvgMatches(matches_dir / "matches.putative.bin", scene.putative_matches);

  sfm_pruning::ColmapDatabase database;
  database.sfm_data = listing;
  database.features = scene.features;
  database.putative = scene.putative_matches;
  sfm_pruning::WriteColmapDatabase(database, dir / "database.db");

  const fs::path truth_dir = dir / "ground_truth";
  fs::create_directories(truth_dir);
  sfm_pruning::WriteSfmData(truth, truth_dir / "sfm_data.json");
  sfm_pruning::WriteGroundTruthCameras(truth, truth_dir / "gt_cameras.txt");
  sfm_pruning::WriteFileAtomically(truth_dir / "synthetic_scene.json", false,
                                   [&](std::ostream& out) { out << SceneSummary(scene).dump(2) << '\n'; });
  WriteFeatureLandmarks(scene, truth_dir / "feature_landmarks.txt");
}

}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("synth", "Generate a synthetic scene (features, putative matches, ground truth)");
  auto options = std::make_shared<sfm_pruning::SyntheticSceneOptions>();
  auto output = std::make_shared<std::string>();
  auto overwrite = std::make_shared<bool>(false);
  sfm_pruning::SyntheticSceneOptions& o = *options;
  cmd->add_option("--scene", o.scene, "Scene: a fixed one, or a family_* whose seed draws the whole scene")->required()->check(CLI::IsMember(sfm_pruning::SyntheticSceneNames()));
  cmd->add_option("--output,--output_path,-o", *output, "Output directory (replaced atomically)")->required();
  AddOverwriteFlag(cmd, overwrite.get(), OverwriteMeans::kReplaceTheFolder);
  cmd->add_option("--seed", o.seed, "Random seed: same options and seed give identical files")->check(SeedValue());
  const sfm_pruning::SyntheticLimits& limits = sfm_pruning::kSyntheticLimits;
  cmd->add_option("--num_views", o.num_views, "Number of views (0: scene default)")
      ->check(RangeValue(0, limits.max_views));
  cmd->add_option("--image_width", o.image_width, "Image width in pixels (0: scene default)")
      ->check(RangeValue(0, limits.max_image_side_px));
  cmd->add_option("--image_height", o.image_height, "Image height in pixels (0: scene default)")
      ->check(RangeValue(0, limits.max_image_side_px));
  cmd->add_option("--focal_px", o.focal_px, "Focal length in pixels (0: 1.2 * max(width, height))")
      ->check(RangeValue(0, limits.max_focal_image_sides * limits.max_image_side_px));
  // The capture conditions a family scene draws from its seed (synthetic_families.hpp).
  std::vector<CLI::Option*> drawn_by_families = {
      cmd->add_option("--noise_px", o.noise_px, "Sigma of the Gaussian keypoint noise, pixels")
          ->check(RangeValue(0, limits.max_noise_px))
          ->capture_default_str(),
      cmd->add_option("--descriptor_noise", o.descriptor_noise, "Expected norm of the descriptor noise (unit histogram)")
          ->check(RangeValue(0, limits.max_descriptor_noise))
          ->capture_default_str(),
      cmd->add_option("--dropout", o.dropout, "Probability that a visible point is not detected")
          ->check(RangeValue(0, 0.99))
          ->capture_default_str(),
      cmd->add_option("--clutter_ratio", o.clutter_ratio, "Clutter keypoints per detected point")
          ->check(RangeValue(0, limits.max_clutter_ratio))
          ->capture_default_str(),
  };
  cmd->add_option("--max_incidence_deg", o.max_incidence_deg,
                  "Surfaces seen at a larger angle from their normal are not detected (>= 90: no facing test)")
      ->check(RangeValue(1e-3, 180))
      ->capture_default_str();
  cmd->add_option("--point_density_scale", o.point_density_scale, "Multiplies every surface's point density")
      ->check(RangeValue(1e-3, limits.max_point_density_scale))
      ->capture_default_str();
  cmd->add_option("--ratio_test", o.ratio_test, "Lowe's ratio on descriptor distances")
      ->check(RangeValue(0.01, 1))
      ->capture_default_str();
  drawn_by_families.push_back(
      cmd->add_option("--outlier_ratio", o.outlier_ratio,
                      "Fraction of random wrong matches per pair (injected on top of the matcher's own)")
          ->check(RangeValue(0, 0.99))
          ->capture_default_str());
  cmd->add_option("--min_matches", o.min_matches, "Pairs with fewer descriptor matches are dropped")
      ->check(NonNegativeValue())
      ->capture_default_str();
  cmd->add_option("--sequential_window", o.sequential_window, "sequential_large: pairs i, i+1 .. i+window (0: 5)")
      ->check(NonNegativeValue());
  cmd->add_option("--loop_candidates", o.loop_candidates, "sequential_large: retrieval candidates per view (0: 3)")
      ->check(NonNegativeValue());
  cmd->add_option("--loop_min_gap", o.loop_min_gap, "sequential_large: frames between loop candidates (0: 50)")
      ->check(NonNegativeValue());
  cmd->add_option("--laps", o.laps, "sequential_large: laps of the loop (0: 2)")->check(NonNegativeValue());
  cmd->add_option("--twin_fraction", o.twin_fraction, "sequential_large: fraction of repeated facades (default 0.25)")
      ->check(RangeValue(0, 0.9));
  cmd->add_option("--loop_straight_per_radius", o.loop_straight_per_radius,
                  "sequential_large: length of each straight over the end arcs' radius (0: 3)")
      ->check(RangeValue(0, 100));
  cmd->add_option("--street_module_width", o.street_module_width_m, "street: width of the repeated facade, metres")
      ->check(RangeValue(2, limits.max_street_module_width_m))
      ->capture_default_str();
  cmd->add_option("--num_threads", o.num_threads, "Threads for matching (the output does not depend on it)")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->callback([options, output, overwrite, drawn_by_families]() {
    sfm_pruning::CheckOutputFolder(*output, sfm_pruning::OutputFolderKind::kSyntheticScene, *overwrite);
    if (sfm_pruning::IsSyntheticFamily(options->scene)) {
      for (const CLI::Option* option : drawn_by_families) {
        if (option->count() > 0) {
          throw sfm_pruning::Error(option->get_name() + ": " + options->scene +
                                   " draws it from the seed; set it on a fixed scene instead");
        }
      }
    }
    const SyntheticScene scene = sfm_pruning::GenerateSyntheticScene(*options, ProgressOnStderr());
    sfm_pruning::WriteDirectoryAtomically(*output, sfm_pruning::OutputFolderKind::kSyntheticScene, [&](const fs::path& dir) { WriteScene(scene, dir); });
    size_t num_matches = 0;
    for (const auto& [pair, matches] : scene.putative_matches) num_matches += matches.size();
    Info("wrote " + scene.name + " (" + std::to_string(scene.ground_truth.views.size()) + " views, " +
         std::to_string(scene.putative_matches.size()) + " pairs, " + std::to_string(num_matches) +
         " putative matches) to " + *output);
  });
}

}  // namespace prunesfm
