#include <vector>

#include <gtest/gtest.h>

#include "sfm_pruning/pruning/pair_trust.hpp"

namespace sfm_pruning {
namespace {

// Subgraph {0, 1} and subgraph {2, 3}, every pair of views matched. Facade features 10 .. 19 are in
// every edge (a view's facade feature is in its 3 edges); unique features 0 .. 9 are also matched
// by 0-1 (inside) and 0-3 (between the subgraphs). So the pair edge 1-2 matches the facade only.
struct TwoSubgraphs {
  ViewGraph graph;
  std::vector<AcceptedSubgraph> accepted;

  TwoSubgraphs() {
    std::vector<FeatureMatch> facade;
    for (IndexT f = 10; f < 20; ++f) facade.push_back({f, f});
    for (IndexT a = 0; a < 4; ++a) {
      for (IndexT b = a + 1; b < 4; ++b) {
        std::vector<FeatureMatch> matches = facade;
        if (a == 0 && (b == 1 || b == 3)) {
          for (IndexT f = 0; f < 10; ++f) matches.push_back({f, f});
        }
        graph.AddEdge(a, b, matches, RelativePose());
      }
    }
    accepted.resize(2);
    accepted[0].solution.view_ids = {0, 1};
    accepted[1].solution.view_ids = {2, 3};
  }
};

TEST(PairTrust, DistinctiveShareIsMeasuredAgainstTheEdgesInsideTheSubgraphs) {
  const TwoSubgraphs scene;
  const PairTrust trust(PairTrustMeasure::kDistinctiveShare, scene.graph, scene.accepted);
  // A facade feature is matched by 3 edges (weight 1/3); unique feature f of view 0 by 2 (0-1 and
  // 0-3), of view 1 or 3 by 1. Inside: 0-1 (20 inliers, 10/3 + 10·(1/2 + 1)/2) and 2-3 (10 inliers,
  // 10/3): share (10/3 + 7.5 + 10/3) / 30.
  const double inside = (10.0 / 3.0 + 7.5 + 10.0 / 3.0) / 30.0;
  EXPECT_DOUBLE_EQ(trust.ReferenceShare(), inside);
  EXPECT_DOUBLE_EQ(trust.Of({{1, 2}}, nullptr), (1.0 / 3.0) / inside);
  EXPECT_DOUBLE_EQ(trust.Of({{3, 0}}, nullptr), ((10.0 / 3.0 + 7.5) / 20.0) / inside);  // either orientation
  EXPECT_GT(trust.Of({{0, 3}}, nullptr), trust.Of({{1, 2}}, nullptr));
  EXPECT_DOUBLE_EQ(trust.Of({}, nullptr), 0.0);
}

TEST(PairTrust, MatchCoverageIsTheSelectedHypothesis) {
  const TwoSubgraphs scene;
  const PairTrust trust(PairTrustMeasure::kMatchCoverage, scene.graph, scene.accepted);
  AlignmentHypothesis selected;
  selected.expected_landmarks = 40;
  selected.matched_landmarks = 30;
  EXPECT_DOUBLE_EQ(trust.Of({{1, 2}}, &selected), 0.75);
  EXPECT_DOUBLE_EQ(trust.Of({{1, 2}}, nullptr), 0.0);
  EXPECT_DOUBLE_EQ(trust.ReferenceShare(), 0.0);
}

}  // namespace
}  // namespace sfm_pruning
