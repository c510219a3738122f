// The view graph panels of the report (the paper's partition figure): nodes placed by a seeded
// force-directed layout of the graph *after* pruning, so that the accepted subgraphs fall apart
// into clusters and the removed edges show up as long red chords between them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/report/run_view_graph.hpp"

namespace sfm_pruning {

// One position per entry of graph.views, in [0, 1]^2. Springs: the kept edges, weighted by
// log(1 + inliers).
std::vector<Eigen::Vector2d> LayoutRunViewGraph(const RunViewGraph& graph, uint64_t seed);

enum class ViewGraphPanel {
  kBeforePruning,  // every verified edge in grey
  kAfterPruning,   // kept edges (in the subgraph colour inside a subgraph); removed edges dashed red, one
                   // bundle per pair of subgraphs (removal_summary.hpp)
};

// An SVG of `size` x `size` user units. Nodes are coloured by subgraph in both panels; every
// node and edge has a tooltip (image names, inliers, the reason of a cut).
std::string DrawViewGraphSvg(const RunViewGraph& graph, const std::vector<Eigen::Vector2d>& layout,
                             ViewGraphPanel panel, double size = 520.0);

}  // namespace sfm_pruning
