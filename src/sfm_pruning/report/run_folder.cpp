#include "sfm_pruning/report/run_folder.hpp"

#include <algorithm>

#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/report/json_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

void ReadTimings(const fs::path& path, RunFolder* run) {
  const nlohmann::json json = ReadJsonObject(path);
  ReadJsonFields(path, "timings", [&]() {
    run->engine = json.at("engine").get<std::string>();
    for (const auto& stage : json.at("stages")) {
      run->stages.push_back({stage.at("stage").get<std::string>(), stage.at("seconds").get<double>()});
    }
    const auto counts = json.find("counts");
    if (counts != json.end() && counts->contains("final_rms_px")) {
      run->final_rms_px = counts->at("final_rms_px").get<double>();
    }
  });
}

PruningSummary ReadPruningSummary(const fs::path& path) {
  const nlohmann::json json = ReadJsonObject(path);
  PruningSummary summary;
  ReadJsonFields(path, "pruning report", [&]() {
    summary.edges_in = json.at("edges_in").get<size_t>();
    summary.edges_out = json.at("edges_out").get<size_t>();
    summary.engine_runs = json.at("engine_runs").get<size_t>();
    summary.total_seconds = json.at("total_seconds").get<double>();
    const size_t num_subgraphs = json.at("num_subgraphs").get<size_t>();
    summary.subgraphs.resize(num_subgraphs);
    for (const auto& node : json.at("tree")) {
      const int index = node.at("accepted_index").get<int>();
      if (index < 0) continue;
      if (static_cast<size_t>(index) >= num_subgraphs) {
        throw FileError(path.string(), "accepted_index " + std::to_string(index) + " >= num_subgraphs");
      }
      summary.subgraphs[static_cast<size_t>(index)] = {node.at("size").get<size_t>(), node.at("edges").get<size_t>(),
                                                       node.at("status").get<std::string>(),
                                                       node.at("depth").get<int>()};
    }
  });
  return summary;
}

}  // namespace

std::vector<StageTotal> TotalsByStage(const std::vector<StageSeconds>& stages) {
  std::vector<StageTotal> totals;
  for (const StageSeconds& stage : stages) {
    auto total = std::find_if(totals.begin(), totals.end(),
                              [&](const StageTotal& entry) { return entry.stage == stage.stage; });
    if (total == totals.end()) total = totals.insert(totals.end(), {stage.stage, 0.0, 0});
    total->seconds += stage.seconds;
    ++total->runs;
  }
  return totals;
}

RunFolder ReadRunFolder(const fs::path& path) {
  if (!fs::is_directory(path)) throw FileError(path.string(), "not a run folder (no such directory)");
  if (fs::exists(path / kOutputFolderMarker) && fs::exists(path / "sfm_data.json") &&
      !fs::exists(path / "timings.json")) {
    throw FileError(path.string(), "the run that wrote this folder did not finish (no timings.json); run it again");
  }
  RunFolder run;
  run.path = path;
  if (fs::is_regular_file(path / "sfm_data.json")) {
    run.model_path = path / "sfm_data.json";
  } else if (fs::is_directory(path / "sparse" / "0")) {
    run.model_path = path / "sparse" / "0";
  } else {
    throw FileError(path.string(), "not a run folder: neither sfm_data.json nor sparse/0");
  }
  run.model = ReadModel(run.model_path);
  if (fs::exists(path / "timings.json")) ReadTimings(path / "timings.json", &run);
  if (fs::exists(path / "view_graph.json")) {
    run.view_graph = ReadRunViewGraph(path / "view_graph.json");
    if (run.engine.empty()) run.engine = run.view_graph->engine;
  }
  if (fs::exists(path / "pruning_report.json")) run.pruning = ReadPruningSummary(path / "pruning_report.json");
  return run;
}

}  // namespace sfm_pruning
