#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "pruning/subgraph_loop_test_scene.hpp"
#include "sfm_pruning/pruning/subgraph_cycle_consistency.hpp"

namespace sfm_pruning {
namespace {

using testing::LoopScene;

// The real street's situation (docs/pruning.md): five subgraphs along a street, subgraph 4 at the
// start, then 0, 1, 2, 3. The true links chain them; 2–4 and 3–4 see subgraph 4 one facade
// period further along (a world shift of three subgraph spacings), the same shift for both, so
// they close their triangle with the true 2–3 and no triangle refutes them.
struct StreetLinks {
  LoopScene scene{std::vector<Eigen::Vector3d>{
      {4, 0, 0}, {8, 0, 0}, {12, 0, 0}, {16, 0, 0}, {0, 0, 0}}};

  // The world shift of subgraph 4 as a motion in k1's frame (Link applies it after the exact link).
  Similarity3 TwinOf4(int k1) const {
    Similarity3 shift;
    shift.translation = Eigen::Vector3d(12, 0, 0);
    return scene.WorldMotionIn(k1, shift);
  }

  // Coverages as measured on the street (the twins re-detect the least).
  std::vector<SubgraphLink> Links() const {
    return {scene.Link(0, 1, 10, {}, 0.39), scene.Link(0, 4, 8, {}, 0.31), scene.Link(1, 2, 7, {}, 0.24),
            scene.Link(2, 3, 12, {}, 0.32), scene.Link(2, 4, 10, TwinOf4(2), 0.22),
            scene.Link(3, 4, 10, TwinOf4(3), 0.09)};
  }
};

TEST(SubgraphCycles, TwinPairsThatCloseTheirOwnTriangleAreCutOnTheLongerCycles) {
  const StreetLinks street;
  const std::vector<SubgraphLink> links = street.Links();
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, street.scene.subgraphs);
  ASSERT_EQ(result.triangles.size(), 1u);  // (2, 3, 4), closed by the shared twin shift
  EXPECT_TRUE(result.triangles[0].consistent);
  ASSERT_EQ(result.rejected.size(), 2u);
  EXPECT_EQ(result.rejected[0].link, 4u);  // 2–4: lowest coverage on the 4-cycle 2-1-0-4
  EXPECT_EQ(result.rejected[1].link, 5u);  // 3–4: then on the 5-cycle 3-2-1-0-4
  for (const RejectedLink& rejected : result.rejected) {
    ASSERT_GE(rejected.cycle, 0);
    const SubgraphCycle& cycle = result.cycles[static_cast<size_t>(rejected.cycle)];
    EXPECT_FALSE(cycle.consistent);
    EXPECT_LT(cycle.rotation_deg, 1e-6);  // a pure shift: only the translation breaks the cycle
    EXPECT_GT(cycle.translation_fraction, 1.0);
  }
  EXPECT_EQ(result.cycles[static_cast<size_t>(result.rejected[0].cycle)].subgraphs.size(), 4u);
  EXPECT_EQ(result.cycles[static_cast<size_t>(result.rejected[1].cycle)].subgraphs.size(), 5u);
}

TEST(SubgraphCycles, OffBelowFourSubgraphs) {
  const StreetLinks street;
  SubgraphLoopOptions options;
  options.max_cycle_length = 3;
  const SubgraphLoopResult result = FindLoopInconsistentLinks(street.Links(), street.scene.subgraphs, options);
  EXPECT_TRUE(result.cycles.empty());
  EXPECT_TRUE(result.rejected.empty());
}

TEST(SubgraphCycles, ExactTransformsCloseAndCyclesWithAChordAreLeftToTheTriangles) {
  const LoopScene ring(5);
  // A ring 0-1-2-3-4-0: one chordless 5-cycle, exact.
  const std::vector<SubgraphLink> ring_links = {ring.Link(0, 1, 5), ring.Link(1, 2, 5), ring.Link(2, 3, 5),
                                                ring.Link(3, 4, 5), ring.Link(0, 4, 5)};
  const SubgraphLoopResult closed = FindLoopInconsistentLinks(ring_links, ring.subgraphs);
  ASSERT_EQ(closed.cycles.size(), 1u);
  EXPECT_TRUE(closed.cycles[0].consistent);
  EXPECT_LT(closed.cycles[0].rotation_deg, 1e-6);
  EXPECT_LT(std::abs(closed.cycles[0].scale_ratio - 1.0), 1e-9);
  EXPECT_LT(closed.cycles[0].translation_fraction, 1e-9);
  EXPECT_EQ(closed.cycles[0].loop_factor, 2u);
  EXPECT_TRUE(closed.rejected.empty());

  // Every pair of four subgraphs linked: each 4-cycle has a chord, only triangles are judged.
  const LoopScene complete(4);
  std::vector<SubgraphLink> links;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) links.push_back(complete.Link(a, b, 10));
  }
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, complete.subgraphs);
  EXPECT_TRUE(result.cycles.empty());
  EXPECT_TRUE(result.rejected.empty());
}

TEST(SubgraphCycles, LongerCyclesGetThePapersLoopFactor) {
  // A 7° turn: above the 5° bound of a 4-cycle (factor ⌊3/2⌋ = 1), within a 5-cycle's 10° (factor 2).
  for (const size_t length : {4u, 5u}) {
    const LoopScene ring(length);
    std::vector<SubgraphLink> links;
    for (int k = 0; k + 1 < static_cast<int>(length); ++k) links.push_back(ring.Link(k, k + 1, 5));
    const Eigen::Vector3d& centre = ring.subgraphs[0].center;
    links.push_back(ring.Link(0, static_cast<int>(length) - 1, 5, testing::TurnAbout(centre, 7.0)));
    SubgraphLoopOptions options;
    options.max_translation_fraction = 10.0;  // judge the rotation alone
    const SubgraphLoopResult result = FindLoopInconsistentLinks(links, ring.subgraphs, options);
    ASSERT_EQ(result.cycles.size(), 1u) << length;
    EXPECT_NEAR(result.cycles[0].rotation_deg, 7.0, 1e-6) << length;
    EXPECT_EQ(result.cycles[0].consistent, length == 5) << length;
    EXPECT_EQ(result.rejected.size(), length == 5 ? 0u : 1u) << length;
  }
}

}  // namespace
}  // namespace sfm_pruning
