#include "software/commands/reconstruction_pipeline.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <set>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/global/focal_calibration.hpp"
#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "sfm_pruning/report/run_view_graph.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands/front_end_stages.hpp"
#include "software/commands/pruning_options.hpp"
#include "software/commands/pruning_report_json.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;
using sfm_pruning::Error;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string PairName(const sfm_pruning::ViewPair& pair) {
  return std::to_string(pair.first) + "-" + std::to_string(pair.second);
}

}  // namespace

sfm_pruning::ViewGraph BuildVerifiedViewGraph(const EngineSettings& settings, const ReconstructionInput& input,
                                              sfm_pruning::ViewGraphBuildReport* report,
                                              const sfm_pruning::SfmData* scene) {
  const sfm_pruning::SfmData& views_and_intrinsics = scene != nullptr ? *scene : input.scene;
  if (input.verified.empty() && input.putative.empty()) {
    throw Error(input.source + ": no two images match (no two-view geometries and no matches): nothing to reconstruct");
  }
  sfm_pruning::ViewGraphBuildOptions options;
  options.seed = settings.seed;
  options.num_threads = settings.num_threads;
  options.two_view.relative_pose.max_angular_error_deg = settings.max_epipolar_error_deg;
  options.two_view.relative_pose.precision_check_ratio = settings.verification_precision_ratio;
  sfm_pruning::ViewGraph graph;
  try {
    graph = input.verified.empty()
                ? BuildViewGraphFromMatches(options, views_and_intrinsics, input.features, input.putative, report,
                                            ProgressOnStderr())
                : BuildViewGraphFromVerifiedPairs(options, views_and_intrinsics, input.features, input.verified,
                                                  report, ProgressOnStderr());
  } catch (const Error& e) {
    throw Error(input.source + ": " + e.what());
  }
  if (graph.NumValidEdges() == 0) {
    std::string message = input.source + ": no two images match: the verification rejected all " +
                          std::to_string(report->num_pairs) + " matched pairs";
    if (!report->rejected_pairs.empty()) {
      message += " (pair " + PairName(report->rejected_pairs.front().pair) + ": " +
                 report->rejected_pairs.front().reason + ")";
    }
    throw Error(message);
  }
  return graph;
}

// Verified pairs give their inliers directly; putative matches are verified once with the prior
// intrinsics first (the caller verifies them again with the calibrated ones).
sfm_pruning::FocalCalibrationReport CalibrateFocals(const EngineSettings& settings, const ReconstructionInput& input,
                                                    const std::set<sfm_pruning::IndexT>& refined,
                                                    sfm_pruning::SfmData* scene,
                                                    std::optional<VerifiedViewGraph>* prior_graph) {
  const sfm_pruning::FocalCalibrationOptions options;
  if (!input.verified.empty()) {
    return CalibrateFocalLengths(options, refined, sfm_pruning::InliersOfPairs(input.verified), input.features, scene);
  }
  VerifiedViewGraph prior;
  prior.graph = BuildVerifiedViewGraph(settings, input, &prior.build, scene);
  const sfm_pruning::FocalCalibrationReport report =
      CalibrateFocalLengths(options, refined, sfm_pruning::InliersOfEdges(prior.graph), input.features, scene);
  if (prior_graph != nullptr) *prior_graph = std::move(prior);
  return report;
}

