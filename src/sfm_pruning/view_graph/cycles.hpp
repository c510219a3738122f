// Bounded, deterministic cycle enumeration for the loop-consistency test (METHOD.md §3: loops
// of fewer than 8 cameras must compose to nearly the identity rotation).
//
// Enumerating every simple cycle explodes on dense graphs, so the search is:
//   1. for every valid edge (a, b), in ViewPair order, the shortest path from a to b that does
//      not use the edge itself (BFS from a, neighbours in increasing id, stopped at depth
//      max_cycle_length - 1). With the edge it closes the tightest loop of at most
//      max_cycle_length cameras through that edge. At most E loops; cost O(E * (V + E)) in the
//      worst case, far less in practice because each BFS stops at the target or the depth bound.
//   2. every triangle, exactly: for each valid edge (a, b), a < b, each common neighbour c > b.
//      Cost O(E * d_max) (sorted adjacency intersection), d_max the largest degree.
// Step 1 comes first because it is what guarantees coverage: every edge that lies on some loop
// of <= max_cycle_length cameras is tested by at least one loop, even when triangles (which can
// number O(E * d_max) on dense graphs) would fill the cap. Not every such loop is listed.
// Duplicates (a triangle found again in step 2) are removed through a canonical form.
// Enumeration stops once max_num_cycles loops are listed.
#pragma once

#include <cstddef>
#include <vector>

#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// A closed loop of distinct views c0 -> c1 -> ... -> c_{l-1} -> c0 along valid edges.
// Canonical form: starts at its smallest id, then goes towards the smaller of that node's
// two cycle neighbours.
using ViewCycle = std::vector<IndexT>;

struct CycleSearchOptions {
  // Longest loop, in cameras (= edges). The paper tests loops of fewer than 8 cameras.
  size_t max_cycle_length = 7;
  // Stop after this many cycles (per-edge shortest loops first); CycleSearchResult::truncated.
  size_t max_num_cycles = 100000;
  bool include_shortest_alternatives = true;  // step 1
  bool include_triangles = true;              // step 2

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct CycleSearchResult {
  // Canonical cycles in discovery order: the step-1 loops in the order of the edge that produced
  // them, then the triangles not yet listed, in ViewPair order of their first edge.
  std::vector<ViewCycle> cycles;
  size_t num_triangles = 0;  // loops of 3 views in `cycles`, whichever step found them
  bool truncated = false;    // true when max_num_cycles stopped the search
};

CycleSearchResult FindBoundedCycles(const ViewGraph& graph, const CycleSearchOptions& options = {});

// Angle in degrees of R_{c_{l-1} c_0} ... R_{c_1 c_2} R_{c_0 c_1}, the relative rotations
// composed around the loop (oriented with ViewGraph::OrientedRelativePose). 0 for perfectly
// consistent relative rotations. Throws std::out_of_range when a loop edge is missing and
// std::invalid_argument for a loop of fewer than 2 views.
double LoopRotationErrorDeg(const ViewGraph& graph, const ViewCycle& cycle);

// The paper's tolerance for a loop of `num_cameras` cameras: step_deg * floor((l - 1) / 2),
// i.e. 5° for 3-4 cameras, 10° for 5-6, 15° for 7.
double LoopRotationThresholdDeg(size_t num_cameras, double step_deg = 5.0);

}  // namespace sfm_pruning
