#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "pruning/subgraph_loop_test_scene.hpp"
#include "sfm_pruning/pruning/trusted_link_forest.hpp"

namespace sfm_pruning {
namespace {

using testing::LoopScene;

// A pair with the exact transform of `scene`, followed by `error` in k1's frame.
SubgraphPairLink Pair(const LoopScene& scene, int k1, int k2, double trust, const Similarity3& error = {}) {
  const SubgraphLink link = scene.Link(k1, k2, 10, error, trust);
  return {k1, k2, true, link.k2_to_k1, trust, 10, -1.0, 10, false};
}

// A pair whose RANSAC gave no transform.
SubgraphPairLink PairWithoutTransform(int k1, int k2, double trust) {
  return {k1, k2, false, {}, trust, 3, -1.0, 3, false};
}

// A street of eight subgraphs, 4 m apart along x, whose facades repeat every 16 m: the twin pairs
// see subgraph k2 where k2 - 4 is (their transforms are shifted by one period in k1's frame), and
// they outnumber the true pairs between neighbours. Twins close triangles among themselves
// (k, k+4, k+8 would), so a vote can go either way; the trust ranks the true pairs first.
struct Street {
  LoopScene scene{std::vector<Eigen::Vector3d>{
      {0, 0, 0}, {4, 0, 0}, {8, 0, 0}, {12, 0, 0}, {16, 0, 0}, {20, 0, 0}, {24, 0, 0}, {28, 0, 0}}};

  Similarity3 PeriodShift(int k1) const {
    Similarity3 shift;
    shift.translation = Eigen::Vector3d(16, 0, 0);
    return scene.WorldMotionIn(k1, shift);
  }