namespace {

// Verification with the intrinsics of `scene`, then the engine; a failed engine is reported in
// report.success.
struct Solution {
  sfm_pruning::ViewGraphBuildReport build;
  double verify_seconds = 0.0;
  sfm_pruning::GlobalEngineReport report;
  sfm_pruning::SfmData model;
  std::optional<sfm_pruning::ViewGraphPruningReport> pruning;
  // The graph before pruning, with the cuts and subgraphs: what `prunesfm report` draws.
  sfm_pruning::RunViewGraph view_graph;
};

// kFocalSearch: the GLOBAL engine with WithFocalSearchSchedule, whatever --engine says (its model
// serves only its focal, which the full solve refines again; the pruning would double its cost).
enum class Schedule { kFull, kFocalSearch };

// `verified`: a graph already verified with the intrinsics of `scene` (none: verify here).
Solution Solve(const EngineSettings& settings, const ReconstructionInput& input, const sfm_pruning::SfmData& scene,
               const std::set<sfm_pruning::IndexT>& refined, Schedule schedule,
               const VerifiedViewGraph* verified = nullptr);

nlohmann::json TimingsJson(const EngineSettings& settings, const sfm_pruning::ViewGraphBuildReport& build,
                           const sfm_pruning::GlobalEngineReport& engine, const sfm_pruning::SfmData& model,
                           double read_seconds, double verify_seconds,
                           const sfm_pruning::ViewGraphPruningReport* pruning) {
  nlohmann::json stages = nlohmann::json::array();
  stages.push_back({{"stage", "read input"}, {"seconds", read_seconds}});
  stages.push_back({{"stage", "verification"}, {"seconds", verify_seconds}});
  if (pruning != nullptr) {
    for (const auto& timing : pruning->timings) stages.push_back({{"stage", timing.stage}, {"seconds", timing.seconds}});
  }
  for (const auto& timing : engine.timings) stages.push_back({{"stage", timing.stage}, {"seconds", timing.seconds}});
  nlohmann::json dropped = nlohmann::json::array();
  const auto add_dropped = [&](const sfm_pruning::DroppedView& view, const char* stage) {
    const auto it = model.views.find(view.view_id);
    dropped.push_back({{"view_id", view.view_id},
                       {"image", it == model.views.end() ? "" : it->second.RelativeImagePath()},
                       {"stage", stage},
                       {"reason", view.reason}});
  };
  for (const auto& view : build.dropped_views) add_dropped(view, "view graph");
  for (const auto& view : engine.dropped_views) add_dropped(view, "engine");
  nlohmann::json json;
  json["engine"] = settings.engine;
  json["positioning"] = settings.positioning;
  json["positioning_tracks"] = settings.positioning_tracks;
  json["positioning_random_starts"] = settings.positioning_random_starts;
  json["positioning_start_screening"] = settings.positioning_start_screening;
  json["max_epipolar_error_deg"] = settings.max_epipolar_error_deg;
  json["verification_precision_ratio"] = settings.verification_precision_ratio;
  if (settings.engine == "GLOBAL_PRUNED") {
    json["prune_model_audit"] = settings.pruning.audit.enabled;
    json["prune_audit_model"] = AuditModelName(settings.pruning.audit.model_schedule);
    json["prune_audit_refine_final"] = settings.pruning.audit.refine_final;
    json["prune_unverified_max_rotation_deg"] = settings.pruning.unverified_rotation.max_median_error_deg;
    json["prune_landmark_check_deg"] = settings.pruning.landmark_check.max_angle_deg;
    json["prune_ransac_enumerate_max"] = settings.pruning.alignment.max_enumerated_samples;
    json["prune_bisect_unsplittable"] = settings.pruning.partition.bisect_unsplittable;
    json["prune_baseline_ratio_factor"] = settings.pruning.partition.consistency.max_baseline_ratio_factor;
    json["prune_trust_prior_edges"] = settings.pruning.trust_prior_edges;
    json["prune_contested_ratio"] = settings.pruning.loops.contested_candidate_ratio;
  }
  json["seed"] = settings.seed;
  json["num_threads"] = settings.num_threads;
  json["stages"] = std::move(stages);
  json["engine_seconds"] = engine.total_seconds;
  json["counts"] = {{"views", model.views.size()},
                    {"pairs", build.num_pairs},
                    {"rejected_pairs", build.rejected_pairs.size()},
                    {"edges_in", engine.num_input_edges},
                    {"edges_after_rotation_filter", engine.num_rotation_edges},
                    {"edges_filtered_by_rotation", engine.num_filtered_edges},
                    {"tracks", engine.num_tracks},
                    {"registered_views", engine.num_registered_views},
                    {"landmarks", engine.num_landmarks},
                    {"observations", engine.num_observations},
                    {"final_rms_px", engine.final_rms_px}};
  // What the solvers did (iterations dominate the time of positioning and bundle adjustment).
  nlohmann::json adjustments = nlohmann::json::array();
  for (const sfm_pruning::BundleAdjustmentResult& ba : engine.bundle_adjustments) {
    adjustments.push_back({{"seconds", ba.seconds},
                           {"iterations", ba.num_iterations},
                           {"termination", ba.termination},
                           {"landmarks", ba.num_landmarks},
                           {"observations", ba.num_observations},
                           {"initial_rms_px", ba.initial_rms_px},
                           {"final_rms_px", ba.final_rms_px}});
  }
  json["solvers"] = {{"positioning",
                      {{"iterations", engine.positioning.num_solver_iterations},
                       {"solved_tracks", engine.positioning.num_solved_tracks},
                       {"landmarks", engine.positioning.num_landmarks},
                       {"observations", engine.positioning.num_observations},
                       {"random_starts", engine.positioning.num_random_starts},
                       {"selected_start", engine.positioning.selected_start},
                       {"consistent_rays_per_start", engine.positioning.consistent_constraints_per_start},
                       {"termination", engine.positioning.message}}},
                     {"bundle_adjustments", std::move(adjustments)}};
  json["dropped_views"] = std::move(dropped);
  return json;
}

// The files of a run folder. timings.json is the run's completion record: it is removed before
// the first output is written and written after the last, so a folder holding a timings.json
// holds the outputs of one finished run, and a reader can tell an interrupted one.
constexpr const char* kRunOutputs[] = {"sfm_data.json", "sparse/0", "cloud_and_poses.ply", "view_graph.json",
                                       "pruning_report.json", "timings.json"};

// Before a run writes its outputs: cleans what an interrupted earlier run left beside them and
// withdraws the completion record of the earlier run.
void BeginOutputs(const fs::path& output) {
  for (const char* name : kRunOutputs) sfm_pruning::RemoveStaleTemporaries(output / name);
  std::error_code ec;
  fs::remove(output / "timings.json", ec);
  if (ec) throw sfm_pruning::FileError((output / "timings.json").string(), "cannot remove: " + ec.message());
}

// Colours the points from the images when every posed view's image is found under the scene's
// root path (`run IMAGES OUT`, `run --database DB --image_path DIR`, an OpenMVG project). A scene
// without a root path (synthetic, `reconstruct --database`) keeps grey points silently; one whose
// images are missing or do not decode keeps them with a line saying why.
void ColorPointsFromImages(int num_threads, sfm_pruning::SfmData* model) {
  if (model->root_path.empty()) return;
  for (const sfm_pruning::IndexT view_id : model->PosedViewIds()) {
    const fs::path image = fs::path(model->root_path) / model->views.at(view_id).RelativeImagePath();
    std::error_code ec;
    if (!fs::is_regular_file(image, ec)) {
      Info("points left grey: no image " + image.string());
      return;
    }
  }
  try {
    sfm_pruning::ColorLandmarksFromImages(model, model->root_path, num_threads, ProgressOnStderr());
  } catch (const sfm_pruning::Error& e) {
    Info(std::string("points left grey: ") + e.what());
  }
}

void WriteModelOutputs(const sfm_pruning::SfmData& model, const sfm_pruning::FeaturesPerView& features,
                       const fs::path& output) {
  fs::create_directories(output / "sparse");
  sfm_pruning::WriteSfmData(model, output / "sfm_data.json");
  sfm_pruning::WriteColmapModel(model, output / "sparse" / "0", sfm_pruning::ColmapModelFormat::kBinary, &features);
  sfm_pruning::WritePly(model, output / "cloud_and_poses.ply");
}

sfm_pruning::PositioningMethod Positioning(const EngineSettings& settings) {
  return settings.positioning == "GLOMAP" ? sfm_pruning::PositioningMethod::kGlobalPositioning
                                          : sfm_pruning::PositioningMethod::kTranslationAveraging;
}

sfm_pruning::PositioningTracks PositioningTracks(const EngineSettings& settings) {
  return settings.positioning_tracks == "MATCH_STARS" ? sfm_pruning::PositioningTracks::kMatchStars
                                                      : sfm_pruning::PositioningTracks::kConnected;
}

}  // namespace

