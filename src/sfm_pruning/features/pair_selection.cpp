#include "sfm_pruning/features/pair_selection.hpp"

#include <algorithm>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {

PairSet ExhaustivePairs(const std::vector<IndexT>& view_ids) {
  PairSet pairs;
  for (size_t a = 0; a < view_ids.size(); ++a) {
    for (size_t b = a + 1; b < view_ids.size(); ++b) {
      if (view_ids[a] == view_ids[b]) continue;
      pairs.insert({std::min(view_ids[a], view_ids[b]), std::max(view_ids[a], view_ids[b])});
    }
  }
  return pairs;
}

PairSet SequentialPairs(const std::vector<IndexT>& ordered_view_ids, int window, bool close_loop) {
  if (window < 1) throw Error("sequential pairs: the window must be at least 1, got " + std::to_string(window));
  PairSet pairs;
  const size_t n = ordered_view_ids.size();
  // A window as long as the sequence already pairs everything; longer would wrap past itself.
  const size_t w = std::min(static_cast<size_t>(window), n == 0 ? size_t{0} : n - 1);
  for (size_t a = 0; a < n; ++a) {
    for (size_t step = 1; step <= w; ++step) {
      size_t b = a + step;
      if (b >= n) {
        if (!close_loop) break;
        b -= n;
      }
      const IndexT i = ordered_view_ids[a];
      const IndexT j = ordered_view_ids[b];
      if (i != j) pairs.insert({std::min(i, j), std::max(i, j)});
    }
  }
  return pairs;
}

PairSet PairsFromList(const std::filesystem::path& path, const SfmData& scene) {
  const IndexT max_id = scene.views.empty() ? 0 : scene.views.rbegin()->first;
  const PairSet listed = ReadPairList(path, static_cast<size_t>(max_id) + 1);
  PairSet pairs;
  for (const ViewPair& pair : listed) {
    for (const IndexT id : {pair.first, pair.second}) {
      if (scene.views.count(id) == 0) {
        throw FileError(path.string(), "pair " + std::to_string(pair.first) + " " + std::to_string(pair.second) +
                                           " names view " + std::to_string(id) + ", which is not in the scene");
      }
    }
    pairs.insert(pair);
  }
  if (pairs.empty()) throw FileError(path.string(), "the pair list holds no pair");
  return pairs;
}

std::vector<IndexT> ViewIdsInOrder(const SfmData& scene) {
  std::vector<IndexT> ids;
  ids.reserve(scene.views.size());
  for (const auto& [view_id, view] : scene.views) ids.push_back(view_id);
  return ids;
}

}  // namespace sfm_pruning
