#include "sfm_pruning/pipeline/reconstruction.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string PairName(const ViewPair& pair) {
  return std::to_string(pair.first) + "-" + std::to_string(pair.second);
}

void Log(const ReconstructionLog& log, const std::string& line) {
  if (log) log(line);
}

// A graph already verified with the intrinsics of the scene it is used with.
struct VerifiedViewGraph {
  ViewGraph graph;
  ViewGraphBuildReport build;
};

// One verification and one engine run.
struct Solution {
  ViewGraphBuildReport build;
  double verification_seconds = 0.0;
  GlobalEngineReport report;
  SfmData model;
  std::optional<ViewGraphPruningReport> pruning;
  RunViewGraph view_graph;
};

// The positioning of a solve (GLOBAL's, GLOBAL_PRUNED's final one).
void SetPositioning(const ReconstructionOptions& options, GlobalEngineOptions* engine) {
  engine->positioning = options.positioning;
  engine->positioning_tracks = options.positioning_tracks;
  engine->link_depth_votes.enabled = options.link_depth_votes;
  engine->positioning_random_starts = options.positioning_random_starts;
  engine->positioning_start_screening_iterations = options.positioning_start_screening_iterations;
}

// The GLOBAL engine's options under `options` (seed, threads, positioning).
GlobalEngineOptions EngineOptions(const ReconstructionOptions& options) {
  GlobalEngineOptions engine;
  engine.seed = options.seed;
  engine.num_threads = options.solver_threads;
  SetPositioning(options, &engine);
  return engine;
}

// kFocalSearch: the GLOBAL engine with WithFocalSearchSchedule, whatever the engine option says
// (its model serves only its focal, which the full solve refines again; the pruning would double
// its cost).
enum class Schedule { kFull, kFocalSearch };

// Verification with the intrinsics of `scene` (unless `verified` is given), then the engine.
Solution Solve(const ReconstructionOptions& options, const ReconstructionInput& input, const SfmData& scene,
               const std::set<IndexT>& refined, Schedule schedule, const VerifiedViewGraph* verified,
               const ProgressCallback& progress, const ReconstructionLog& log) {
  Solution solution;
  const auto verify_start = std::chrono::steady_clock::now();
  std::optional<ViewGraph> verified_here;
  if (verified == nullptr) {
    verified_here = BuildVerifiedViewGraph(options, input, &solution.build, &scene, progress);
  } else {
    solution.build = verified->build;
  }
  const ViewGraph& graph = verified != nullptr ? verified->graph : *verified_here;
  solution.verification_seconds = SecondsSince(verify_start);
  Log(log, "view graph: " + std::to_string(graph.NumValidEdges()) + " edges of " +
               std::to_string(solution.build.num_pairs) + " pairs, " + std::to_string(graph.NumNodes()) +
               " views");
  const BundleAdjustmentOptions bundle = RefiningBundleOptions(options.intrinsics, input, refined);
  const bool pruned = options.engine == ReconstructionEngine::kGlobalPruned && schedule == Schedule::kFull;
  if (pruned) {
    PrunedGlobalEngineOptions engine_options = PrunedEngineOptions(options);
    engine_options.engine.bundle = bundle;  // the final solve; the per-community solves hold the intrinsics
    engine_options.engine.distortion_needs_evidence = options.intrinsics.distortion_needs_evidence;
    PrunedGlobalEngineReport report;
    RunPrunedGlobalEngine(engine_options, graph, scene, input.features, &solution.model, &report, progress);
    solution.report = std::move(report.engine);
    solution.pruning = std::move(report.pruning);
  } else {
    GlobalEngineOptions engine_options = EngineOptions(options);
    engine_options.bundle = bundle;
    engine_options.distortion_needs_evidence = options.intrinsics.distortion_needs_evidence;
    if (schedule == Schedule::kFocalSearch) engine_options = WithFocalSearchSchedule(engine_options);
    RunGlobalEngine(engine_options, graph, scene, input.features, &solution.model, &solution.report,
                    progress);
  }
  solution.view_graph = MakeRunViewGraph(ReconstructionEngineName(options.engine), graph, scene,
                                         solution.pruning ? &*solution.pruning : nullptr);
  return solution;
}

// The cameras whose focal the calibration could not determine: bundle adjustment would move their
// focal far from the guess, and the relative poses verified with the guess would have to be
// estimated and solved again. A quick solve finds the focal first, written into `scene`, so that
// the full solve runs with it. Returns the search's wall time (0 when no camera needed one).
double SearchUncalibratedFocals(const ReconstructionOptions& options, const ReconstructionInput& input,
                                const FocalCalibrationReport& calibration, const std::set<IndexT>& refined,
                                SfmData* scene, const VerifiedViewGraph* prior_graph,
                                const ProgressCallback& progress, const ReconstructionLog& log) {
  const std::set<IndexT> uncalibrated = UncalibratedFocals(calibration, *scene);
  if (uncalibrated.empty()) return 0.0;
  const auto start = std::chrono::steady_clock::now();
  const Solution search =
      Solve(options, input, *scene, refined, Schedule::kFocalSearch, prior_graph, progress, log);
  if (search.report.success) {
    const std::string searched = MovedFocals(*scene, search.model, uncalibrated, 0.0);
    Log(log, "focal search: " + (searched.empty() ? std::string("the guessed focal stays") : searched));
    for (const IndexT id : uncalibrated)
      scene->intrinsics.at(id).SetFocalLength(search.model.intrinsics.at(id).FocalLength());
  } else {
    Log(log, "focal search failed (" + search.report.message + "): solving from the guessed focal");
  }
  return SecondsSince(start);
}

}  // namespace