void AddEngineOptions(CLI::App* cmd, EngineSettings* settings) {
  cmd->add_option("--engine", settings->engine, "Reconstruction engine")
      ->check(CLI::IsMember({"GLOBAL", "GLOBAL_PRUNED"}))
      ->capture_default_str();
  AddSolverOptions(cmd, settings);
  AddIntrinsicsOptions(cmd, &settings->intrinsics);
  AddPruningOptions(cmd, &settings->pruning, true);
}

sfm_pruning::PrunedGlobalEngineOptions PrunedEngineOptions(const EngineSettings& settings) {
  sfm_pruning::PrunedGlobalEngineOptions options;
  options.pruning = settings.pruning;
  options.engine.positioning = Positioning(settings);
  options.pruning.partition.engine.positioning = Positioning(settings);
  options.engine.positioning_tracks = PositioningTracks(settings);
  options.pruning.partition.engine.positioning_tracks = PositioningTracks(settings);
  // The solve of the pruned graph only (the audit's, whose poses the final adjustment keeps): the
  // per-community solves are many and small, and the consistency tests already judge each of them.
  options.engine.positioning_random_starts = settings.positioning_random_starts;
  options.engine.positioning_start_screening_iterations = settings.positioning_start_screening;
  options.SetSeedAndThreads(settings.seed, settings.num_threads);
  return options;
}

