// sequential_large: the pair structure (sliding window + loop closures) at 1,000 views.
#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_scene.hpp"

namespace sfm_pruning {
namespace {

TEST(SyntheticSequential, ThousandViewsHaveWindowAndLoopPairs) {
  SyntheticSceneOptions options;
  options.scene = "sequential_large";
  options.num_views = 1000;
  options.seed = 11;
  options.point_density_scale = 0.35;  // fewer points per view keeps the test fast
  options.num_threads = 2;
  const SyntheticScene scene = GenerateSyntheticScene(options);
  const int window = scene.options.sequential_window;
  ASSERT_EQ(window, 5);
  ASSERT_EQ(scene.ground_truth.views.size(), 1000u);
  const IndexT views_per_lap = 500;  // two laps by default

  size_t window_pairs = 0, consecutive = 0, loop_pairs = 0, true_loops = 0, false_loops = 0;
  size_t twin_dominated_window_pairs = 0, misplaced_true_loops = 0;
  std::set<IndexT> views_with_true_loop;
  for (const auto& [pair, stats] : scene.pair_stats) {
    const IndexT gap = pair.second - pair.first;
    if (gap <= static_cast<IndexT>(window)) {
      ++window_pairs;
      consecutive += gap == 1;
      twin_dominated_window_pairs += stats.num_twin >= stats.num_true;
      continue;
    }
    ++loop_pairs;
    EXPECT_GE(gap, 50u);  // loop_min_gap
    if (stats.num_true >= 15) {
      ++true_loops;
      // A true loop closure links the two laps at one place, or closes the lap at its start.
      const bool across_laps = (pair.first < views_per_lap) != (pair.second < views_per_lap);
      const bool lap_end = (pair.first % views_per_lap) < 20 && (pair.second % views_per_lap) >= views_per_lap - 20;
      misplaced_true_loops += !(across_laps || lap_end);
      if (across_laps) views_with_true_loop.insert(pair.second);
    }
    if (stats.num_twin > stats.num_true) ++false_loops;
  }
  // Consecutive views always overlap enough to keep their pair.
  EXPECT_GE(consecutive, 995u);
  // Pairs up to 5 frames apart overlap by half a view or more; a few fall under min_matches at
  // this reduced density.
  EXPECT_GE(window_pairs, 4500u);
  EXPECT_EQ(twin_dominated_window_pairs, 0u);
  EXPECT_EQ(misplaced_true_loops, 0u);
  // Loop closures: most views of the second lap are linked to the first.
  EXPECT_GT(views_with_true_loop.size(), 400u);
  // The repeated facades make retrieval propose false loops too (twin-dominated pairs).
  EXPECT_GT(false_loops, 20u);
  EXPECT_GT(loop_pairs, true_loops);
}

}  // namespace
}  // namespace sfm_pruning