std::string ReconstructionEngineName(ReconstructionEngine engine) {
  return engine == ReconstructionEngine::kGlobalPruned ? "GLOBAL_PRUNED" : "GLOBAL";
}

ReconstructionEngine ParseReconstructionEngine(const std::string& name) {
  if (name == "GLOBAL") return ReconstructionEngine::kGlobal;
  if (name == "GLOBAL_PRUNED") return ReconstructionEngine::kGlobalPruned;
  throw std::invalid_argument("unknown engine '" + name + "' (GLOBAL or GLOBAL_PRUNED)");
}

int ReconstructionOptions::ResolvedThreads() const { return ResolveThreadCount(num_threads); }

void ReconstructionOptions::Check() const {
  if (num_threads < 0) throw std::invalid_argument("ReconstructionOptions::num_threads must be >= 0 (0: every core)");
  if (solver_threads < 1) throw std::invalid_argument("ReconstructionOptions::solver_threads must be at least 1");
  if (positioning_random_starts < 1 || positioning_random_starts > 1000) {
    throw std::invalid_argument("ReconstructionOptions::positioning_random_starts must be in [1, 1000]");
  }
  if (positioning_start_screening_iterations < 0) {
    throw std::invalid_argument("ReconstructionOptions::positioning_start_screening_iterations must be >= 0");
  }
  if (!(max_epipolar_error_deg > 0.0 && max_epipolar_error_deg <= 90.0)) {
    throw std::invalid_argument("ReconstructionOptions::max_epipolar_error_deg must be in (0, 90]");
  }
  if (!(verification_precision_ratio >= 0.0 && verification_precision_ratio <= 0.99)) {
    throw std::invalid_argument("ReconstructionOptions::verification_precision_ratio must be in [0, 0.99]");
  }
  if (positioning == PositioningMethod::kTranslationAveraging &&
      positioning_tracks == PositioningTracks::kMatchStars) {
    throw std::invalid_argument(
        "ReconstructionOptions::positioning_tracks MATCH_STARS needs GLOMAP positioning (translation "
        "averaging has "
        "no positioning tracks)");
  }
  pruning.Check();
  intrinsics.Check();
}

ViewGraphBuildOptions VerificationOptions(const ReconstructionOptions& options) {
  ViewGraphBuildOptions verification;
  verification.seed = options.seed;
  verification.num_threads = options.ResolvedThreads();
  verification.two_view.relative_pose.max_angular_error_deg = options.max_epipolar_error_deg;
  verification.two_view.relative_pose.precision_check_ratio = options.verification_precision_ratio;
  return verification;
}

PrunedGlobalEngineOptions PrunedEngineOptions(const ReconstructionOptions& options) {
  PrunedGlobalEngineOptions pruned;
  pruned.pruning = options.pruning;
  // The random starts apply to the solve of the pruned graph only (the audit's, whose poses the
  // final adjustment keeps): the per-community solves are many and small, and the consistency
  // tests already judge each of them.
  SetPositioning(options, &pruned.engine);
  pruned.pruning.partition.engine.positioning = options.positioning;
  pruned.pruning.partition.engine.positioning_tracks = options.positioning_tracks;
  pruned.pruning.partition.engine.link_depth_votes.enabled = options.link_depth_votes;
  pruned.SetSeedAndThreads(options.seed, options.ResolvedThreads(), options.solver_threads);
  return pruned;
}

ViewGraph BuildVerifiedViewGraph(const ReconstructionOptions& options, const ReconstructionInput& input,
                                 ViewGraphBuildReport* report, const SfmData* scene,
                                 const ProgressCallback& progress) {
  const SfmData& views_and_intrinsics = scene != nullptr ? *scene : input.scene;
  if (input.verified.empty() && input.putative.empty()) {
    throw Error(input.source +
                ": no two images match (no two-view geometries and no matches): nothing to reconstruct");
  }
  ViewGraphBuildReport local;
  ViewGraphBuildReport& build = report != nullptr ? *report : local;
  const ViewGraphBuildOptions verification = VerificationOptions(options);
  ViewGraph graph;
  try {
    graph = input.verified.empty()
                ? BuildViewGraphFromMatches(verification, views_and_intrinsics, input.features,
                                            input.putative, &build, progress)
                : BuildViewGraphFromVerifiedPairs(verification, views_and_intrinsics, input.features,
                                                  input.verified, &build, progress);
  } catch (const Error& e) {
    throw Error(input.source + ": " + e.what());
  }
  if (graph.NumValidEdges() == 0) {
    std::string message = input.source + ": no two images match: the verification rejected all " +
                          std::to_string(build.num_pairs) + " matched pairs";
    if (!build.rejected_pairs.empty()) {
      message += " (pair " + PairName(build.rejected_pairs.front().pair) + ": " +
                 build.rejected_pairs.front().reason + ")";
    }
    throw Error(message);
  }
  return graph;
}