void AddSolverOptions(CLI::App* cmd, EngineSettings* settings) {
  cmd->add_option("--seed", settings->seed, "Seed of every random choice (RANSAC, positioning start)")
      ->check(SeedValue())
      ->capture_default_str();
  cmd->add_option("--num_threads", settings->num_threads,
                  "Worker threads. 1 (the default) gives bitwise reproducible models; with more, Ceres's "
                  "threaded sums make the last digits differ from run to run")
      ->check(PositiveValue())
      ->capture_default_str();
  cmd->add_option("--positioning", settings->positioning,
                  "GLOMAP: global positioning of cameras and points; TRANSLATION_AVERAGING: from edge directions")
      ->check(CLI::IsMember({"GLOMAP", "TRANSLATION_AVERAGING"}))
      ->capture_default_str();
  cmd->add_option("--positioning_tracks", settings->positioning_tracks,
                  "Tracks of the global positioning solve (--positioning GLOMAP only): CONNECTED (union-find "
                  "tracks, GLOMAP) or MATCH_STARS (each feature with its direct matches: a wrong match between "
                  "copies of a repeated texture misplaces one observation instead of merging two tracks; "
                  "docs/global.md)")
      ->check(CLI::IsMember({"CONNECTED", "MATCH_STARS"}))
      ->capture_default_str();
  cmd->add_option("--positioning_random_starts", settings->positioning_random_starts,
                  "Random starts of the positioning solve (GLOBAL_PRUNED: of its solve of the pruned graph); the "
                  "solution that agrees with the most observation rays is kept (1: a single start, as GLOMAP)")
      ->check(RangeValue(1, 1000))
      ->capture_default_str();
  cmd->add_option("--positioning_start_screening", settings->positioning_start_screening,
                  "With several random starts: solve each for this many iterations only, keep the one that "
                  "agrees with the most rays, and solve only that one to the end (0: every start to the end)")
      ->check(NonNegativeValue())
      ->capture_default_str();
  AddVerificationOptions(cmd, &settings->max_epipolar_error_deg, &settings->verification_precision_ratio);
  // Translation averaging builds its tracks after the solve, from the solved cameras: the option
  // would be ignored, so the combination is refused rather than run as if it had been honoured.
  // This takes the command's one parse-complete callback slot (reconstruct, run and prune set none).
  cmd->parse_complete_callback([settings]() {
    if (settings->positioning == "TRANSLATION_AVERAGING" && settings->positioning_tracks == "MATCH_STARS") {
      throw CLI::ValidationError("--positioning_tracks MATCH_STARS",
                                 "needs --positioning GLOMAP (translation averaging has no positioning tracks)");
    }
  });
}

