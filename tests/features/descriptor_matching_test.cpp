// Descriptor matching on synthetic descriptors with a known correspondence: both matchers find
// it, the ratio test drops ambiguous features, the mutual check drops one-sided matches, and the
// result does not depend on the number of threads.
#include <gtest/gtest.h>

#include <random>

#include "sfm_pruning/features/descriptor_matching.hpp"

namespace sfm_pruning::testing {
namespace {

Descriptor RandomDescriptor(std::mt19937& rng) {
  std::uniform_int_distribution<int> value(0, 120);
  Descriptor d{};
  for (auto& v : d) v = static_cast<uint8_t>(value(rng));
  return d;
}

Descriptor Perturbed(const Descriptor& d, std::mt19937& rng, int amplitude) {
  std::uniform_int_distribution<int> noise(-amplitude, amplitude);
  Descriptor out = d;
  for (auto& v : out) v = static_cast<uint8_t>(std::clamp(v + noise(rng), 0, 255));
  return out;
}

// View 0: 300 features. View 1: feature k of view 0 appears at (7 k) mod 300 perturbed, and the
// first 20 features of view 0 appear twice in view 1 (ambiguous: the ratio test must drop them).
FeaturesPerView TwoViews() {
  std::mt19937 rng(3);
  FeaturesPerView features;
  FeatureSet& a = features[0];
  FeatureSet& b = features[1];
  for (int k = 0; k < 300; ++k) a.descriptors.push_back(RandomDescriptor(rng));
  b.descriptors.resize(320);
  for (int k = 0; k < 300; ++k) b.descriptors[static_cast<size_t>((7 * k) % 300)] = Perturbed(a.descriptors[k], rng, 4);
  for (int k = 0; k < 20; ++k) b.descriptors[300 + static_cast<size_t>(k)] = Perturbed(a.descriptors[k], rng, 4);
  a.keypoints.resize(a.descriptors.size());
  b.keypoints.resize(b.descriptors.size());
  return features;
}

void ExpectPermutationFound(const PairwiseMatches& result) {
  ASSERT_EQ(result.count({0, 1}), 1u);
  const std::vector<FeatureMatch>& matches = result.at({0, 1});
  EXPECT_EQ(matches.size(), 280u);
  for (const FeatureMatch& m : matches) {
    EXPECT_GE(m.i, 20u);
    EXPECT_EQ(m.j, (7 * m.i) % 300);
  }
}

TEST(DescriptorMatching, BruteForceFindsTheCorrespondenceAndDropsAmbiguousFeatures) {
  DescriptorMatchingOptions options;
  options.matcher = DescriptorMatcher::kBruteForce;
  ExpectPermutationFound(MatchDescriptors(TwoViews(), {{0, 1}}, options));
}

TEST(DescriptorMatching, FlannFindsTheSameMatches) {
  DescriptorMatchingOptions options;
  options.matcher = DescriptorMatcher::kFlann;
  options.flann_checks = 256;
  ExpectPermutationFound(MatchDescriptors(TwoViews(), {{0, 1}}, options));
}

TEST(DescriptorMatching, MutualCheckDropsOneSidedMatches) {
  // View 1 holds one copy of a feature of view 0 and nothing else near: both directions agree.
  // View 2 holds two nearby copies of feature 0 of view 0 and of nothing else: 0 -> both fails
  // the ratio test, and neither copy's back match is unique, so nothing survives.
  FeaturesPerView features = TwoViews();
  std::mt19937 rng(5);
  FeatureSet& c = features[2];
  c.descriptors = {Perturbed(features[0].descriptors[0], rng, 2), Perturbed(features[0].descriptors[0], rng, 2)};
  for (int k = 0; k < 40; ++k) c.descriptors.push_back(RandomDescriptor(rng));
  c.keypoints.resize(c.descriptors.size());
  DescriptorMatchingOptions options;
  options.matcher = DescriptorMatcher::kBruteForce;
  options.min_num_matches = 1;
  const PairwiseMatches with_check = MatchDescriptors(features, {{0, 2}}, options);
  EXPECT_EQ(with_check.count({0, 2}), 0u);
  options.mutual_check = false;
  options.max_ratio = 1.0;
  const PairwiseMatches without = MatchDescriptors(features, {{0, 2}}, options);
  ASSERT_EQ(without.count({0, 2}), 1u);
  EXPECT_EQ(without.at({0, 2}).size(), 300u);  // every feature of view 0 has some nearest neighbour
}

TEST(DescriptorMatching, ResultDoesNotDependOnThreadsAndSkipsPairsWithoutFeatures) {
  FeaturesPerView features = TwoViews();
  features[2] = features[1];
  DescriptorMatchingOptions options;
  options.matcher = DescriptorMatcher::kFlann;  // the kd-trees are seeded per view, not per thread
  options.num_threads = 1;
  const PairwiseMatches one = MatchDescriptors(features, {{0, 1}, {0, 2}, {1, 2}, {0, 9}}, options);
  options.num_threads = 3;
  const PairwiseMatches three = MatchDescriptors(features, {{0, 1}, {0, 2}, {1, 2}, {0, 9}}, options);
  EXPECT_EQ(one, three);
  EXPECT_EQ(one.count({0, 9}), 0u);
  EXPECT_EQ(one.size(), 3u);
}

}  // namespace
}  // namespace sfm_pruning::testing
