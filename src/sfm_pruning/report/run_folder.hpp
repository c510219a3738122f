// What `prunesfm report` reads from a run folder (the output of `prunesfm run` / `reconstruct`):
//   sfm_data.json (else sparse/0)  the model: cameras, points, observations      (required)
//   timings.json                   engine, per-stage seconds, counts             (optional)
//   view_graph.json                the graph before pruning (run_view_graph.hpp) (optional)
//   pruning_report.json            the subgraph tree of GLOBAL_PRUNED            (optional)
// An optional file that exists must parse: a corrupt one is an error, not a silent gap.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sfm_pruning/report/run_view_graph.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

struct StageSeconds {
  std::string stage;
  double seconds = 0.0;
};

// One stage's seconds summed over its runs: a stage may run several times (the solves of the
// missing-correspondence rounds), and timings.json lists each run.
struct StageTotal {
  std::string stage;
  double seconds = 0.0;
  int runs = 0;
};

// The totals of `stages` by name, in the order the names first appear.
std::vector<StageTotal> TotalsByStage(const std::vector<StageSeconds>& stages);

struct AcceptedSubgraphSummary {
  size_t num_views = 0;
  size_t num_edges = 0;
  std::string status;  // "consistent", "tiny", ...
  int depth = 0;
};

struct PruningSummary {
  size_t edges_in = 0;
  size_t edges_out = 0;
  size_t engine_runs = 0;
  double total_seconds = 0.0;
  std::vector<AcceptedSubgraphSummary> subgraphs;  // in acceptance order (= subgraph index)
};

struct RunFolder {
  std::filesystem::path path;
  std::filesystem::path model_path;  // the file or folder the model came from
  SfmData model;
  std::string engine;  // from timings.json (or view_graph.json); empty when neither exists
  std::vector<StageSeconds> stages;
  double final_rms_px = -1.0;  // -1 when unknown
  std::optional<RunViewGraph> view_graph;
  std::optional<PruningSummary> pruning;
};

// Throws Error naming the folder when it holds no model, or naming the file that is corrupt.
RunFolder ReadRunFolder(const std::filesystem::path& path);

}  // namespace sfm_pruning
