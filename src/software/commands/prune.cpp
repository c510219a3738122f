// prunesfm prune: the view-graph pruning of GLOBAL_PRUNED as a filter for other tools. It builds
// the verified view graph of the input, prunes it exactly as GLOBAL_PRUNED does (PruneAndAudit:
// the partition and votes, the landmark check's match removals, the missing-correspondence check
// and, when enabled, the model audit, each against a solve of the pruned graph), and writes the
// input again without what the pruning removed, so COLMAP's or GLOMAP's mapper (or OpenMVG's)
// runs on a cleaned graph:
//   --database DB --output DB2: a copy of the COLMAP database whose two_view_geometries rows of
//       the removed pairs are deleted and whose kept rows lose the inliers the landmark check
//       dropped (everything else byte for byte, the matches table too: the mappers build their
//       correspondence graph from two_view_geometries only);
//   --sfm_data S --matches_dir D --output M: the OpenMVG match file without the removed pairs
//       and the dropped matches.
// Cameras with a guessed focal are calibrated on the view graph first (as `run` does by default).
// Only the edges the pruning removes are dropped; pairs our verification rejects are kept (the
// input tool accepted them and may judge them differently). Plus the pruning report (JSON).
#include <CLI/CLI.hpp>

#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/openmvg_matches.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_support.hpp"
#include "software/commands.hpp"
#include "software/commands/front_end_stages.hpp"
#include "software/commands/pruning_options.hpp"
#include "software/commands/pruning_report_json.hpp"
#include "software/commands/reconstruction_pipeline.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;
using sfm_pruning::Error;
using sfm_pruning::ViewPair;

struct PruneArguments {
  EngineSettings settings;
  std::string database;
  std::string sfm_data;
  std::string matches_dir;
  std::string match_file;
  std::string output;
  std::string report;
};

