#include "software/commands/reconstruction_pipeline.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "sfm_pruning/report/run_folder.hpp"
#include "sfm_pruning/report/run_view_graph.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "software/cli_checks.hpp"
#include "software/cli_support.hpp"
#include "software/commands/front_end_stages.hpp"
#include "software/commands/pruning_options.hpp"
#include "software/commands/pruning_report_json.hpp"
#include "software/help_format.hpp"

namespace prunesfm {
namespace {
namespace fs = std::filesystem;
using sfm_pruning::Error;

// "stage 1.23 s, ..." in the order the stages first appear; a stage that ran several times (the
// solves of the missing-correspondence rounds) is summed: "stage 412.58 s (3 runs)".
// timings.json keeps each run.
std::string StageSecondsLine(const nlohmann::json& stage_list) {
  std::vector<sfm_pruning::StageSeconds> stages;
  for (const auto& stage : stage_list) {
    stages.push_back({stage.at("stage").get<std::string>(), stage.at("seconds").get<double>()});
  }
  std::string line;
  for (const sfm_pruning::StageTotal& total : sfm_pruning::TotalsByStage(stages)) {
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.2f", total.seconds);
    line += (line.empty() ? "" : ", ") + total.stage + " " + seconds + " s" +
            (total.runs > 1 ? " (" + std::to_string(total.runs) + " runs)" : "");
  }
  return line;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

namespace {

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
  json["link_depth_votes"] = settings.link_depth_votes;
  json["positioning_random_starts"] = settings.positioning_random_starts;
  json["positioning_start_screening"] = settings.positioning_start_screening;
  json["max_epipolar_error_deg"] = settings.max_epipolar_error_deg;
  json["verification_precision_ratio"] = settings.verification_precision_ratio;
  if (settings.engine == "GLOBAL_PRUNED") {
    json["prune_audit_enabled"] = settings.pruning.audit.enabled;
    json["prune_audit_model_schedule"] = AuditModelName(settings.pruning.audit.model_schedule);
    json["prune_audit_refine_final"] = settings.pruning.audit.refine_final;
    json["prune_landmark_check_max_angle_deg"] = settings.pruning.landmark_check.max_angle_deg;
    json["prune_missing_correspondences_enabled"] = settings.pruning.missing_correspondences.enabled;
    json["prune_missing_correspondences_max_rounds"] = settings.pruning.missing_correspondences.max_rounds;
    json["prune_max_enumerated_samples"] = settings.pruning.alignment.max_enumerated_samples;
    json["prune_bisect_unsplittable"] = settings.pruning.partition.bisect_unsplittable;
    json["prune_max_baseline_ratio_factor"] =
        settings.pruning.partition.consistency.max_baseline_ratio_factor;
    json["prune_trust_prior_edges"] = settings.pruning.trust_prior_edges;
    json["prune_capture_order_use"] = sfm_pruning::CaptureOrderUseName(settings.pruning.capture_order.use);
  }
  json["seed"] = settings.seed;
  json["num_threads"] = sfm_pruning::ResolveThreadCount(settings.num_threads);
  json["solver_threads"] = settings.solver_threads;
  json["stages"] = std::move(stages);
  json["engine_seconds"] = engine.total_seconds;
  json["counts"] = {{"views", model.views.size()},
                    {"pairs", build.num_pairs},
                    {"rejected_pairs", build.rejected_pairs.size()},
                    {"edges_in", engine.num_input_edges},
                    {"edges_after_rotation_filter", engine.num_rotation_edges},
                    {"edges_filtered_by_rotation", engine.num_filtered_edges},
                    {"depth_inconsistent_links", engine.num_depth_inconsistent_links},
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
  if (engine.distortion.tested) {
    json["distortion_evidence"] = {{"kept", engine.distortion.kept},
                                   {"statistic", engine.distortion.statistic},
                                   {"threshold", engine.distortion.threshold},
                                   {"parameters", engine.distortion.num_parameters},
                                   {"residuals", engine.distortion.num_residuals}};
  }
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

}  // namespace

void AddEngineOptions(CLI::App* cmd, EngineSettings* settings) {
  cmd->add_option("--engine", settings->engine, "Reconstruction engine")
      ->check(CLI::IsMember({"GLOBAL", "GLOBAL_PRUNED"}))
      ->capture_default_str();
  cmd->add_option("--reverify_database_pairs", settings->reverify_database_pairs,
                  "With --database: verify the pairs COLMAP verified again, from their raw matches, with this "
                  "project's verification instead of taking COLMAP's inliers (its 4 px threshold keeps matches "
                  "between copies of a repeated structure inside true pairs); false, the default: COLMAP's "
                  "inliers, each pair's pose re-estimated from them")
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  AddSolverOptions(cmd, settings);
  AddIntrinsicsOptions(cmd, &settings->intrinsics);
  AddPruningOptions(cmd, &settings->pruning, true);
}

sfm_pruning::ReconstructionInput ReadDatabaseInput(const std::string& database, const std::string& image_path,
                                                   const EngineSettings& settings) {
  sfm_pruning::ReconstructionInput input = sfm_pruning::ReadColmapInput(database);
  input.scene.root_path = image_path;
  if (settings.reverify_database_pairs) sfm_pruning::ReverifyDatabasePairs(&input);
  return input;
}

sfm_pruning::ReconstructionOptions ToReconstructionOptions(const EngineSettings& settings) {
  sfm_pruning::ReconstructionOptions options;
  options.engine = sfm_pruning::ParseReconstructionEngine(settings.engine);
  options.seed = settings.seed;
  options.num_threads = settings.num_threads;
  options.solver_threads = settings.solver_threads;
  options.positioning = settings.positioning == "GLOMAP" ? sfm_pruning::PositioningMethod::kGlobalPositioning
                                                         : sfm_pruning::PositioningMethod::kTranslationAveraging;
  options.positioning_tracks = settings.positioning_tracks == "MATCH_STARS" ? sfm_pruning::PositioningTracks::kMatchStars
                                                                             : sfm_pruning::PositioningTracks::kConnected;
  options.link_depth_votes = settings.link_depth_votes;
  options.positioning_random_starts = settings.positioning_random_starts;
  options.positioning_start_screening_iterations = settings.positioning_start_screening;
  options.max_epipolar_error_deg = settings.max_epipolar_error_deg;
  options.verification_precision_ratio = settings.verification_precision_ratio;
  options.pruning = settings.pruning;
  options.intrinsics = ToIntrinsicsOptions(settings.intrinsics);
  return options;
}

void AddSolverOptions(CLI::App* cmd, EngineSettings* settings) {
  cmd->add_option("--seed", settings->seed, "Seed of every random choice (RANSAC, positioning start)")
      ->check(SeedValue())
      ->capture_default_str();
  cmd->add_option("--num_threads", settings->num_threads,
                  "Worker threads of the stages whose result does not depend on their number (features, "
                  "matching, verification, the pruning's community solves and subgraph pairs, point colours); "
                  "0, the default: every core")
      ->check(NonNegativeValue())
      ->capture_default_str();
  cmd->add_option("--solver_threads", settings->solver_threads,
                  "Ceres threads of positioning and bundle adjustment. 1, the default, keeps every output "
                  "bitwise reproducible whatever --num_threads is; more are faster on large scenes, but Ceres's "
                  "threaded sums then change the last digits from run to run")
      ->check(PositiveValue())
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--positioning", settings->positioning,
                  "GLOMAP: global positioning of cameras and points; TRANSLATION_AVERAGING: from edge directions")
      ->check(CLI::IsMember({"GLOMAP", "TRANSLATION_AVERAGING"}))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--positioning_tracks", settings->positioning_tracks,
                  "Tracks of the global positioning solve (--positioning GLOMAP only): CONNECTED (union-find "
                  "tracks, GLOMAP) or MATCH_STARS (each feature with its direct matches: a wrong match between "
                  "copies of a repeated texture misplaces one observation instead of merging two tracks; "
                  "docs/global.md)")
      ->check(CLI::IsMember({"CONNECTED", "MATCH_STARS"}))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--link_depth_votes", settings->link_depth_votes,
                  "Keep out of the tracks the inlier matches whose depth the feature's other matches contradict "
                  "(a match between copies of a repeated texture along the baseline; docs/global.md)")
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--positioning_random_starts", settings->positioning_random_starts,
                  "Random starts of the positioning solve (GLOBAL_PRUNED: of its solve of the pruned graph); the "
                  "solution that agrees with the most observation rays is kept (1: a single start, as GLOMAP)")
      ->check(RangeValue(1, 1000))
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  cmd->add_option("--positioning_start_screening", settings->positioning_start_screening,
                  "With several random starts: solve each for this many iterations only, keep the one that "
                  "agrees with the most rays, and solve only that one to the end (0: every start to the end)")
      ->check(NonNegativeValue())
      ->capture_default_str()
      ->group(kExpertOptionsGroup);
  AddVerificationOptions(cmd, &settings->max_epipolar_error_deg, &settings->verification_precision_ratio);
  // Translation averaging builds its tracks after the solve, from the solved cameras: the option
  // would be ignored, so the combination is refused rather than run as if it had been honoured.
  // This takes the command's one parse-complete callback slot (reconstruct, run and prune set none).
  // The same callback checks every value against the library's rules (ReconstructionOptions::Check,
  // which includes the pruning's), so a value that no single flag's range catches (an audit whose
  // keep share exceeds its re-admit share) stops the command before it reads anything.
  cmd->parse_complete_callback([settings]() {
    if (settings->positioning == "TRANSLATION_AVERAGING" && settings->positioning_tracks == "MATCH_STARS") {
      throw CLI::ValidationError("--positioning_tracks MATCH_STARS",
                                 "needs --positioning GLOMAP (translation averaging has no positioning tracks)");
    }
    try {
      ToReconstructionOptions(*settings).Check();
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("option values", e.what());
    }
  });
}

