#include "software/commands/reconstruction_pipeline.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <glog/logging.h>
#include <nlohmann/json.hpp>

#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "software/cli_support.hpp"

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

sfm_pruning::ViewGraph BuildGraph(const EngineSettings& settings, const ReconstructionInput& input,
                                  sfm_pruning::ViewGraphBuildReport* report) {
  if (input.verified.empty() && input.putative.empty()) {
    throw Error(input.source + ": no edges: no two-view geometries and no matches");
  }
  sfm_pruning::ViewGraphBuildOptions options;
  options.seed = settings.seed;
  options.num_threads = settings.num_threads;
  sfm_pruning::ViewGraph graph;
  try {
    graph = input.verified.empty()
                ? BuildViewGraphFromMatches(options, input.scene, input.features, input.putative, report,
                                            TerminalProgressBar())
                : BuildViewGraphFromVerifiedPairs(options, input.scene, input.features, input.verified, report,
                                                  TerminalProgressBar());
  } catch (const Error& e) {
    throw Error(input.source + ": " + e.what());
  }
  if (graph.NumValidEdges() == 0) {
    std::string message = input.source + ": no edges: all " + std::to_string(report->num_pairs) +
                          " pairs were rejected by the verification";
    if (!report->rejected_pairs.empty()) {
      message += " (pair " + PairName(report->rejected_pairs.front().pair) + ": " +
                 report->rejected_pairs.front().reason + ")";
    }
    throw Error(message);
  }
  return graph;
}

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
  json["dropped_views"] = std::move(dropped);
  return json;
}

nlohmann::json ViewPairJson(const sfm_pruning::ViewPair& pair) { return nlohmann::json::array({pair.first, pair.second}); }

// OUT/pruning_report.json: the subgraph tree, the accepted subgraphs, the connected pairs, the
// removed edges with their reasons and measured errors, and the phase times.
nlohmann::json PruningReportJson(const sfm_pruning::ViewGraphPruningReport& pruning) {
  using namespace sfm_pruning;
  const auto summary = [](const ErrorSummary& s) {
    return nlohmann::json{{"count", s.count}, {"max_deg", s.max_deg}, {"median_deg", s.median_deg}};
  };
  nlohmann::json nodes = nlohmann::json::array();
  for (size_t i = 0; i < pruning.partition.nodes.size(); ++i) {
    const SubgraphNode& node = pruning.partition.nodes[i];
    nlohmann::json entry = {{"id", i},
                            {"parent", node.parent},
                            {"depth", node.depth},
                            {"size", node.view_ids.size()},
                            {"edges", node.num_edges},
                            {"status", SubgraphStatusName(node.status)},
                            {"children", node.children},
                            {"accepted_index", node.accepted_index},
                            {"seconds", node.seconds}};
    if (node.solved) {
      entry["engine_success"] = node.engine_success;
      if (!node.engine_message.empty()) entry["engine_message"] = node.engine_message;
      entry["registered"] = node.num_registered;
      entry["landmarks"] = node.num_landmarks;
    }
    if (node.consistency_tested) {
      size_t counts[3] = {0, 0, 0};
      for (const ConsistencyViolation& v : node.consistency.violations) ++counts[static_cast<int>(v.test)];
      entry["consistent"] = node.consistency.consistent;
      entry["violations"] = {{"loop", counts[0]}, {"relative_rotation", counts[1]}, {"relative_translation", counts[2]}};
      entry["loop_error"] = summary(node.consistency.loop_error);
      entry["relative_rotation_error"] = summary(node.consistency.relative_rotation_error);
      entry["relative_translation_error"] = summary(node.consistency.relative_translation_error);
    }
    entry["view_ids"] = node.view_ids;
    nodes.push_back(std::move(entry));
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (const SubgraphPairReport& pair : pruning.pairs) {
    pairs.push_back({{"k1", pair.k1},
                     {"k2", pair.k2},
                     {"status", SubgraphAlignmentStatusName(pair.status)},
                     {"edges", pair.num_edges},
                     {"voting_edges", pair.num_voting_edges},
                     {"removed_edges", pair.num_removed_edges},
                     {"beta", pair.beta}});
  }
  nlohmann::json removed = nlohmann::json::array();
  for (const RemovedEdge& edge : pruning.removed_edges) {
    removed.push_back({{"pair", ViewPairJson(edge.pair)},
                       {"k1", edge.k1},
                       {"k2", edge.k2},
                       {"verdict", InterSubgraphVerdictName(edge.verdict)},
                       {"reason", EdgeInvalidReasonName(edge.invalidation.reason)},
                       {"value", edge.invalidation.value},
                       {"threshold", edge.invalidation.threshold}});
  }
  nlohmann::json phases = nlohmann::json::array();
  for (const StageTiming& timing : pruning.timings) phases.push_back({{"stage", timing.stage}, {"seconds", timing.seconds}});
  return {{"edges_in", pruning.num_input_edges},
          {"edges_out", pruning.num_output_edges},
          {"num_subgraphs", pruning.partition.accepted.size()},
          {"engine_runs", pruning.partition.num_engine_runs},
          {"phases", std::move(phases)},
          {"total_seconds", pruning.total_seconds},
          {"tree", std::move(nodes)},
          {"subgraph_pairs", std::move(pairs)},
          {"removed_edges", std::move(removed)}};
}

// Ceres logs solver warnings (e.g. a rejected Levenberg-Marquardt step) through glog on stderr;
// the engine reports through its results instead, so the command keeps stderr to its own lines.
void SilenceSolverLogging() {
  static const bool initialized = []() {
    google::InitGoogleLogging("prunesfm");
    FLAGS_logtostderr = true;
    FLAGS_minloglevel = google::GLOG_FATAL;
    return true;
  }();
  (void)initialized;
}

void WriteOutputs(const sfm_pruning::SfmData& model, const sfm_pruning::FeaturesPerView& features,
                  const nlohmann::json& timings, const fs::path& output) {
  fs::create_directories(output / "sparse");
  sfm_pruning::WriteSfmData(model, output / "sfm_data.json");
  sfm_pruning::WriteColmapModel(model, output / "sparse" / "0", sfm_pruning::ColmapModelFormat::kBinary, &features);
  sfm_pruning::WritePly(model, output / "cloud_and_poses.ply");
  sfm_pruning::WriteFileAtomically(output / "timings.json", false,
                                   [&](std::ostream& out) { out << timings.dump(2) << "\n"; });
}

}  // namespace

