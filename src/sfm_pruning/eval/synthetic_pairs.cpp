#include "sfm_pruning/eval/synthetic_pairs.hpp"

#include <algorithm>
#include <set>

namespace sfm_pruning {

std::vector<ViewPair> ExhaustivePairs(IndexT num_views) {
  std::vector<ViewPair> pairs;
  for (IndexT i = 0; i < num_views; ++i) {
    for (IndexT j = i + 1; j < num_views; ++j) pairs.emplace_back(i, j);
  }
  return pairs;
}

std::vector<ViewPair> SequentialAndRetrievalPairs(const std::vector<std::vector<IndexT>>& view_appearances,
                                                  IndexT num_appearances, int window, int min_loop_gap,
                                                  int num_candidates, int min_shared) {
  const auto num_views = static_cast<IndexT>(view_appearances.size());
  std::set<ViewPair> pairs;
  for (IndexT i = 0; i < num_views; ++i) {
    for (IndexT j = i + 1; j < num_views && j <= i + static_cast<IndexT>(window); ++j) pairs.insert({i, j});
  }

  // Each view counts an appearance once (it may see several twins of it), and an inverted
  // index appearance -> views that see it.
  std::vector<std::vector<IndexT>> unique_appearances(num_views);
  std::vector<std::vector<IndexT>> viewers(num_appearances);
  for (IndexT v = 0; v < num_views; ++v) {
    std::vector<IndexT>& unique = unique_appearances[v];
    unique = view_appearances[v];
    std::sort(unique.begin(), unique.end());
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    for (IndexT a : unique) viewers[a].push_back(v);
  }

  std::vector<int> score(num_views, 0);
  std::vector<IndexT> touched;
  for (IndexT i = 0; i < num_views; ++i) {
    touched.clear();
    for (IndexT a : unique_appearances[i]) {
      for (IndexT j : viewers[a]) {
        const IndexT gap = i > j ? i - j : j - i;
        if (gap < static_cast<IndexT>(std::max(window + 1, min_loop_gap))) continue;
        if (score[j]++ == 0) touched.push_back(j);
      }
    }
    std::sort(touched.begin(), touched.end(), [&](IndexT a, IndexT b) {
      return score[a] != score[b] ? score[a] > score[b] : a < b;
    });
    // Distinct places only: a candidate within `window` of one already chosen is the same place
    // seen a frame later (the temporal suppression loop detectors apply).
    std::vector<IndexT> chosen;
    for (size_t k = 0; k < touched.size() && chosen.size() < static_cast<size_t>(num_candidates); ++k) {
      const IndexT j = touched[k];
      if (score[j] < min_shared) break;
      const bool same_place = std::any_of(chosen.begin(), chosen.end(), [&](IndexT c) {
        return (c > j ? c - j : j - c) <= static_cast<IndexT>(window);
      });
      if (same_place) continue;
      chosen.push_back(j);
      pairs.insert(MakeViewPair(i, j));
    }
    for (IndexT j : touched) score[j] = 0;
  }
  return {pairs.begin(), pairs.end()};
}

}  // namespace sfm_pruning
