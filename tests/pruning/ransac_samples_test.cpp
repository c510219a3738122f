// The samples of one inter-subgraph RANSAC run (ransac_samples.hpp): every subset exactly once
// when enumerated, the paper's random rounds otherwise.
#include <gtest/gtest.h>

#include <set>

#include "sfm_pruning/pruning/ransac_samples.hpp"

namespace sfm_pruning {
namespace {

TEST(NumSubsetsTest, MatchesHandCountedBinomials) {
  EXPECT_EQ(NumSubsets(17, 2), 136.0);
  EXPECT_EQ(NumSubsets(45, 2), 990.0);
  EXPECT_EQ(NumSubsets(10, 4), 210.0);
  EXPECT_EQ(NumSubsets(5, 5), 1.0);
  EXPECT_EQ(NumSubsets(5, 0), 1.0);
  EXPECT_EQ(NumSubsets(3, 4), 0.0);
}

TEST(RansacSamplesTest, EnumerationVisitsEverySubsetOnceInOrder) {
  std::mt19937_64 rng(1);
  RansacSamples samples(6, 3, 30, 1000, &rng);
  ASSERT_TRUE(samples.enumerated());
  ASSERT_EQ(samples.size(), 20);
  std::set<std::vector<size_t>> seen;
  std::vector<size_t> previous;
  for (int k = 0; k < samples.size(); ++k) {
    const std::vector<size_t> sample = samples.Next();
    ASSERT_EQ(sample.size(), 3u);
    EXPECT_LT(sample[0], sample[1]);
    EXPECT_LT(sample[1], sample[2]);
    EXPECT_LT(sample[2], 6u);
    if (k > 0) {
      EXPECT_LT(previous, sample);  // lexicographic
    }
    previous = sample;
    seen.insert(sample);
  }
  EXPECT_EQ(seen.size(), 20u);
  EXPECT_EQ(*seen.begin(), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(*seen.rbegin(), (std::vector<size_t>{3, 4, 5}));
}

TEST(RansacSamplesTest, EnumerationUsesNoRandomNumbers) {
  std::mt19937_64 rng(7), untouched(7);
  RansacSamples samples(17, 2, 30, 1000, &rng);
  ASSERT_TRUE(samples.enumerated());
  EXPECT_EQ(samples.size(), 136);
  for (int k = 0; k < samples.size(); ++k) samples.Next();
  EXPECT_EQ(rng(), untouched());
}

TEST(RansacSamplesTest, AboveTheBoundOrWithoutOneTheRoundsAreRandomDraws) {
  for (const size_t bound : {size_t{0}, size_t{135}}) {
    std::mt19937_64 rng(3);
    RansacSamples samples(17, 2, 30, bound, &rng);
    EXPECT_FALSE(samples.enumerated());
    ASSERT_EQ(samples.size(), 30);
    std::set<std::vector<size_t>> distinct;
    for (int k = 0; k < samples.size(); ++k) {
      const std::vector<size_t> sample = samples.Next();
      ASSERT_EQ(sample.size(), 2u);
      EXPECT_LT(sample[0], sample[1]);
      EXPECT_LT(sample[1], 17u);
      distinct.insert(sample);
    }
    EXPECT_GT(distinct.size(), 20u);  // 30 uniform draws among 136 pairs rarely repeat much
  }
}

TEST(RansacSamplesTest, RandomDrawsDependOnlyOnTheSeed) {
  std::mt19937_64 a(5), b(5);
  RansacSamples first(40, 2, 30, 0, &a), second(40, 2, 30, 0, &b);
  for (int k = 0; k < 30; ++k) EXPECT_EQ(first.Next(), second.Next());
}

TEST(RansacSamplesTest, AWholePoolIsOneSample) {
  std::mt19937_64 rng(0);
  RansacSamples samples(3, 3, 30, 1000, &rng);
  ASSERT_TRUE(samples.enumerated());
  ASSERT_EQ(samples.size(), 1);
  EXPECT_EQ(samples.Next(), (std::vector<size_t>{0, 1, 2}));
}

}  // namespace
}  // namespace sfm_pruning
