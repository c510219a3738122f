// The image pairs a synthetic scene matches: what a real pipeline's pair selection would give.
#pragma once

#include <map>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"

namespace sfm_pruning {

// Every pair of views 0 .. num_views-1, ordered.
std::vector<ViewPair> ExhaustivePairs(IndexT num_views);

// Sequential pairs (i, i+1 .. i+window) plus, for every view, up to `num_candidates` views at
// least `min_loop_gap` frames away ranked by the number of appearance ids both see (ties to the
// lower id), if they share at least `min_shared`, keeping one view per place (candidates within
// `window` of a better one are skipped). The gap keeps retrieval from re-proposing the recent
// frames, which the window already pairs, as loop detectors do. Ranking by shared appearance is what a vocabulary tree
// does: it proposes true loop closures and, through duplicate structure, false ones.
// `view_appearances` lists, per view 0 .. n-1, the appearance ids of its detected points.
std::vector<ViewPair> SequentialAndRetrievalPairs(const std::vector<std::vector<IndexT>>& view_appearances,
                                                  IndexT num_appearances, int window, int min_loop_gap,
                                                  int num_candidates, int min_shared);

}  // namespace sfm_pruning