namespace {

Solution Solve(const EngineSettings& settings, const ReconstructionInput& input, const sfm_pruning::SfmData& scene,
               const std::set<sfm_pruning::IndexT>& refined, Schedule schedule, const VerifiedViewGraph* verified) {
  Solution solution;
  const auto verify_start = std::chrono::steady_clock::now();
  std::optional<sfm_pruning::ViewGraph> verified_here;
  if (verified == nullptr) {
    verified_here = BuildVerifiedViewGraph(settings, input, &solution.build, &scene);
  } else {
    solution.build = verified->build;
  }
  const sfm_pruning::ViewGraph& graph = verified != nullptr ? verified->graph : *verified_here;
  solution.verify_seconds = SecondsSince(verify_start);
  Info("view graph: " + std::to_string(graph.NumValidEdges()) + " edges of " +
       std::to_string(solution.build.num_pairs) + " pairs, " + std::to_string(graph.NumNodes()) + " views");
  const sfm_pruning::BundleAdjustmentOptions bundle = RefiningBundleOptions(settings.intrinsics, input, refined);
  if (settings.engine == "GLOBAL_PRUNED" && schedule == Schedule::kFull) {
    sfm_pruning::PrunedGlobalEngineOptions options = PrunedEngineOptions(settings);
    options.engine.bundle = bundle;  // the final solve; the per-community solves hold the intrinsics
    sfm_pruning::PrunedGlobalEngineReport pruned;
    RunPrunedGlobalEngine(options, graph, scene, input.features, &solution.model, &pruned, ProgressOnStderr());
    solution.report = std::move(pruned.engine);
    solution.pruning = std::move(pruned.pruning);
  } else {
    sfm_pruning::GlobalEngineOptions options;
    options.seed = settings.seed;
    options.num_threads = settings.num_threads;
    options.positioning = Positioning(settings);
    options.positioning_tracks = PositioningTracks(settings);
    options.positioning_random_starts = settings.positioning_random_starts;
    options.positioning_start_screening_iterations = settings.positioning_start_screening;
    options.bundle = bundle;
    if (schedule == Schedule::kFocalSearch) options = sfm_pruning::WithFocalSearchSchedule(options);
    RunGlobalEngine(options, graph, scene, input.features, &solution.model, &solution.report, ProgressOnStderr());
  }
  solution.view_graph = sfm_pruning::MakeRunViewGraph(settings.engine, graph, scene,
                                                      solution.pruning ? &*solution.pruning : nullptr);
  return solution;
}

// The cameras whose focal the calibration could not determine: bundle adjustment will move their
// focal far from the guess, and the relative poses verified with the guess would have to be
// estimated and solved again. A quick solve finds the focal first, written into `scene`, so that
// the full solve runs with it. Returns the search's wall time (0 when no camera needed one).
// `prior_graph`: the calibration's graph when it is still valid for `scene` (else verified here).
double SearchUncalibratedFocals(const EngineSettings& settings, const ReconstructionInput& input,
                                const sfm_pruning::FocalCalibrationReport& calibration,
                                const std::set<sfm_pruning::IndexT>& refined, sfm_pruning::SfmData* scene,
                                const VerifiedViewGraph* prior_graph) {
  const std::set<sfm_pruning::IndexT> uncalibrated = UncalibratedFocals(calibration, *scene);
  if (uncalibrated.empty()) return 0.0;
  const auto start = std::chrono::steady_clock::now();
  const Solution search = Solve(settings, input, *scene, refined, Schedule::kFocalSearch, prior_graph);
  if (search.report.success) {
    const std::string searched = MovedFocals(*scene, search.model, uncalibrated, 0.0);
    Info("focal search: " + (searched.empty() ? std::string("the guessed focal stays") : searched));
    for (const sfm_pruning::IndexT id : uncalibrated) {
      scene->intrinsics.at(id).SetFocalLength(search.model.intrinsics.at(id).FocalLength());
    }
  } else {
    Info("focal search failed (" + search.report.message + "): solving from the guessed focal");
  }
  return SecondsSince(start);
}

}  // namespace