void RunReconstruction(const EngineSettings& settings, const sfm_pruning::ReconstructionInput& input,
                       const fs::path& output, double read_seconds, const std::vector<FrontEndStageTiming>& front_end) {
  sfm_pruning::ReconstructionResult result;
  try {
    result = sfm_pruning::Reconstruct(ToReconstructionOptions(settings), input, ProgressOnStderr(),
                                      [](const std::string& line) { Info(line); });
  } catch (const std::invalid_argument& e) {
    throw Error(input.source + ": " + e.what());
  }
  const sfm_pruning::ViewGraphBuildReport& build = result.build;
  const sfm_pruning::GlobalEngineReport& report = result.engine;
  sfm_pruning::SfmData& model = result.model;
  const std::optional<sfm_pruning::ViewGraphPruningReport>& pruning = result.pruning;
  const std::optional<sfm_pruning::FocalCalibrationReport>& calibration = result.calibration;
  const std::set<sfm_pruning::IndexT>& refined = result.refined_intrinsics;
  if (!result.success) throw Error(input.source + ": reconstruction failed: " + result.message);
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
      TimingsJson(settings, build, report, model, read_seconds, result.verification_seconds,
                  pruning ? &*pruning : nullptr);
  auto& stage_list = timings.at("stages");
  if (result.first_pass_seconds > 0.0) {
    stage_list.insert(stage_list.begin() + 1,
                      nlohmann::json{{"stage", "first pass"}, {"seconds", result.first_pass_seconds}});
  }
  if (result.focal_search_seconds > 0.0) {
    stage_list.insert(stage_list.begin() + 1,
                      nlohmann::json{{"stage", "focal search"}, {"seconds", result.focal_search_seconds}});
  }
  if (calibration) {
    stage_list.insert(stage_list.begin() + 1,
                      nlohmann::json{{"stage", "focal calibration"}, {"seconds", result.calibration_seconds}});
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
  ColorPointsFromImages(sfm_pruning::ResolveThreadCount(settings.num_threads), &model);
  stage_list.push_back({{"stage", "point colours"}, {"seconds", SecondsSince(coloring_start)}});
  WriteModelOutputs(model, input.features, output);
  sfm_pruning::WriteRunViewGraph(result.view_graph, output / "view_graph.json");
  WriteJsonAtomically(timings, output / "timings.json");  // last: the run is complete
  Info("registered " + std::to_string(report.num_registered_views) + " of " + std::to_string(input.scene.views.size()) +
       " views, " + std::to_string(report.num_landmarks) + " points, RMS " + std::to_string(report.final_rms_px) +
       " px; " + StageSecondsLine(timings.at("stages")));
  if (report.distortion.tested) {
    char evidence[160];
    std::snprintf(evidence, sizeof(evidence), "lens distortion %s: its adjustment saved %.1f, the criterion asks %.1f",
                  report.distortion.kept ? "estimated" : "held (the data do not determine it)",
                  report.distortion.statistic, report.distortion.threshold);
    Info(evidence);
  }
  Info("wrote " + (output / "sfm_data.json").string() + ", " + (output / "sparse" / "0").string() +
       ", cloud_and_poses.ply, timings.json, view_graph.json");
}

}  // namespace prunesfm