namespace {

// CalibrateFocals, also handing over the graph verified for it (when the input had to be
// verified): it stays valid for the solve if the calibration changes no focal.
FocalCalibrationReport CalibrateFocalsKeepingGraph(const ReconstructionOptions& options,
                                                   const ReconstructionInput& input,
                                                   const std::set<IndexT>& calibrated, SfmData* scene,
                                                   const ProgressCallback& progress,
                                                   std::optional<VerifiedViewGraph>* prior_graph) {
  const FocalCalibrationOptions calibration;
  if (!input.verified.empty()) {
    return CalibrateFocalLengths(calibration, calibrated, InliersOfPairs(input.verified), input.features,
                                 scene);
  }
  VerifiedViewGraph prior;
  prior.graph = BuildVerifiedViewGraph(options, input, &prior.build, scene, progress);
  const FocalCalibrationReport report =
      CalibrateFocalLengths(calibration, calibrated, InliersOfEdges(prior.graph), input.features, scene);
  if (prior_graph != nullptr) *prior_graph = std::move(prior);
  return report;
}

}  // namespace

FocalCalibrationReport CalibrateFocals(const ReconstructionOptions& options, const ReconstructionInput& input,
                                       const std::set<IndexT>& calibrated, SfmData* scene,
                                       const ProgressCallback& progress) {
  return CalibrateFocalsKeepingGraph(options, input, calibrated, scene, progress, nullptr);
}

ReconstructionResult Reconstruct(const ReconstructionOptions& options, const ReconstructionInput& input,
                                 const ProgressCallback& progress, const ReconstructionLog& log) {
  options.Check();
  ReconstructionResult result;
  result.refined_intrinsics = RefinedIntrinsics(options.intrinsics, input);
  const std::set<IndexT>& refined = result.refined_intrinsics;
  SfmData scene = input.scene;

  // 1. Calibration of the guessed focals.
  std::optional<VerifiedViewGraph> prior_graph;
  const auto calibration_start = std::chrono::steady_clock::now();
  const std::set<IndexT> focals_to_calibrate = FocalsToCalibrate(options.intrinsics, input);
  if (options.intrinsics.focal && !focals_to_calibrate.empty()) {
    result.calibration =
        CalibrateFocalsKeepingGraph(options, input, focals_to_calibrate, &scene, progress, &prior_graph);
    for (const std::string& line : CalibrationLines(*result.calibration)) Log(log, line);
    // An accepted focal changes the intrinsics the prior graph was verified with.
    for (const IntrinsicFocalCalibration& entry : result.calibration->intrinsics) {
      if (entry.accepted) prior_graph.reset();
    }
    result.calibration_seconds = SecondsSince(calibration_start);
    // 2. The focal search for the cameras the calibration could not determine.
    result.focal_search_seconds =
        SearchUncalibratedFocals(options, input, *result.calibration, refined, &scene,
                                 prior_graph ? &*prior_graph : nullptr, progress, log);
  }

  // 3, 4. Verification and engine.
  Solution solution = Solve(options, input, scene, refined, Schedule::kFull, nullptr, progress, log);
  // 5. Once more when bundle adjustment found the focal the pairs were verified with wrong.
  const std::string moved = MovedFocals(scene, solution.model, refined, options.intrinsics.refocus_threshold);
  if (solution.report.success && options.intrinsics.focal && !moved.empty()) {
    Log(log, "bundle adjustment moved the focal (" + moved +
                 "): verifying and solving again with the refined intrinsics");
    result.first_pass_seconds = solution.verification_seconds + solution.report.total_seconds;
    for (const IndexT id : refined) scene.intrinsics.at(id) = solution.model.intrinsics.at(id);
    solution = Solve(options, input, scene, refined, Schedule::kFull, nullptr, progress, log);
  }
  result.success = solution.report.success;
  result.message = solution.report.message;
  // The filtering rounds can drop every camera of a model that never fitted: an empty model is a
  // failure, not a result.
  if (result.success && solution.model.poses.size() < 2) {
    result.success = false;
    result.message = std::to_string(solution.model.poses.size()) + " of " +
                     std::to_string(solution.model.views.size()) + " views registered after the final adjustment";
  }
  result.model = std::move(solution.model);
  result.build = std::move(solution.build);
  result.engine = std::move(solution.report);
  result.pruning = std::move(solution.pruning);
  result.view_graph = std::move(solution.view_graph);
  result.verification_seconds = solution.verification_seconds;
  return result;
}

}  // namespace sfm_pruning
