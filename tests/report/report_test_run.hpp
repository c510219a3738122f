// A small run folder written without running an engine: cameras on a ring looking at a cloud of
// points, a view graph with two subgraphs and removed edges between them, timings.
#pragma once

#include <filesystem>

#include "sfm_pruning/report/run_view_graph.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning::testing {

// `num_views` cameras on a circle of radius 4 around the origin (z up), looking at it, sharing
// one pinhole intrinsic (640 x 480, f = 500); 200 points near the origin observed by every
// camera that sees them. `radial_k1` != 0 gives a pinhole_radial_k3 camera instead.
SfmData RingScene(int num_views, double radial_k1 = 0.0);

// Views split into two halves (subgraphs 0 and 1); edges between neighbours on the ring, the
// edges joining the two halves removed.
RunViewGraph TwoSubgraphGraph(const SfmData& scene);

// Writes sfm_data.json, view_graph.json and timings.json of `scene` into `dir`.
void WriteTestRun(const SfmData& scene, const std::string& engine, const std::filesystem::path& dir);

}  // namespace sfm_pruning::testing