class StageClock {
 public:
  double Lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// The matches of `matches` that `excluded` does not hold, in their order.
std::vector<sfm_pruning::FeatureMatch> MatchesNotIn(const std::vector<sfm_pruning::FeatureMatch>& matches,
                                                    const std::vector<sfm_pruning::FeatureMatch>& excluded) {
  std::set<std::pair<sfm_pruning::IndexT, sfm_pruning::IndexT>> out;
  for (const sfm_pruning::FeatureMatch& match : excluded) out.emplace(match.i, match.j);
  std::vector<sfm_pruning::FeatureMatch> kept;
  for (const sfm_pruning::FeatureMatch& match : matches) {
    if (out.count({match.i, match.j}) == 0) kept.push_back(match);
  }
  return kept;
}

// What the pruning changed in the verified graph: the edges it removed, and the matches the
// landmark check took out of the edges it kept.
struct PrunedPairs {
  std::set<ViewPair> removed;
  std::map<ViewPair, std::vector<sfm_pruning::FeatureMatch>> dropped_matches;
};

PrunedPairs ChangesOfPruning(const sfm_pruning::ViewGraph& verified, const sfm_pruning::ViewGraph& pruned) {
  PrunedPairs changes;
  for (const auto& [pair, edge] : verified.Edges()) {
    if (!edge.is_valid) continue;
    const sfm_pruning::ViewGraphEdge* after = pruned.FindEdge(pair.first, pair.second);
    if (after == nullptr || !after->is_valid) {
      changes.removed.insert(pair);
      continue;
    }
    std::vector<sfm_pruning::FeatureMatch> dropped = MatchesNotIn(edge.matches, after->matches);
    if (!dropped.empty()) changes.dropped_matches.emplace(pair, std::move(dropped));
  }
  return changes;
}

size_t NumMatches(const std::map<ViewPair, std::vector<sfm_pruning::FeatureMatch>>& matches) {
  size_t count = 0;
  for (const auto& [pair, list] : matches) count += list.size();
  return count;
}

// The putative matches of the kept pairs, without the dropped ones.
sfm_pruning::PairwiseMatches KeptMatches(const sfm_pruning::PairwiseMatches& putative, const std::set<ViewPair>& keep,
                                         const std::map<ViewPair, std::vector<sfm_pruning::FeatureMatch>>& dropped) {
  sfm_pruning::PairwiseMatches kept;
  for (const auto& [pair, matches] : putative) {
    if (keep.count(pair) == 0) continue;
    const auto drop = dropped.find(pair);
    if (drop == dropped.end()) {
      kept.emplace(pair, matches);
      continue;
    }
    kept.emplace(pair, MatchesNotIn(matches, drop->second));
  }
  return kept;
}

// Every pair the input holds (verified or only matched), minus the removed ones.
std::set<ViewPair> PairsToKeep(const sfm_pruning::ReconstructionInput& input,
                                const std::set<ViewPair>& removed) {
  std::set<ViewPair> keep;
  for (const auto& [pair, geometry] : input.verified) {
    if (removed.count(pair) == 0) keep.insert(pair);
  }
  for (const auto& [pair, matches] : input.putative) {
    if (removed.count(pair) == 0) keep.insert(pair);
  }
  return keep;
}

// The pruning report's path (--report, or beside --output), after checking that the arguments
// name one input and that neither output would replace it. Before any work.
fs::path CheckedReportPath(const PruneArguments& args) {
  const bool colmap = !args.database.empty();
  if (colmap == !args.sfm_data.empty()) {
    throw Error("prune: give either --database, or --sfm_data with --matches_dir");
  }
  if (!colmap && args.matches_dir.empty()) throw Error("prune: --sfm_data needs --matches_dir");
  const fs::path output = args.output;
  const fs::path report_path =
      args.report.empty() ? fs::path(output).replace_extension(".pruning_report.json") : fs::path(args.report);
  if (report_path == output) throw Error(output.string() + ": --report must differ from --output");
  std::vector<fs::path> inputs = {args.database, args.sfm_data, args.matches_dir};
  if (!colmap) inputs.push_back(sfm_pruning::FindOpenMvgMatchesFile(args.matches_dir, args.match_file));
  RefuseOutputOverInput(output, inputs);
  RefuseOutputOverInput(report_path, inputs);
  return report_path;
}

// The input again without what the pruning changed (the header says how per format); returns
// the number of pairs the input held.
size_t WriteFilteredInput(const PruneArguments& args, const sfm_pruning::ReconstructionInput& input,
                          bool verified_here, const sfm_pruning::ViewGraph& pruned, const PrunedPairs& changes) {
  const std::set<ViewPair> keep = PairsToKeep(input, changes.removed);
  if (verified_here) {
    sfm_pruning::CopyColmapDatabaseWithGeometries(args.database, args.output, ColmapGeometriesOf(pruned));
    return input.putative.size();
  }
  if (!args.database.empty()) {
    sfm_pruning::CopyColmapDatabaseKeepingPairs(args.database, args.output, keep, changes.dropped_matches);
    return input.verified.size();
  }
  sfm_pruning::WriteOpenMvgMatches(args.output, KeptMatches(input.putative, keep, changes.dropped_matches));
  return input.putative.size();
}

// The report's "filter" section: what went in and out, the settings, the time of each stage.
nlohmann::json FilterJson(const PruneArguments& args, const sfm_pruning::ReconstructionInput& input,
                          bool verified_here, size_t num_pairs, const PrunedPairs& changes,
                          const sfm_pruning::ViewGraphBuildReport& build, const nlohmann::json& seconds) {
  const bool colmap = !args.database.empty();
  return {{"input", colmap ? args.database : input.source},
          {"output", args.output},
          {"format", colmap ? "colmap_database" : "openmvg_matches"},
          {"verified_here", verified_here},
          {"input_pairs", num_pairs},
          {"removed_pairs", changes.removed.size()},
          {"pairs_with_matches_dropped", changes.dropped_matches.size()},
          {"matches_dropped", NumMatches(changes.dropped_matches)},
          {"rejected_by_verification_kept", build.rejected_pairs.size()},
          {"seed", args.settings.seed},
          {"num_threads", sfm_pruning::ResolveThreadCount(args.settings.num_threads)},
          {"solver_threads", args.settings.solver_threads},
          {"seconds", seconds}};
}

void RunPrune(const PruneArguments& args) {
  const bool colmap = !args.database.empty();
  const fs::path report_path = CheckedReportPath(args);

  StageClock clock;
  const sfm_pruning::ReconstructionInput input =
      colmap ? sfm_pruning::ReadColmapInput(args.database)
             : sfm_pruning::ReadOpenMvgInput(args.sfm_data, args.matches_dir, args.match_file, ProgressOnStderr());
  // A database of matches only (another tool matched, nothing verified): our verification's pairs,
  // minus the pruned ones, become its two-view geometries.
  const bool verified_here = colmap && input.verified.empty();
  const double read_seconds = clock.Lap();

  // Cameras whose focal is a guess (COLMAP's prior_focal_length = 0) are calibrated on the view
  // graph first, as `run` does: relative poses verified with a wrong focal mislead the pruning.
  const sfm_pruning::ReconstructionOptions options = ToReconstructionOptions(args.settings);
  sfm_pruning::SfmData scene = input.scene;
  const std::set<sfm_pruning::IndexT> to_calibrate = sfm_pruning::FocalsToCalibrate(options.intrinsics, input);
  nlohmann::json calibration;
  if (!to_calibrate.empty()) {
    const sfm_pruning::FocalCalibrationReport report =
        sfm_pruning::CalibrateFocals(options, input, to_calibrate, &scene, ProgressOnStderr());
    for (const std::string& line : sfm_pruning::CalibrationLines(report)) Info(line);
    calibration = CalibrationJson(report);
  }
  const double calibration_seconds = clock.Lap();

  sfm_pruning::ViewGraphBuildReport build;
  sfm_pruning::ViewGraph graph = sfm_pruning::BuildVerifiedViewGraph(options, input, &build, &scene, ProgressOnStderr());
  const double verify_seconds = clock.Lap();
  Info("view graph: " + std::to_string(graph.NumValidEdges()) + " edges of " + std::to_string(build.num_pairs) +
       " pairs, " + std::to_string(graph.NumNodes()) + " views");

  // GLOBAL_PRUNED's pruning, all of it: the view-graph pruning with its landmark check, the audit
  // and the missing-correspondence check when they are on.
  sfm_pruning::ViewGraph pruned;
  sfm_pruning::SfmData audit_model;
  sfm_pruning::PrunedGlobalEngineReport engine_report;
  sfm_pruning::PrunedGlobalEngineOptions engine_options = sfm_pruning::PrunedEngineOptions(options);
  // The audit's solve adjusts the intrinsics as GLOBAL_PRUNED's does.
  engine_options.engine.bundle = sfm_pruning::RefiningBundleOptions(
      options.intrinsics, input, sfm_pruning::RefinedIntrinsics(options.intrinsics, input));
  const sfm_pruning::PrunedGlobalEngineStep step = PruneAndAudit(engine_options, graph, scene, input.features, &pruned,
                                                                 &audit_model, &engine_report, ProgressOnStderr());
  if (step == sfm_pruning::PrunedGlobalEngineStep::kAuditModelFailed) {
    Info("model audit skipped: the solve of the pruned graph failed (" + engine_report.engine.message + ")");
  }
  const double prune_seconds = clock.Lap();
  Info("pruning: " + PruningSummary(engine_report.pruning));

  const PrunedPairs changes = ChangesOfPruning(graph, pruned);
  const size_t num_pairs = WriteFilteredInput(args, input, verified_here, pruned, changes);
  const double write_seconds = clock.Lap();

  nlohmann::json report = PruningReportJson(engine_report.pruning);
  report["filter"] = FilterJson(args, input, verified_here, num_pairs, changes, build,
                                {{"read input", read_seconds},
                                 {"focal calibration", calibration_seconds},
                                 {"verification", verify_seconds},
                                 {"pruning", prune_seconds},
                                 {"write output", write_seconds}});
  if (!calibration.is_null()) report["filter"]["focal_calibration"] = std::move(calibration);
  WriteJsonAtomically(report, report_path);
  Info("wrote " + args.output + " (" + std::to_string(num_pairs - changes.removed.size()) + " of " +
       std::to_string(num_pairs) + " pairs kept) and " + report_path.string());
}

}  // namespace

void AddPruneCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "prune",
      "Remove spurious two-view geometries (GLOBAL_PRUNED's view-graph pruning, model audit included)\n"
      "for another mapper. COLMAP: --database DB --output DB2 writes a copy of DB without the removed\n"
      "pairs' two_view_geometries and without the inliers the pruning's landmark check dropped (run\n"
      "'colmap mapper' or 'glomap mapper' on DB2). OpenMVG: --sfm_data + --matches_dir --output\n"
      "MATCHES(.bin|.txt) writes the match file without them. Also writes the pruning report (JSON;\n"
      "default: OUTPUT with the extension .pruning_report.json).");
  auto args = std::make_shared<PruneArguments>();
  cmd->add_option("--database_path,--database", args->database, "COLMAP database.db with two-view geometries");
  cmd->add_option("--sfm_data", args->sfm_data, "OpenMVG sfm_data.json/.bin with views and intrinsics");
  cmd->add_option("--matches_dir", args->matches_dir, "Folder of the .feat files and the match file");
  cmd->add_option("--match_file", args->match_file, "Match file (default: matches.e/f/putative .bin/.txt)");
  cmd->add_option("--output,--output_path,-o", args->output,
                  "Pruned database, or pruned OpenMVG match file")->required();
  cmd->add_option("--report", args->report, "Pruning report JSON (default: OUTPUT.pruning_report.json)");
  AddSolverOptions(cmd, &args->settings);
  AddPruningOptions(cmd, &args->settings.pruning, false);
  cmd->callback([args]() { RunPrune(*args); });
}

}  // namespace prunesfm
