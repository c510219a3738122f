// The view graph of a run as the report draws it (OUT/view_graph.json, written by `prunesfm
// run` / `reconstruct`): every verified edge before pruning with its inlier count, whether the
// pruning removed it (and why), and the accepted subgraph of every view.
//
// The engine's own rotation filter is not recorded: it runs on a copy inside the solve. Edges
// rejected by the two-view verification are not listed (they never entered the graph).
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct RunGraphView {
  IndexT view_id = kUndefinedIndex;
  std::string image;  // View::RelativeImagePath()
  int subgraph = -1;  // index of the accepted subgraph; -1 without pruning or outside the partition
};

struct RunGraphEdge {
  IndexT i = kUndefinedIndex;  // i < j
  IndexT j = kUndefinedIndex;
  size_t inliers = 0;
  bool removed = false;  // cut by the pruning
  std::string reason;    // EdgeInvalidReasonName of the cut, empty when kept
  double value = 0.0;    // measured error of the cut, in the unit of `measure`
  double threshold = 0.0;
  std::string measure;  // EdgeMeasureName of the cut ("degrees", ...); empty in older files
  // The verified two-view geometry, X_j = R_ij X_i + t_ij with |t_ij| = 1 (sfm/pose.hpp);
  // absent (identity, zero) in files written before it was recorded.
  RelativePose relative_pose;
  // Its rotation's standard deviation along the least determined axis, degrees (ViewGraphEdge);
  // infinite when not estimated (a database's pose) and in files written before it was recorded.
  double rotation_std_deg = std::numeric_limits<double>::infinity();
};

struct RunViewGraph {
  std::string engine;  // "GLOBAL", "GLOBAL_PRUNED"
  int num_subgraphs = 0;
  std::vector<RunGraphView> views;  // view id order
  std::vector<RunGraphEdge> edges;  // (i, j) order

  size_t NumRemovedEdges() const;
};

// The record of `graph` (valid edges only) with the cuts and subgraphs of `pruning` (nullptr for
// an engine without pruning). Views are those of the graph, named from `scene`.
RunViewGraph MakeRunViewGraph(const std::string& engine, const ViewGraph& graph, const SfmData& scene,
                              const ViewGraphPruningReport* pruning);

// JSON: {"engine", "num_subgraphs", "views": [{"view_id", "image", "subgraph"}],
//        "edges": [{"i", "j", "inliers", "removed", "rotation": [qw, qx, qy, qz] of R_ij,
//                   "translation": t_ij, ["rotation_std_deg"], ["reason", "value", "threshold",
//                   "measure"]}]}. Atomic.
void WriteRunViewGraph(const RunViewGraph& graph, const std::filesystem::path& path);

// Throws Error naming the file for unreadable JSON, a missing field, an edge whose ends are not
// listed views, or a subgraph index outside [-1, num_subgraphs).
RunViewGraph ReadRunViewGraph(const std::filesystem::path& path);

}  // namespace sfm_pruning
