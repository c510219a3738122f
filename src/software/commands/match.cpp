// prunesfm match: pair selection, descriptor matching and two-view verification (the GLOBAL
// engine's OpenGV 5-point RANSAC) -> OpenMVG's matches.putative.bin and matches.e.bin.
#include <CLI/CLI.hpp>

#include "sfm_pruning/io/openmvg_features.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/front_end_stages.hpp"

namespace prunesfm {
namespace {

struct MatchArguments {
  MatchSettings settings;
  std::string sfm_data;
  std::string matches_dir;
  std::string colmap_database;
  int num_threads = 0;
};

void RunMatch(const MatchArguments& args) {
  using sfm_pruning::SfmDataParts;
  const sfm_pruning::SfmData scene =
      sfm_pruning::ReadSfmData(args.sfm_data, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  RefuseOutputOverInput(args.colmap_database, {args.sfm_data, args.matches_dir});
  sfm_pruning::FeaturesPerView features =
      sfm_pruning::ReadOpenMvgFeatures(scene, args.matches_dir, true, ProgressOnStderr());
  RunMatchStage(args.settings, scene, &features, args.matches_dir, sfm_pruning::ResolveThreadCount(args.num_threads),
                args.colmap_database);
}

}  // namespace

void AddMatchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "match",
      "Match the features of image pairs (exhaustive, sequential window or a pair list; FLANN or brute force,\n"
      "ratio test, mutual check; parallel over pairs) and verify each pair (OpenGV 5-point RANSAC, as the GLOBAL\n"
      "engine). Writes <matches_dir>/matches.putative.bin and matches.e.bin (the verified inliers).");
  auto args = std::make_shared<MatchArguments>();
  cmd->add_option("--sfm_data,-s", args->sfm_data, "sfm_data.json from 'prunesfm init'")->required();
  cmd->add_option("--matches_dir,-m", args->matches_dir, "Folder of the .feat/.desc files; matches are written here")
      ->required();
  cmd->add_option("--num_threads", args->num_threads, "Threads (default: every core)")->check(PositiveValue());
  cmd->add_option("--colmap_database", args->colmap_database,
                  "Also write the features, matches and verified pairs as this COLMAP database.db (replaced "
                  "atomically), for colmap mapper, glomap mapper or prunesfm prune");
  AddMatchOptions(cmd, &args->settings, true);
  cmd->callback([args]() { RunMatch(*args); });
}

}  // namespace prunesfm
