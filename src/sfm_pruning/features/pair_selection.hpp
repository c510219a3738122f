// Which image pairs to match: all of them, a sliding window over the image order (video, a
// walk), or a list from a file (OpenMVG pair list, e.g. from image retrieval).
#pragma once

#include <filesystem>
#include <vector>

#include "sfm_pruning/io/pair_list.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

// Every pair of distinct views.
PairSet ExhaustivePairs(const std::vector<IndexT>& view_ids);

// Each view with the next `window` views of `ordered_view_ids` (image order). When `close_loop`,
// the first `window` views are also paired with the last ones, as for a ring of images.
// Throws Error when window < 1.
PairSet SequentialPairs(const std::vector<IndexT>& ordered_view_ids, int window, bool close_loop = false);

// The pairs of an OpenMVG pair list whose views both exist in `scene` (view ids are the indices
// of the list). Throws Error naming the file for a malformed list, one naming a view id absent
// from the scene, or an empty result.
PairSet PairsFromList(const std::filesystem::path& path, const SfmData& scene);

// The view ids of `scene` in id order (= image order for a scene made by `prunesfm init`).
std::vector<IndexT> ViewIdsInOrder(const SfmData& scene);

}  // namespace sfm_pruning
