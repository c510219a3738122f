// What the pruning removed, in words: the removed edges of a run's view graph grouped by the
// reason and measure of their cut, and by the pair of accepted subgraphs they joined. The report
// leads its view-graph section with it (html_report.cpp) and draws one bundle per subgraph pair
// (view_graph_drawing.cpp) instead of one dashed chord per edge.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sfm_pruning/report/run_view_graph.hpp"

namespace sfm_pruning {

// The removed edges that share a reason and a measure.
struct RemovalGroup {
  std::string reason;   // EdgeInvalidReasonName
  std::string measure;  // EdgeMeasureName ("" in files that did not record it)
  size_t edges = 0;
  size_t subgraph_pairs = 0;  // distinct pairs of accepted subgraphs among them
  double median_value = 0.0;
  double median_threshold = 0.0;
};

// The verified edges between two accepted subgraphs a < b (or, with a = b = -1, the edges with an
// end outside the partition).
struct SubgraphPairRemovals {
  int a = -1;
  int b = -1;
  size_t removed = 0;
  size_t kept = 0;
  RemovalGroup main;  // the reason that removed most of its edges (its counts over this pair only)
};

struct RemovalSummary {
  size_t edges = 0;    // verified edges before pruning
  size_t removed = 0;  // of them removed
  std::vector<RemovalGroup> groups;        // most edges first, then by reason name
  std::vector<SubgraphPairRemovals> pairs;  // pairs with at least one removed edge, most removed first
};

RemovalSummary SummariseRemovals(const RunViewGraph& graph);

// What a reason means, completing "N edges were removed because ...", e.g. "their two subgraphs'
// alignment (the inter-subgraph RANSAC) placed them elsewhere". Unknown names are returned as they are.
std::string RemovalReasonInWords(const std::string& reason);

// A value of `measure` (of a cut for `reason`) with its unit: "12.3°", "0.41 × the loop's mean
// side", "35 %" ("" measure: the bare number).
std::string MeasureValueInWords(const std::string& reason, const std::string& measure, double value);

// One line for a group: "median 12.3° off, allowed 5°" ("median 3 broken subgraph triangles
// against 1 closing", ...).
std::string GroupMeasureInWords(const RemovalGroup& group);

}  // namespace sfm_pruning
