#include <vector>

#include <gtest/gtest.h>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/pruning/pair_trust.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::RandomSimilarity;

// Subgraph {0, 1} and subgraph {2, 3}, every pair of views matched. Facade features 10 .. 19 are in
// every edge (a view's facade feature is in its 3 edges); unique features 0 .. 9 are also matched
// by 0-1 (inside) and 0-3 (between the subgraphs). So the pair edge 1-2 matches the facade only.
struct TwoSubgraphs {
  ViewGraph graph;
  std::vector<AcceptedSubgraph> accepted;
  SfmData no_views;

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

  // A pair result keeping `kept` of the connecting edges (i in {0, 1}, j in {2, 3}).
  static SubgraphAlignmentResult Kept(const std::vector<ViewPair>& kept, const std::vector<ViewPair>& removed = {}) {
    SubgraphAlignmentResult result;
    for (const auto& [edges, keep] : {std::pair{kept, true}, std::pair{removed, false}}) {
      for (const ViewPair& edge : edges) {
        InterSubgraphEdgeDecision decision;
        decision.placement.view_i = edge.first;
        decision.placement.view_j = edge.second;
        decision.kept = keep;
        result.edges.push_back(decision);
      }
    }
    return result;
  }
};

TEST(PairTrust, DistinctiveShareIsMeasuredAgainstTheEdgesInsideTheSubgraphs) {
  const TwoSubgraphs scene;
  const PairTrust trust(PairTrustMeasure::kDistinctiveShare, scene.graph, scene.accepted, scene.no_views, {});
  // A facade feature is matched by 3 edges (weight 1/3); unique feature f of view 0 by 2 (0-1 and
  // 0-3), of view 1 or 3 by 1. Inside: 0-1 (20 inliers, 10/3 + 10·(1/2 + 1)/2) and 2-3 (10 inliers,
  // 10/3): share (10/3 + 7.5 + 10/3) / 30.
  const double inside = (10.0 / 3.0 + 7.5 + 10.0 / 3.0) / 30.0;
  EXPECT_DOUBLE_EQ(trust.ReferenceShare(), inside);
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({{1, 2}}), false), (1.0 / 3.0) / inside);
  const double true_pair = ((10.0 / 3.0 + 7.5) / 20.0) / inside;
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({{0, 3}}), false), true_pair);
  // Only the kept edges count, unless all of them are asked for.
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({{0, 3}}, {{1, 2}}), false), true_pair);
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({{0, 3}}, {{1, 2}}), true),
                   ((10.0 / 3.0 + 7.5 + 10.0 / 3.0) / 30.0) / inside);
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({}), false), 0.0);
}

TEST(PairTrust, PriorEdgesPullOneKeptEdgeTowardTheShareOfAllConnectingEdges) {
  const TwoSubgraphs scene;
  const double prior_edges = 2.0;
  const PairTrust trust(PairTrustMeasure::kDistinctiveShare, scene.graph, scene.accepted, scene.no_views, {},
                        prior_edges);
  const double inside = (10.0 / 3.0 + 7.5 + 10.0 / 3.0) / 30.0;
  // 0-3 alone: (10/3 + 7.5) / 20. All four connecting edges: the facade's 4 · 10/3 plus 0-3's
  // unique 7.5 over 50 inliers. One kept edge weighs as one against the prior's two.
  const double kept_share = (10.0 / 3.0 + 7.5) / 20.0;
  const double all_share = (4.0 * 10.0 / 3.0 + 7.5) / 50.0;
  const SubgraphAlignmentResult one_kept = TwoSubgraphs::Kept({{0, 3}}, {{0, 2}, {1, 2}, {1, 3}});
  EXPECT_DOUBLE_EQ(trust.Of(one_kept, false), ((kept_share + prior_edges * all_share) / 3.0) / inside);
  EXPECT_LT(trust.Of(one_kept, false), kept_share / inside);
  // Every edge kept: the prior changes nothing; all edges asked for: no prior; nothing kept: 0.
  const SubgraphAlignmentResult all_kept = TwoSubgraphs::Kept({{0, 2}, {0, 3}, {1, 2}, {1, 3}});
  EXPECT_NEAR(trust.Of(all_kept, false), all_share / inside, 1e-12);
  EXPECT_DOUBLE_EQ(trust.Of(one_kept, true), all_share / inside);
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({}, {{0, 3}}), false), 0.0);
}

TEST(PairTrust, MatchCoverageIsTheSelectedHypothesis) {
  const TwoSubgraphs scene;
  const PairTrust trust(PairTrustMeasure::kMatchCoverage, scene.graph, scene.accepted, scene.no_views, {});
  SubgraphAlignmentResult aligned = TwoSubgraphs::Kept({{1, 2}});
  AlignmentHypothesis selected;
  selected.expected_landmarks = 40;
  selected.matched_landmarks = 30;
  aligned.hypotheses = {selected};
  aligned.selected_hypothesis = 0;
  EXPECT_DOUBLE_EQ(trust.Of(aligned, false), 0.75);
  EXPECT_DOUBLE_EQ(trust.Of(TwoSubgraphs::Kept({{1, 2}}), false), 0.0);
  EXPECT_DOUBLE_EQ(trust.ReferenceShare(), 0.0);
}

TEST(PairTrust, CoverageIsRelativeToTheEdgesInsideTheSubgraphs) {
  // Exact data: the edges inside each subgraph match every landmark they should see, so the
  // reference coverage is 1 and a pair's relative coverage is its own.
  PruningTestScene scene = MakePruningTestScene(8, 60, 3);
  for (IndexT a = 0; a < 4; ++a) {
    for (IndexT b = a + 1; b < 4; ++b) scene.AddExactEdge(a, b);
  }
  std::vector<AcceptedSubgraph> accepted(1);
  accepted[0].solution = scene.Solution({0, 1, 2, 3}, RandomSimilarity(5, 2.0));
  const PairTrust trust(PairTrustMeasure::kDistinctiveShare, scene.graph, accepted, scene.views_and_intrinsics, {});
  EXPECT_DOUBLE_EQ(trust.ReferenceCoverage(), 1.0);
  SubgraphAlignmentResult pair = TwoSubgraphs::Kept({{0, 4}, {1, 5}});
  pair.edges[0].placement.status = EdgePlacementStatus::kPlaced;
  pair.edges[0].placement.num_expected_landmarks = 40;
  pair.edges[0].placement.num_matched_landmarks = 10;
  pair.edges[1].placement.status = EdgePlacementStatus::kPnpFailed;  // expects nothing
  EXPECT_DOUBLE_EQ(trust.RelativeCoverageOf(pair, false), 0.25);
  pair.edges[0].kept = false;
  EXPECT_DOUBLE_EQ(trust.RelativeCoverageOf(pair, false), -1.0);
  EXPECT_DOUBLE_EQ(trust.RelativeCoverageOf(pair, true), 0.25);
}

}  // namespace
}  // namespace sfm_pruning
