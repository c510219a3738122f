// Duplicate structure and putative matches of synthetic scenes, judged against the truth.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_descriptors.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"

namespace sfm_pruning {
namespace {

SyntheticSceneOptions SmallOptions(const std::string& scene) {
  SyntheticSceneOptions options;
  options.scene = scene;
  options.seed = 3;
  options.num_views = 12;
  options.point_density_scale = 0.4;
  return options;
}

// Independent re-classification of a pair's matches from the scene's truth tables.
PairMatchStats Recount(const SyntheticScene& scene, const ViewPair& pair) {
  PairMatchStats stats;
  const std::vector<IndexT>& la = scene.feature_landmarks.at(pair.first);
  const std::vector<IndexT>& lb = scene.feature_landmarks.at(pair.second);
  for (const FeatureMatch& m : scene.putative_matches.at(pair)) {
    const IndexT a = la.at(m.i), b = lb.at(m.j);
    if (a != kUndefinedIndex && a == b) ++stats.num_true;
    else if (a != kUndefinedIndex && b != kUndefinedIndex &&
             scene.landmark_appearance.at(a) == scene.landmark_appearance.at(b)) ++stats.num_twin;
    else ++stats.num_random;
  }
  return stats;
}

// Angle between the horizontal viewing directions (headings) of two views, degrees.
double HeadingAngleDeg(const SyntheticScene& scene, IndexT a, IndexT b) {
  Eigen::Vector3d da = scene.ground_truth.poses.at(a).ViewingDirection();
  Eigen::Vector3d db = scene.ground_truth.poses.at(b).ViewingDirection();
  da.z() = db.z() = 0.0;
  return RadToDeg(AngleBetweenVectors(da, db));
}

TEST(SyntheticDuplicates, TwinsShareOneBaseDescriptor) {
  const SyntheticScene scene = GenerateSyntheticScene(SmallOptions("orbit_symmetric"));
  ASSERT_FALSE(scene.twin_landmarks.empty());
  // Descriptors of one view's observations, per landmark.
  std::map<IndexT, std::vector<const Descriptor*>> seen;
  for (const auto& [view, landmarks] : scene.feature_landmarks) {
    for (size_t f = 0; f < landmarks.size(); ++f) {
      if (landmarks[f] != kUndefinedIndex) seen[landmarks[f]].push_back(&scene.features.at(view).descriptors[f]);
    }
  }
  // Mean squared distance between observations of one landmark, of twin copies, of unrelated points.
  double same = 0, twin = 0, unrelated = 0;
  size_t n_same = 0, n_twin = 0, n_unrelated = 0;
  std::map<IndexT, std::vector<IndexT>> by_appearance;
  for (const auto& [landmark, descriptors] : seen) by_appearance[scene.landmark_appearance.at(landmark)].push_back(landmark);
  const Descriptor* previous = nullptr;
  for (const auto& [appearance, landmarks] : by_appearance) {
    const Descriptor* first = seen[landmarks[0]][0];
    if (seen[landmarks[0]].size() > 1) same += SquaredDescriptorDistance(*first, *seen[landmarks[0]][1]), ++n_same;
    if (landmarks.size() > 1) {
      EXPECT_TRUE(scene.twin_landmarks.count(landmarks[0]) && scene.twin_landmarks.count(landmarks[1]));
      twin += SquaredDescriptorDistance(*first, *seen[landmarks[1]][0]), ++n_twin;
    }
    if (previous) unrelated += SquaredDescriptorDistance(*first, *previous), ++n_unrelated;
    previous = first;
  }
  ASSERT_GT(n_twin, 50u);
  ASSERT_GT(n_same, 50u);
  same /= n_same, twin /= n_twin, unrelated /= n_unrelated;
  // Twin copies look exactly as alike as two sightings of one point, and far closer than others.
  EXPECT_NEAR(twin / same, 1.0, 0.15);
  EXPECT_LT(twin, 0.35 * unrelated);
}

TEST(SyntheticDuplicates, StatsMatchAnIndependentRecount) {
  const SyntheticScene scene = GenerateSyntheticScene(SmallOptions("street"));
  ASSERT_EQ(scene.pair_stats.size(), scene.putative_matches.size());
  for (const auto& [pair, matches] : scene.putative_matches) {
    const PairMatchStats expected = Recount(scene, pair);
    const PairMatchStats& stats = scene.pair_stats.at(pair);
    EXPECT_EQ(stats.num_true, expected.num_true);
    EXPECT_EQ(stats.num_twin, expected.num_twin);
    EXPECT_EQ(stats.num_random, expected.num_random);
    EXPECT_EQ(stats.total(), matches.size());
    EXPECT_GE(matches.size(), 15u);
  }
}

// Opposite views of the symmetric object see the same picture: most of their matches are wrong.
TEST(SyntheticDuplicates, OppositeViewsOfTheSymmetricObjectMatchWrongly) {
  const SyntheticScene scene = GenerateSyntheticScene(SmallOptions("orbit_symmetric"));
  size_t opposite_true = 0, opposite_false = 0, near_true = 0, near_false = 0;
  for (const auto& [pair, stats] : scene.pair_stats) {
    const double angle = HeadingAngleDeg(scene, pair.first, pair.second);
    if (angle > 150.0) opposite_true += stats.num_true, opposite_false += stats.num_false();
    if (angle < 40.0) near_true += stats.num_true, near_false += stats.num_false();
  }
  ASSERT_GT(opposite_true + opposite_false, 100u);
  EXPECT_GT(static_cast<double>(opposite_false) / (opposite_true + opposite_false), 0.6);
  // Neighbouring views: false matches only from the outlier ratio (20 %) and little else.
  EXPECT_LT(static_cast<double>(near_false) / (near_true + near_false), 0.3);
}

TEST(SyntheticDuplicates, CourtyardWallsConfuseViewsAQuarterTurnApart) {
  SyntheticSceneOptions options = SmallOptions("courtyard");
  options.num_views = 16;
  const SyntheticScene scene = GenerateSyntheticScene(options);
  size_t quarter_twin = 0, quarter_total = 0;
  for (const auto& [pair, stats] : scene.pair_stats) {
    const double angle = HeadingAngleDeg(scene, pair.first, pair.second);
    if (std::abs(angle - 90.0) < 20.0) quarter_twin += stats.num_twin, quarter_total += stats.total();
  }
  ASSERT_GT(quarter_total, 100u);
  EXPECT_GT(static_cast<double>(quarter_twin) / quarter_total, 0.5);
}

TEST(SyntheticDuplicates, CleanSceneHasNoTwinsAndTheRequestedOutlierRatio) {
  // Up to about 0.4: injected matches are one-to-one between unmatched features, and at higher
  // ratios pairs whose features are mostly matched run out of free ones.
  for (const double ratio : {0.0, 0.2, 0.35}) {
    SyntheticSceneOptions options = SmallOptions("clean");
    options.outlier_ratio = ratio;
    const SyntheticScene scene = GenerateSyntheticScene(options);
    EXPECT_TRUE(scene.twin_landmarks.empty());
    size_t num_true = 0, total = 0;
    for (const auto& [pair, stats] : scene.pair_stats) {
      EXPECT_EQ(stats.num_twin, 0u);
      num_true += stats.num_true;
      total += stats.total();
    }
    ASSERT_GT(total, 1000u);
    // Per pair the count is rounded, so the aggregate is within a fraction of a percent.
    EXPECT_NEAR(static_cast<double>(num_true) / total, 1.0 - ratio, 0.01)
        << "outlier_ratio " << ratio << " true " << num_true << " of " << total;
  }
}

TEST(SyntheticDuplicates, PairsBelowMinMatchesAreDropped) {
  SyntheticSceneOptions options = SmallOptions("street");
  options.min_matches = 60;
  const SyntheticScene scene = GenerateSyntheticScene(options);
  for (const auto& [pair, stats] : scene.pair_stats) {
    // The threshold applies to the descriptor matches, before injection.
    EXPECT_GE(stats.total() - stats.num_injected, 60u);
  }
}

}  // namespace
}  // namespace sfm_pruning
