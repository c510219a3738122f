#include "sfm_pruning/pipeline/reconstruction_input.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sfm_pruning {
namespace {

std::vector<FeatureMatch> Matches(std::initializer_list<IndexT> first_features) {
  std::vector<FeatureMatch> matches;
  for (IndexT f : first_features) matches.push_back({f, f + 100});
  return matches;
}

TEST(ReverifyDatabasePairs, VerifiedPairsBecomeTheirRawMatches) {
  ReconstructionInput input;
  // (0, 1): verified, 2 of its 4 raw matches are inliers. (0, 2): raw matches only, the other
  // tool rejected the pair. (1, 2): verified, but the database kept no raw matches for it.
  input.putative[{0, 1}] = Matches({1, 2, 3, 4});
  input.putative[{0, 2}] = Matches({5, 6, 7});
  input.verified[{0, 1}].inliers = Matches({1, 3});
  input.verified[{1, 2}].inliers = Matches({8, 9});

  ReverifyDatabasePairs(&input);

  EXPECT_TRUE(input.verified.empty());
  ASSERT_EQ(input.putative.size(), 2u);
  EXPECT_EQ(input.putative.at({0, 1}), Matches({1, 2, 3, 4}));
  EXPECT_EQ(input.putative.at({1, 2}), Matches({8, 9}));
  EXPECT_EQ(input.putative.count({0, 2}), 0u);  // rejected by the other tool: stays out
}

TEST(ReverifyDatabasePairs, AnInputWithoutVerifiedPairsIsUnchanged) {
  ReconstructionInput input;
  input.putative[{0, 2}] = Matches({5, 6, 7});
  ReverifyDatabasePairs(&input);
  ASSERT_EQ(input.putative.size(), 1u);
  EXPECT_EQ(input.putative.at({0, 2}), Matches({5, 6, 7}));
}

}  // namespace
}  // namespace sfm_pruning
