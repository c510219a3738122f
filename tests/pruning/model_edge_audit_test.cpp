// The model's audit of the pruning (model_edge_audit.hpp) on exact data: the model is the ground
// truth itself, every point a landmark seen by every view (feature id = point id).
#include <gtest/gtest.h>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/model_edge_audit.hpp"

namespace sfm_pruning {
namespace {

using testing::GroundTruthModel;
using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::Similarity;

TEST(ModelEdgeAudit, TrueMatchesTransferAndTwinMatchesDoNot) {
  PruningTestScene scene = MakePruningTestScene(8, 40, 3);
  scene.AddExactEdge(0, 1);
  Similarity twin;  // the copy one period along x: its points project far from the originals
  twin.translation = Eigen::Vector3d(1.5, 0.0, 0.0);
  scene.AddTwinEdge(2, 3, twin);
  scene.AddTwinEdge(4, 5, twin, 10);  // a mixed edge: 10 matches to the copy, then 30 true ones
  for (IndexT p = 10; p < 40; ++p) scene.graph.MutableEdge(4, 5)->matches.push_back({p, p});
  const SfmData model = GroundTruthModel(scene);
  const std::vector<EdgeAgreement> audit =
      AuditEdgesAgainstModel(scene.graph, {{0, 1}, {2, 3}, {4, 5}, {6, 7}}, model, scene.features, {});
  ASSERT_EQ(audit.size(), 3u);  // {6, 7} is no edge
  EXPECT_EQ(audit[0].pair, ViewPair(0, 1));
  EXPECT_EQ(audit[0].transferred, 40u);
  EXPECT_EQ(audit[0].agreeing, 40u);
  EXPECT_EQ(audit[1].pair, ViewPair(2, 3));
  EXPECT_EQ(audit[1].transferred, 40u);  // through view 2's features (3's copies are no landmark)
  EXPECT_EQ(audit[1].agreeing, 0u);
  EXPECT_NEAR(audit[2].Share(), 30.0 / 40.0, 1e-12);
}

TEST(ModelEdgeAudit, ViewsTheModelDidNotPoseAreNotJudged) {
  PruningTestScene scene = MakePruningTestScene(4, 30, 5);
  scene.AddExactEdge(0, 1);
  scene.AddExactEdge(1, 2);
  SfmData model = GroundTruthModel(scene);
  model.poses.erase(model.views.at(2).id_pose);
  const std::vector<EdgeAgreement> audit =
      AuditEdgesAgainstModel(scene.graph, {{0, 1}, {1, 2}}, model, scene.features, {});
  ASSERT_EQ(audit.size(), 1u);
  EXPECT_EQ(audit[0].pair, ViewPair(0, 1));
  EXPECT_DOUBLE_EQ(audit[0].Share(), 1.0);
}

}  // namespace
}  // namespace sfm_pruning