  std::vector<SubgraphPairLink> Pairs() const {
    std::vector<SubgraphPairLink> pairs;
    for (int k = 0; k + 1 < 8; ++k) pairs.push_back(Pair(scene, k, k + 1, 0.8 + 0.01 * k));  // true neighbours
    for (int k = 0; k + 2 < 8; ++k) pairs.push_back(Pair(scene, k, k + 2, 0.7));               // true, wider
    for (int k = 0; k + 3 < 8; ++k) {  // twins: k + 3 .. k + 5 seen one period closer
      for (int d = 3; d <= 5 && k + d < 8; ++d) pairs.push_back(Pair(scene, k, k + d, 0.5, PeriodShift(k)));
    }
    return pairs;
  }
};

TEST(TrustedLinkForest, TwinPairsOfAStreetAreCutWhateverTheirNumber) {
  const Street street;
  const std::vector<SubgraphPairLink> pairs = street.Pairs();
  const TrustedForestResult result = SelectLinksByTrustedForest(pairs, street.scene.subgraphs, {});
  ASSERT_EQ(result.decisions.size(), pairs.size());
  size_t twins = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const int gap = pairs[p].k2 - pairs[p].k1;
    if (gap == 1) {
      EXPECT_EQ(result.decisions[p], LinkDecision::kForest) << pairs[p].k1 << "-" << pairs[p].k2;
    } else if (gap == 2) {
      EXPECT_EQ(result.decisions[p], LinkDecision::kClosesCycle) << pairs[p].k1 << "-" << pairs[p].k2;
    } else {
      ++twins;
      EXPECT_EQ(result.decisions[p], LinkDecision::kBreaksCycle) << pairs[p].k1 << "-" << pairs[p].k2;
      const SubgraphCycle& cycle = result.cycles.at(static_cast<size_t>(result.cycle_of[p]));
      EXPECT_LT(cycle.rotation_deg, 1e-6);  // a pure shift
      EXPECT_GT(cycle.translation_fraction, 1.0);
      EXPECT_EQ(cycle.subgraphs.size(), static_cast<size_t>(gap + 1));  // closed along the neighbours
    }
  }
  EXPECT_GT(twins, 7u);  // more twin pairs than true neighbours
}

TEST(TrustedLinkForest, AMoreTrustedTwinWinsItsCutAndItsTrueRivalIsCut) {
  // The forest takes the trust at its word: a twin pair ranked above the true pairs is kept and
  // the true pair it contradicts is cut. (What the trust is for: docs/pruning.md.)
  const Street street;
  std::vector<SubgraphPairLink> pairs = {Pair(street.scene, 0, 1, 0.9), Pair(street.scene, 1, 2, 0.9),
                                         Pair(street.scene, 2, 3, 0.9), Pair(street.scene, 3, 4, 0.5),
                                         Pair(street.scene, 0, 4, 0.95, street.PeriodShift(0))};
  const TrustedForestResult result = SelectLinksByTrustedForest(pairs, street.scene.subgraphs, {});
  EXPECT_EQ(result.decisions[4], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[3], LinkDecision::kBreaksCycle);
}

TEST(TrustedLinkForest, PairsWithoutTransformBridgeButNeverVerify) {
  const LoopScene scene(5);
  const std::vector<SubgraphPairLink> pairs = {
      Pair(scene, 0, 1, 0.9), Pair(scene, 1, 2, 0.9),
      PairWithoutTransform(2, 3, 0.8),  // the only way to 3: kept
      Pair(scene, 3, 4, 0.9),
      Pair(scene, 0, 2, 0.7),             // closes 0-1-2
      PairWithoutTransform(0, 2, 0.6),    // redundant, nothing to verify it with
      Pair(scene, 2, 4, 0.5),             // its cycle runs through 2-3, which has no transform
  };
  const TrustedForestResult result = SelectLinksByTrustedForest(pairs, scene.subgraphs, {});
  EXPECT_EQ(result.decisions[2], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[4], LinkDecision::kClosesCycle);
  EXPECT_EQ(result.decisions[5], LinkDecision::kRedundantUnverified);
  EXPECT_EQ(result.decisions[6], LinkDecision::kRedundantUnverified);
  EXPECT_EQ(result.cycle_of[5], -1);
  EXPECT_EQ(result.cycles.size(), 1u);
  // Unverifiable but as distinctive as the subgraphs' own edges: kept.
  SubgraphLoopOptions lenient;
  lenient.min_unverified_trust = 0.55;
  const TrustedForestResult kept = SelectLinksByTrustedForest(pairs, scene.subgraphs, lenient);
  EXPECT_EQ(kept.decisions[5], LinkDecision::kKeptUnverified);
  EXPECT_EQ(kept.decisions[6], LinkDecision::kRedundantUnverified);
  // ... unless its placed views miss what they should see.
  std::vector<SubgraphPairLink> missing = pairs;
  missing[5].relative_coverage = 0.5;
  EXPECT_EQ(SelectLinksByTrustedForest(missing, scene.subgraphs, lenient).decisions[5],
            LinkDecision::kRedundantUnverified);
  missing[5].relative_coverage = 0.9;
  EXPECT_EQ(SelectLinksByTrustedForest(missing, scene.subgraphs, lenient).decisions[5], LinkDecision::kKeptUnverified);
}

// A redundant pair without a transform of its own is judged by its edges against the transform
// chained along the forest path, when that path has transforms all along; the check receives the
// path's transform k2 -> k1.
TEST(TrustedLinkForest, PairsWithoutTransformAreCheckedAgainstTheChainedForestTransform) {
  const LoopScene scene(5);
  const std::vector<SubgraphPairLink> pairs = {
      Pair(scene, 0, 1, 0.9), Pair(scene, 1, 2, 0.9), PairWithoutTransform(2, 3, 0.8), Pair(scene, 3, 4, 0.9),
      PairWithoutTransform(0, 2, 0.6),  // path 0-1-2: transforms all along
      PairWithoutTransform(1, 2, 0.6),  // path 1-2: likewise
      PairWithoutTransform(2, 4, 0.6),  // path 2-3-4 runs through a pair without transform
  };
  const Similarity3 truth_0_2 = scene.Link(0, 2, 10, {}, 1.0).k2_to_k1;
  std::vector<size_t> checked;
  const ForestTransformCheck check = [&](size_t pair, const ChainedTransform& chained) -> std::optional<bool> {
    const Similarity3& k2_to_k1 = chained.k2_to_k1;
    checked.push_back(pair);
    if (pair == 4) {
      EXPECT_NEAR(k2_to_k1.scale, truth_0_2.scale, 1e-9);
      EXPECT_LT((k2_to_k1.rotation - truth_0_2.rotation).norm(), 1e-9);
      EXPECT_LT((k2_to_k1.translation - truth_0_2.translation).norm(), 1e-9);
      return true;
    }
    return std::nullopt;  // nothing of pair 5 could be checked
  };
  const TrustedForestResult result = SelectLinksByTrustedForest(pairs, scene.subgraphs, {}, check);
  EXPECT_EQ(checked, (std::vector<size_t>{4, 5}));
  EXPECT_EQ(result.decisions[4], LinkDecision::kAgreesWithForest);
  EXPECT_EQ(result.decisions[5], LinkDecision::kRedundantUnverified);  // the trust rule decides
  EXPECT_EQ(result.decisions[6], LinkDecision::kRedundantUnverified);
  const ForestTransformCheck contradicts = [](size_t, const ChainedTransform&) -> std::optional<bool> { return false; };
  EXPECT_EQ(SelectLinksByTrustedForest(pairs, scene.subgraphs, {}, contradicts).decisions[4],
            LinkDecision::kContradictsForest);
}

TEST(TrustedLinkForest, CaptureLinkedPairsRankFirst) {
  // The twin pair 0-4 is the most trusted, as on a courtyard whose twins match most of each view;
  // the pairs along the capture order rank first all the same, and the twin must close its cycle
  // with them.
  const Street street;
  std::vector<SubgraphPairLink> pairs = {Pair(street.scene, 0, 1, 0.6), Pair(street.scene, 1, 2, 0.6),
                                         Pair(street.scene, 2, 3, 0.6), Pair(street.scene, 3, 4, 0.6),
                                         Pair(street.scene, 0, 4, 0.95, street.PeriodShift(0)),
                                         PairWithoutTransform(1, 3, 0.1)};
  TrustedForestResult result = SelectLinksByTrustedForest(pairs, street.scene.subgraphs, {});
  EXPECT_EQ(result.decisions[4], LinkDecision::kForest);  // trust alone: the twin joins first
  EXPECT_EQ(result.decisions[3], LinkDecision::kBreaksCycle);
  for (size_t p = 0; p < 4; ++p) pairs[p].capture_linked = true;
  pairs[5].capture_linked = true;
  result = SelectLinksByTrustedForest(pairs, street.scene.subgraphs, {});
  for (size_t p = 0; p < 4; ++p) EXPECT_EQ(result.decisions[p], LinkDecision::kForest) << p;
  EXPECT_EQ(result.decisions[4], LinkDecision::kBreaksCycle);
  // Being capture-linked ranks a pair, it does not vouch for it: unverifiable and far below
  // min_unverified_trust, it is cut.
  EXPECT_EQ(result.decisions[5], LinkDecision::kRedundantUnverified);
}

TEST(TrustedLinkForest, PairsOfFewEdgesComeAfterTheOthersWhateverTheirTrust) {
  // castle-P19: a one-edge pair (no transform, trust 1.49) entered the forest first and left the
  // cycle of a 16-edge true pair unverifiable, which was cut.
  const LoopScene scene(4);
  std::vector<SubgraphPairLink> pairs = {Pair(scene, 0, 1, 0.9), Pair(scene, 1, 2, 0.9),
                                         PairWithoutTransform(2, 3, 1.5), Pair(scene, 0, 3, 0.6),
                                         Pair(scene, 1, 3, 0.5)};
  pairs[2].num_edges = 1;
  TrustedForestResult result = SelectLinksByTrustedForest(pairs, scene.subgraphs, {});
  EXPECT_EQ(result.decisions[3], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[4], LinkDecision::kClosesCycle);
  EXPECT_EQ(result.decisions[2], LinkDecision::kKeptUnverified);  // redundant; its trust vouches
  SubgraphLoopOptions by_trust_only;
  by_trust_only.min_edges_for_trust = 0;
  result = SelectLinksByTrustedForest(pairs, scene.subgraphs, by_trust_only);
  EXPECT_EQ(result.decisions[2], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[3], LinkDecision::kRedundantUnverified);  // 0.6 < 0.65, nothing verifies it
}

TEST(TrustedLinkForest, LongCyclesGetThePapersLoopFactor) {
  // A ring of 7 subgraphs whose links each drift by 2 degrees: 12° around the 7-cycle closed by
  // the least trusted link, within 5° · ⌊(7 − 1) / 2⌋ = 15°, but not within the triangle's 5°.
  const LoopScene scene(7);
  std::vector<SubgraphPairLink> pairs;
  for (int k = 0; k + 1 < 7; ++k) {
    Similarity3 drift;  // 2° about the world's z axis, written in k's frame
    drift.rotation = ExpSO3(DegToRad(2.0) * Eigen::Vector3d::UnitZ());
    pairs.push_back(Pair(scene, k, k + 1, 0.9, scene.WorldMotionIn(k, drift)));
  }
  pairs.push_back(Pair(scene, 0, 6, 0.5));
  TrustedForestResult result = SelectLinksByTrustedForest(pairs, scene.subgraphs, {});
  ASSERT_EQ(result.cycles.size(), 1u);
  EXPECT_EQ(result.cycles[0].subgraphs.size(), 7u);
  EXPECT_EQ(result.cycles[0].loop_factor, 3u);
  EXPECT_NEAR(result.cycles[0].rotation_deg, 12.0, 0.5);
  EXPECT_EQ(result.decisions[6], LinkDecision::kClosesCycle);
  SubgraphLoopOptions strict;
  strict.max_rotation_deg = 3.0;  // 9° allowed around seven subgraphs
  result = SelectLinksByTrustedForest(pairs, scene.subgraphs, strict);
  EXPECT_EQ(result.decisions[6], LinkDecision::kBreaksCycle);
}

TEST(TrustedLinkForest, TiesInTrustGoToTheLargerSupportThenTheEarlierPair) {
  const LoopScene scene(3);
  std::vector<SubgraphPairLink> pairs = {Pair(scene, 0, 1, 0.5), Pair(scene, 1, 2, 0.5),
                                         Pair(scene, 0, 2, 0.5, testing::TurnAbout(Eigen::Vector3d::Zero(), 30))};
  pairs[2].support = 20;  // the wrong one has the most edges: in the forest, 0-1 or 1-2 is cut
  const TrustedForestResult result = SelectLinksByTrustedForest(pairs, scene.subgraphs, {});
  EXPECT_EQ(result.decisions[2], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[0], LinkDecision::kForest);
  EXPECT_EQ(result.decisions[1], LinkDecision::kBreaksCycle);
}

}  // namespace
}  // namespace sfm_pruning
