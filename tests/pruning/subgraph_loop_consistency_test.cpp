#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "pruning/subgraph_loop_test_scene.hpp"
#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"

namespace sfm_pruning {
namespace {

using testing::LoopScene;
using testing::TurnAbout;

TEST(SubgraphLoops, ExactTransformsCloseEveryTriangle) {
  const LoopScene scene(4);
  std::vector<SubgraphLink> links;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) links.push_back(scene.Link(a, b, 10));
  }
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, scene.subgraphs);
  ASSERT_EQ(result.triangles.size(), 4u);
  for (const SubgraphTriangle& triangle : result.triangles) {
    EXPECT_TRUE(triangle.consistent);
    EXPECT_LT(triangle.rotation_deg, 1e-6);
    EXPECT_LT(std::abs(triangle.scale_ratio - 1.0), 1e-9);
    EXPECT_LT(triangle.translation_fraction, 1e-9);
  }
  EXPECT_TRUE(result.rejected.empty());
}

TEST(SubgraphLoops, TheOneWrongPairIsRejectedEvenWithTheLargestSupport) {
  const LoopScene scene(4);
  std::vector<SubgraphLink> links;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) {
      const bool wrong = a == 2 && b == 3;  // like books: every edge between 2 and 3 is a doppelganger
      links.push_back(wrong ? scene.Link(a, b, 40, TurnAbout(scene.subgraphs[2].center, 60.0)) : scene.Link(a, b, 10));
    }
  }
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, scene.subgraphs);
  ASSERT_EQ(result.rejected.size(), 1u);
  const SubgraphLink& rejected = links[result.rejected[0].link];
  EXPECT_EQ(rejected.k1, 2);
  EXPECT_EQ(rejected.k2, 3);
  EXPECT_EQ(result.rejected[0].inconsistent_triangles, 2u);  // (0,2,3) and (1,2,3)
  EXPECT_EQ(result.rejected[0].consistent_triangles, 0u);
  size_t inconsistent = 0;
  for (const SubgraphTriangle& triangle : result.triangles) {
    const bool has_wrong_pair = triangle.b == 2 && triangle.c == 3;
    EXPECT_EQ(triangle.consistent, !has_wrong_pair) << triangle.a << triangle.b << triangle.c;
    if (has_wrong_pair) {
      EXPECT_NEAR(triangle.rotation_deg, 60.0, 1e-6);
    }
    inconsistent += triangle.consistent ? 0 : 1;
  }
  EXPECT_EQ(inconsistent, 2u);
}

TEST(SubgraphLoops, AShiftAlongTheStreetBreaksTheLoopsThroughTranslationAlone) {
  const LoopScene scene(4);
  Similarity3 shift;  // a facade module further along, no rotation
  shift.translation = Eigen::Vector3d(1.0, 0.0, 0.0) * 3.0 * scene.frames[0].scale;
  std::vector<SubgraphLink> links;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) links.push_back(a == 0 && b == 1 ? scene.Link(a, b, 30, shift) : scene.Link(a, b, 10));
  }
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, scene.subgraphs);
  ASSERT_EQ(result.rejected.size(), 1u);
  EXPECT_EQ(links[result.rejected[0].link].k1, 0);
  EXPECT_EQ(links[result.rejected[0].link].k2, 1);
  for (const SubgraphTriangle& triangle : result.triangles) {
    if (triangle.a == 0 && triangle.b == 1) {
      EXPECT_LT(triangle.rotation_deg, 1e-6);
      EXPECT_GT(triangle.translation_fraction, 0.25);
    }
  }
}

TEST(SubgraphLoops, ASingleBrokenTriangleLosesItsWeakestPairAndPairsOutsideTrianglesStay) {
  const LoopScene scene(4);
  // Triangle (0, 1, 2) with a wrong (1, 2), plus subgraph 3 hanging on (2, 3), in no triangle.
  std::vector<SubgraphLink> links = {scene.Link(0, 1, 30), scene.Link(0, 2, 20),
                                     scene.Link(1, 2, 5, TurnAbout(scene.subgraphs[1].center, 30.0)),
                                     scene.Link(2, 3, 1)};
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, scene.subgraphs);
  ASSERT_EQ(result.triangles.size(), 1u);
  EXPECT_FALSE(result.triangles[0].consistent);
  ASSERT_EQ(result.rejected.size(), 1u);  // one of the three must go; nothing can tell which but support
  EXPECT_EQ(result.rejected[0].link, 2u);
  EXPECT_EQ(result.inconsistent_triangles, (std::vector<size_t>{1, 1, 1, 0}));
  EXPECT_EQ(result.consistent_triangles, (std::vector<size_t>{0, 0, 0, 0}));
}

TEST(SubgraphLoops, SwitchedOffItMeasuresButRejectsNothing) {
  const LoopScene scene(3);
  const std::vector<SubgraphLink> links = {scene.Link(0, 1, 10), scene.Link(0, 2, 10),
                                           scene.Link(1, 2, 10, TurnAbout(scene.subgraphs[1].center, 45.0))};
  SubgraphLoopOptions options;
  options.enabled = false;
  const SubgraphLoopResult result = FindLoopInconsistentLinks(links, scene.subgraphs, options);
  ASSERT_EQ(result.triangles.size(), 1u);
  EXPECT_FALSE(result.triangles[0].consistent);
  EXPECT_TRUE(result.rejected.empty());
}

}  // namespace
}  // namespace sfm_pruning
