// Building blocks of the synthetic scenes: SIFT-like descriptors, the brute-force matcher, the
// pair selection and the injection of wrong matches.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_descriptors.hpp"
#include "sfm_pruning/eval/synthetic_matching.hpp"
#include "sfm_pruning/eval/synthetic_pairs.hpp"

namespace sfm_pruning {
namespace {

TEST(SyntheticDescriptors, LookLikeSift) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 100; ++k) {
    const Descriptor d = ObserveDescriptor(RandomDescriptorHistogram(rng), 0.25, rng);
    double norm2 = 0.0;
    int zeros = 0, max_value = 0;
    for (uint8_t v : d) norm2 += double(v) * v, zeros += v == 0, max_value = std::max<int>(max_value, v);
    // Unit norm scaled by 512 (rounding moves it a little), clipped at 0.2 * 512 before the
    // second normalisation, so no byte is far above ~0.2-0.3 of 512.
    EXPECT_NEAR(std::sqrt(norm2), 512.0, 6.0);
    EXPECT_LE(max_value, 160);
    EXPECT_GT(zeros, 10);  // sparse, as real gradient histograms
  }
}

TEST(SyntheticDescriptors, RatioTestSeparatesSightingsFromOtherPoints) {
  std::mt19937_64 rng(9);
  int passed = 0;
  for (int k = 0; k < 200; ++k) {
    const DescriptorHistogram base = RandomDescriptorHistogram(rng);
    const Descriptor a = ObserveDescriptor(base, 0.25, rng);
    const Descriptor b = ObserveDescriptor(base, 0.25, rng);
    const Descriptor other = ObserveDescriptor(RandomDescriptorHistogram(rng), 0.25, rng);
    const double same = std::sqrt(SquaredDescriptorDistance(a, b));
    const double different = std::sqrt(SquaredDescriptorDistance(a, other));
    passed += same < 0.8 * different;
  }
  EXPECT_GE(passed, 195);
}

FeatureSet MakeSet(const std::vector<Descriptor>& descriptors) {
  FeatureSet set;
  set.descriptors = descriptors;
  set.keypoints.resize(descriptors.size());
  return set;
}

Descriptor Filled(uint8_t value, int first_bins = kDescriptorSize) {
  Descriptor d{};
  for (int k = 0; k < first_bins; ++k) d[k] = value;
  return d;
}

TEST(SyntheticMatching, RatioTestAndMutualCheck) {
  // a0 matches b0 clearly; a1 sits halfway between b1 and b2 (ambiguous: ratio test rejects);
  // a2 and a3 both prefer b3, which prefers a3 (mutual check keeps only a3 -> b3).
  const FeatureSet a = MakeSet({Filled(10), Filled(100, 64), Filled(200, 100), Filled(200, 110)});
  const FeatureSet b = MakeSet({Filled(11), Filled(90, 64), Filled(110, 64), Filled(200, 112)});
  const std::vector<FeatureMatch> mutual = MatchDescriptorsBruteForce(a, b, 0.8, true);
  ASSERT_EQ(mutual.size(), 2u);
  EXPECT_EQ(mutual[0], (FeatureMatch{0, 0}));
  EXPECT_EQ(mutual[1], (FeatureMatch{3, 3}));
  const std::vector<FeatureMatch> one_way = MatchDescriptorsBruteForce(a, b, 0.8, false);
  ASSERT_EQ(one_way.size(), 3u);
  EXPECT_EQ(one_way[1], (FeatureMatch{2, 3}));
}

TEST(SyntheticMatching, InjectionReachesTheRatioWithOneToOneWrongMatches) {
  // 100 features per view; features k < 60 observe landmark k in both views, the rest clutter.
  std::vector<IndexT> la(100, kUndefinedIndex), lb(100, kUndefinedIndex);
  std::map<IndexT, IndexT> appearance;
  std::vector<FeatureMatch> matches;
  for (IndexT k = 0; k < 60; ++k) la[k] = lb[k] = k, appearance[k] = k;
  for (IndexT k = 0; k < 40; ++k) matches.push_back({k, k});
  const MatchTruth truth{&la, &lb, &appearance};
  const PairMatchStats before = ClassifyMatches(matches, truth);
  ASSERT_EQ(before.num_true, 40u);
  std::mt19937_64 rng(1);
  const size_t added = InjectRandomWrongMatches(before, 0.2, 100, 100, truth, rng, &matches);
  EXPECT_EQ(added, 10u);  // 10 / (40 + 10) = 0.2
  const PairMatchStats after = ClassifyMatches(matches, truth);
  EXPECT_EQ(after.num_true, 40u);
  EXPECT_EQ(after.num_random, 10u);
  std::set<IndexT> used_i, used_j;
  for (const FeatureMatch& m : matches) {
    EXPECT_TRUE(used_i.insert(m.i).second);
    EXPECT_TRUE(used_j.insert(m.j).second);
  }
  EXPECT_TRUE(std::is_sorted(matches.begin(), matches.end(),
                             [](const FeatureMatch& x, const FeatureMatch& y) { return x.i < y.i; }));
}

TEST(SyntheticPairs, WindowPlusDistinctRetrievalCandidates) {
  // 12 views. Views 0-1 and 9-10 see appearances 0..29 (one place, visited twice); every view
  // also sees its own 20 appearances.
  std::vector<std::vector<IndexT>> seen(12);
  for (IndexT v = 0; v < 12; ++v) {
    for (IndexT a = 0; a < 20; ++a) seen[v].push_back(100 + 20 * v + a);
  }
  for (IndexT v : {0u, 1u, 9u, 10u}) {
    for (IndexT a = 0; a < 30; ++a) seen[v].push_back(a);
  }
  const std::vector<ViewPair> pairs = SequentialAndRetrievalPairs(seen, 400, 2, 5, 3, 15);
  const std::set<ViewPair> set(pairs.begin(), pairs.end());
  for (IndexT i = 0; i + 1 < 12; ++i) EXPECT_TRUE(set.count({i, i + 1}));
  for (IndexT i = 0; i + 2 < 12; ++i) EXPECT_TRUE(set.count({i, i + 2}));
  EXPECT_FALSE(set.count({0, 3}));
  EXPECT_FALSE(set.count({1, 5}));  // within the loop gap: never a loop candidate
  // View 0 ranks 9 and 10 equally (one place): only the lower id is proposed from view 0, but
  // view 10 proposes 0 from its own side (also one place: 0 and 1, lower id).
  EXPECT_TRUE(set.count({0, 9}));
  EXPECT_TRUE(set.count({0, 10}));
  EXPECT_TRUE(set.count({1, 9}));
  EXPECT_EQ(ExhaustivePairs(5).size(), 10u);
}

}  // namespace
}  // namespace sfm_pruning
