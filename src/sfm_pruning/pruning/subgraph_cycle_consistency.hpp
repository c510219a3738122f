// The second pass of the loop check between subgraphs (subgraph_loop_consistency.hpp runs it after
// the triangles): cycles of four or more subgraphs. PruneSfM's addition (docs/pruning.md).
//
// Why: the triangle pass cuts a pair whose transform breaks more triangles than it closes. Two
// doppelganger pairs that share their twin shift close a triangle with the clean pair between
// their far ends (real street: {0012–0015}×{0000–0004}, {0016–0018}×{0000–0004} and
// {0012–0015}×{0016–0018}), and once the triangle pass has cut the other pairs through them no
// triangle is left to refute them. Only the longer way round, through the subgraphs in between,
// does. On such a cycle counting cannot say which pair is wrong (every pair on it lies in the
// same broken cycle); the match coverage can: a twin transform places the views of one subgraph
// where they should re-detect far more of the other's landmarks than they do.
//
// The cycles are the fundamental cycles of a maximum spanning forest of the remaining links
// (weight: the link's coverage, then its support): each link outside the forest closes one
// cycle with the forest path between its ends, so the number of cycles is bounded by the number
// of links and each is found in linear time. A cycle is judged when it has 4..max_cycle_length
// subgraphs and no chord among the remaining links (a cycle with a chord is made of smaller
// cycles, which are judged themselves; triangles are the first pass's). Its loop
// T_{c0←c1} · … · T_{c(l−1)←c0} is compared to the identity with the triangle bounds widened by
// the paper's loop factor ⌊(l − 1) / 2⌋ (rotation and translation fraction multiplied by it,
// scale ratio raised to it); the translation is c0's centre displacement over the mean distance
// between consecutive subgraph centres along the cycle (at least c0's radius). A broken cycle
// loses its link of lowest coverage (ties: smaller support, then the later link); the forest is
// then rebuilt and the search starts again, so the pass ends after at most one cut per link.
// Removing one link of a cycle never disconnects the subgraphs.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"

namespace sfm_pruning {

// A forest of subgraphs: per subgraph, (neighbour, index of the link or pair joining them).
using ForestAdjacency = std::vector<std::vector<std::pair<int, size_t>>>;

// The forest path from `from` to `to` (both ends included; empty if they are not connected) and
// the links along it.
std::pair<std::vector<int>, std::vector<size_t>> ForestPath(const ForestAdjacency& forest, int from, int to);

// The paper's loop factor of a cycle of `length` subgraphs: ⌊(length − 1) / 2⌋, at least 1.
size_t CycleLoopFactor(size_t length);

// The triangle bounds widened by a cycle's loop factor: rotation and translation fraction
// multiplied by it, scale ratio raised to it.
struct CycleBounds {
  double rotation_deg = 0.0;
  double scale_ratio = 1.0;
  double translation_fraction = 0.0;
};
CycleBounds WidenedCycleBounds(size_t loop_factor, const SubgraphLoopOptions& options);

// The loop of a cycle c0 -> c1 -> ... -> c(l-1) -> c0 of subgraphs; `to_previous[k]` is the
// transform from c(k+1)'s frame into c(k)'s (the last one from c0's into c(l-1)'s).
SubgraphCycle MeasureSubgraphCycle(const std::vector<int>& subgraphs, const std::vector<Similarity3>& to_previous,
                                   const std::vector<SubgraphFrame>& frames, const SubgraphLoopOptions& options);

// Cuts links of `active` (indexed like `links`) that break a longer cycle; appends the measured
// cycles to result->cycles and the cuts to result->rejected.
void RejectCycleInconsistentLinks(const std::vector<SubgraphLink>& links, const std::vector<SubgraphFrame>& frames,
                                  const SubgraphLoopOptions& options, std::vector<bool>* active,
                                  SubgraphLoopResult* result);

}  // namespace sfm_pruning