void RunReconstruction(const EngineSettings& settings, const ReconstructionInput& input, const fs::path& output,
                       double read_seconds, const std::vector<FrontEndStageTiming>& front_end) {
  const std::set<sfm_pruning::IndexT> refined = RefinedIntrinsics(settings.intrinsics, input);
  sfm_pruning::SfmData scene = input.scene;
  std::optional<sfm_pruning::FocalCalibrationReport> calibration;
  std::optional<VerifiedViewGraph> prior_graph;
  const auto calibration_start = std::chrono::steady_clock::now();
  const std::set<sfm_pruning::IndexT> focals_to_calibrate = FocalsToCalibrate(settings.intrinsics, input);
  if (settings.intrinsics.focal && !focals_to_calibrate.empty()) {
    calibration = CalibrateFocals(settings, input, focals_to_calibrate, &scene, &prior_graph);
    ReportCalibration(*calibration);
    // An accepted focal changes the intrinsics the prior graph was verified with.
    for (const sfm_pruning::IntrinsicFocalCalibration& entry : calibration->intrinsics) {
      if (entry.accepted) prior_graph.reset();
    }
  }
  const double calibration_seconds = SecondsSince(calibration_start);

  const double focal_search_seconds =
      calibration && settings.intrinsics.focal
          ? SearchUncalibratedFocals(settings, input, *calibration, refined, &scene,
                                     prior_graph ? &*prior_graph : nullptr)
          : 0.0;

  Solution solution = Solve(settings, input, scene, refined, Schedule::kFull);
  double first_pass_seconds = 0.0;
  const std::string moved = MovedFocals(scene, solution.model, refined, settings.intrinsics.refocus_threshold);
  if (solution.report.success && settings.intrinsics.focal && !moved.empty()) {
    // The relative poses were estimated with a focal that bundle adjustment found wrong: verify
    // again with the refined intrinsics and solve again, once.
    Info("bundle adjustment moved the focal (" + moved + "): verifying and solving again with the refined intrinsics");
    first_pass_seconds = solution.verify_seconds + solution.report.total_seconds;
    for (const sfm_pruning::IndexT id : refined) scene.intrinsics.at(id) = solution.model.intrinsics.at(id);
    solution = Solve(settings, input, scene, refined, Schedule::kFull);
  }
  const sfm_pruning::ViewGraphBuildReport& build = solution.build;
  const sfm_pruning::GlobalEngineReport& report = solution.report;
  sfm_pruning::SfmData& model = solution.model;
  const std::optional<sfm_pruning::ViewGraphPruningReport>& pruning = solution.pruning;
  const double verify_seconds = solution.verify_seconds;
  if (!report.success) throw Error(input.source + ": reconstruction failed: " + report.message);
  fs::create_directories(output);
  BeginOutputs(output);
  if (pruning) {
    WriteJsonAtomically(PruningReportJson(*pruning), output / "pruning_report.json");
    Info("pruning: " + PruningSummary(*pruning) + "; wrote pruning_report.json");
  } else {
    // An earlier GLOBAL_PRUNED run's report would describe a pruning this run did not do.
    std::error_code ec;
    fs::remove(output / "pruning_report.json", ec);
  }

  nlohmann::json timings =
      TimingsJson(settings, build, report, model, read_seconds, verify_seconds, pruning ? &*pruning : nullptr);
  auto& stage_list = timings.at("stages");
  if (first_pass_seconds > 0.0) {
    stage_list.insert(stage_list.begin() + 1, nlohmann::json{{"stage", "first pass"}, {"seconds", first_pass_seconds}});
  }
  if (focal_search_seconds > 0.0) {
    stage_list.insert(stage_list.begin() + 1,
                      nlohmann::json{{"stage", "focal search"}, {"seconds", focal_search_seconds}});
  }
  if (calibration) {
    stage_list.insert(stage_list.begin() + 1,
                      nlohmann::json{{"stage", "focal calibration"}, {"seconds", calibration_seconds}});
    timings["focal_calibration"] = CalibrationJson(*calibration);
  }
  timings["refined_intrinsics"] = {{"intrinsic_ids", refined},
                                   {"focal", settings.intrinsics.focal},
                                   {"distortion", settings.intrinsics.distortion},
                                   {"principal_point", settings.intrinsics.principal_point}};
  // The image front end's stages (`run IMAGES OUT`) come first.
  stage_list.insert(stage_list.begin(), front_end.size(), nlohmann::json());
  for (size_t k = 0; k < front_end.size(); ++k) {
    stage_list[k] = {{"stage", front_end[k].stage}, {"seconds", front_end[k].seconds}, {"reused", front_end[k].reused}};
  }
  for (const auto& dropped : timings.at("dropped_views")) {
    Info("dropped view " + dropped.at("view_id").dump() + " (" + dropped.at("image").get<std::string>() +
         "): " + dropped.at("reason").get<std::string>());
  }
  const auto coloring_start = std::chrono::steady_clock::now();
  ColorPointsFromImages(settings.num_threads, &model);
  stage_list.push_back({{"stage", "point colours"}, {"seconds", SecondsSince(coloring_start)}});
  WriteModelOutputs(model, input.features, output);
  sfm_pruning::WriteRunViewGraph(solution.view_graph, output / "view_graph.json");
  WriteJsonAtomically(timings, output / "timings.json");  // last: the run is complete
  std::string stages;
  for (const auto& stage : timings.at("stages")) {
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.2f", stage.at("seconds").get<double>());
    stages += (stages.empty() ? "" : ", ") + stage.at("stage").get<std::string>() + " " + seconds + " s";
  }
  Info("registered " + std::to_string(report.num_registered_views) + " of " + std::to_string(input.scene.views.size()) +
       " views, " + std::to_string(report.num_landmarks) + " points, RMS " + std::to_string(report.final_rms_px) +
       " px; " + stages);
  Info("wrote " + (output / "sfm_data.json").string() + ", " + (output / "sparse" / "0").string() +
       ", cloud_and_poses.ply, timings.json, view_graph.json");
}

}  // namespace prunesfm