void AddEngineOptions(CLI::App* cmd, EngineSettings* settings) {
  cmd->add_option("--engine", settings->engine, "Reconstruction engine")
      ->check(CLI::IsMember({"GLOBAL", "GLOBAL_PRUNED"}))
      ->capture_default_str();
  cmd->add_option("--seed", settings->seed, "Seed of every random choice (RANSAC, positioning start)")
      ->capture_default_str();
  cmd->add_option("--num_threads", settings->num_threads,
                  "Worker threads (1 gives bitwise reproducible results)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--positioning", settings->positioning,
                  "GLOMAP: global positioning of cameras and points; TRANSLATION_AVERAGING: from edge directions")
      ->check(CLI::IsMember({"GLOMAP", "TRANSLATION_AVERAGING"}))
      ->capture_default_str();
}

void RunReconstruction(const EngineSettings& settings, const ReconstructionInput& input, const fs::path& output,
                       double read_seconds) {
  SilenceSolverLogging();
  const auto verify_start = std::chrono::steady_clock::now();
  sfm_pruning::ViewGraphBuildReport build;
  const sfm_pruning::ViewGraph graph = BuildGraph(settings, input, &build);
  const double verify_seconds = SecondsSince(verify_start);
  Info("view graph: " + std::to_string(graph.NumValidEdges()) + " edges of " + std::to_string(build.num_pairs) +
       " pairs, " + std::to_string(graph.NumNodes()) + " views");

  const sfm_pruning::PositioningMethod positioning = settings.positioning == "GLOMAP"
                                                        ? sfm_pruning::PositioningMethod::kGlobalPositioning
                                                        : sfm_pruning::PositioningMethod::kTranslationAveraging;
  sfm_pruning::SfmData model;
  sfm_pruning::GlobalEngineReport report;
  std::optional<sfm_pruning::ViewGraphPruningReport> pruning;
  if (settings.engine == "GLOBAL_PRUNED") {
    sfm_pruning::PrunedGlobalEngineOptions options;
    options.engine.positioning = positioning;
    options.pruning.partition.engine.positioning = positioning;
    options.SetSeedAndThreads(settings.seed, settings.num_threads);
    sfm_pruning::PrunedGlobalEngineReport pruned;
    RunPrunedGlobalEngine(options, graph, input.scene, input.features, &model, &pruned, TerminalProgressBar());
    report = std::move(pruned.engine);
    pruning = std::move(pruned.pruning);
  } else {
    sfm_pruning::GlobalEngineOptions options;
    options.seed = settings.seed;
    options.num_threads = settings.num_threads;
    options.positioning = positioning;
    RunGlobalEngine(options, graph, input.scene, input.features, &model, &report, TerminalProgressBar());
  }
  if (!report.success) throw Error(input.source + ": reconstruction failed: " + report.message);
  if (pruning) {
    fs::create_directories(output);
    const nlohmann::json pruning_json = PruningReportJson(*pruning);
    sfm_pruning::WriteFileAtomically(output / "pruning_report.json", false,
                                     [&](std::ostream& out) { out << pruning_json.dump(2) << "\n"; });
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.2f", pruning->total_seconds);
    Info("pruning: " + std::to_string(pruning->partition.accepted.size()) + " subgraphs (" +
         std::to_string(pruning->partition.nodes.size()) + " tree nodes, " +
         std::to_string(pruning->partition.num_engine_runs) + " engine runs), removed " +
         std::to_string(pruning->removed_edges.size()) + " of " + std::to_string(pruning->num_input_edges) +
         " edges in " + std::to_string(pruning->pairs.size()) + " subgraph pairs, " + seconds +
         " s; wrote pruning_report.json");
  }

  const nlohmann::json timings =
      TimingsJson(settings, build, report, model, read_seconds, verify_seconds, pruning ? &*pruning : nullptr);
  for (const auto& dropped : timings.at("dropped_views")) {
    Info("dropped view " + dropped.at("view_id").dump() + " (" + dropped.at("image").get<std::string>() +
         "): " + dropped.at("reason").get<std::string>());
  }
  WriteOutputs(model, input.features, timings, output);
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
       ", cloud_and_poses.ply, timings.json");
}

}  // namespace prunesfm
