// Depth votes on the links of tracks (global/link_depth_votes.hpp): on an exact scene with pixel
// noise, links between two points that lie on one epipolar plane at different depths (a repeated
// texture shifted along the baseline) are dropped, and the true links are kept.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "global/positioning_synthetic_scene.hpp"
#include "sfm_pruning/global/link_depth_votes.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePositioningScene;
using testing::PositioningScene;
using testing::PositioningSceneOptions;

using LinkKey = std::pair<ViewPair, FeatureMatch>;
struct LinkKeyLess {
  bool operator()(const LinkKey& a, const LinkKey& b) const {
    return std::tie(a.first, a.second.i, a.second.j) < std::tie(b.first, b.second.i, b.second.j);
  }
};
using LinkSet = std::set<LinkKey, LinkKeyLess>;

// Replaces every `stride`-th match of every edge by a twin link: the first view's feature matched to
// a new feature of the second view at the projection of the point moved along the baseline by
// `shift` times its length (on the same epipolar plane: it passes the epipolar test, at another
// depth; shift 1 puts it at infinity). Returns the twin links.
LinkSet InjectTwinLinks(PositioningScene* scene, size_t stride, double shift) {
  LinkSet twins;
  const ViewGraph original = scene->graph;
  for (const auto& [pair, edge] : original.Edges()) {
    const Pose& first = scene->true_poses.at(pair.first);
    const Pose& second = scene->true_poses.at(pair.second);
    const CameraIntrinsics& first_camera =
        scene->sfm_data.intrinsics.at(scene->sfm_data.views.at(pair.first).id_intrinsic);
    const CameraIntrinsics& second_camera =
        scene->sfm_data.intrinsics.at(scene->sfm_data.views.at(pair.second).id_intrinsic);
    ViewGraphEdge changed = edge;
    for (size_t k = 0; k < changed.matches.size(); k += stride) {
      FeatureMatch& match = changed.matches[k];
      // The point seen by the first view's feature, on its ray at the depth the second view's
      // (true) feature gives: the exact point up to the pixel noise.
      const Eigen::Vector3d ray =
          first.rotation.transpose() * first_camera.Unproject(scene->features.at(pair.first).Position(match.i)).normalized();
      double best_depth = 0.0, best_error = 1e300;
      for (const Eigen::Vector3d& point : scene->points) {
        const Eigen::Vector3d offset = point - first.center;
        const double error = (offset - offset.dot(ray) * ray).norm();
        if (error < best_error) best_error = error, best_depth = offset.dot(ray);
      }
      const Eigen::Vector3d point = first.center + best_depth * ray;
      const Eigen::Vector3d twin = point + shift * (second.center - first.center);
      const Eigen::Vector3d in_second = second.ToCamera(twin);
      if (in_second.z() <= 0.0) continue;
      const Eigen::Vector2d pixel = second_camera.Project(in_second);
      if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > second_camera.width() - 1 ||
          pixel.y() > second_camera.height() - 1) {
        continue;
      }
      FeatureSet& features = scene->features.at(pair.second);
      Keypoint keypoint;
      keypoint.x = static_cast<float>(pixel.x());
      keypoint.y = static_cast<float>(pixel.y());
      match.j = static_cast<IndexT>(features.keypoints.size());
      features.keypoints.push_back(keypoint);
      twins.insert({pair, match});
    }
    scene->graph.AddEdge(pair, changed);
  }
  return twins;
}

LinkSet Links(const ViewGraph& graph) {
  LinkSet links;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    for (const FeatureMatch& match : edge.matches) links.insert({pair, match});
  });
  return links;
}

PositioningSceneOptions NoisyScene() {
  PositioningSceneOptions options = testing::SmallSceneOptions();
  options.pixel_noise_std = 0.5;
  return options;
}

TEST(LinkDepthVotes, KeepsEveryLinkOfATrueGraph) {
  const PositioningScene scene = MakePositioningScene(NoisyScene());
  LinkDepthVoteOptions options;
  options.enabled = true;
  const LinkDepthVoteResult result = DropDepthInconsistentLinks(options, scene.graph, scene.sfm_data, scene.features);
  ASSERT_GT(result.num_links, 10000u);
  // Pixel noise moves a far point's inverse depth by a few per cent, far below the factor of 2.
  EXPECT_LE(result.num_dropped_links, result.num_links / 1000);
}

TEST(LinkDepthVotes, DropsLinksShiftedAlongTheBaseline) {
  for (const double shift : {0.6, 1.0}) {  // depth x2.5, and at infinity
    PositioningScene scene = MakePositioningScene(NoisyScene());
    const LinkSet twins = InjectTwinLinks(&scene, 5, shift);
    const LinkSet before = Links(scene.graph);
    ASSERT_GT(twins.size(), 300u) << "shift " << shift;  // most shifted points leave the image

    LinkDepthVoteOptions options;
    options.enabled = true;
    const LinkDepthVoteResult result = DropDepthInconsistentLinks(options, scene.graph, scene.sfm_data, scene.features);
    const LinkSet after = Links(result.graph);
    size_t twins_dropped = 0, true_dropped = 0;
    for (const LinkKey& link : before) {
      if (after.count(link) > 0) continue;
      ++(twins.count(link) > 0 ? twins_dropped : true_dropped);
    }
    EXPECT_EQ(result.num_dropped_links, twins_dropped + true_dropped);
    EXPECT_GE(twins_dropped, twins.size() * 95 / 100) << "shift " << shift;
    EXPECT_LE(true_dropped, (before.size() - twins.size()) / 100) << "shift " << shift;
    // The input graph is not modified; the output keeps its edges and poses.
    EXPECT_EQ(Links(scene.graph).size(), before.size());
    EXPECT_EQ(result.graph.NumValidEdges(), scene.graph.NumValidEdges());
  }
}

TEST(LinkDepthVotes, DisabledKeepsTheGraph) {
  PositioningScene scene = MakePositioningScene(NoisyScene());
  InjectTwinLinks(&scene, 10, 1.0);
  LinkDepthVoteOptions options;
  options.enabled = false;
  const LinkDepthVoteResult result = DropDepthInconsistentLinks(options, scene.graph, scene.sfm_data, scene.features);
  EXPECT_EQ(result.num_dropped_links, 0u);
  EXPECT_EQ(Links(result.graph).size(), Links(scene.graph).size());
}

TEST(LinkDepthVotes, CheckNamesTheFieldOutOfRange) {
  EXPECT_EQ(testing::CheckMessage(LinkDepthVoteOptions{}), "");
  testing::ExpectEachCaseNamesItsField<LinkDepthVoteOptions>({
      {[](auto* o) { o->max_inverse_depth_ratio = 0.5; }, "LinkDepthVoteOptions::max_inverse_depth_ratio"},
      {[](auto* o) { o->max_inverse_depth_ratio = testing::kNan; }, "LinkDepthVoteOptions::max_inverse_depth_ratio"},
      {[](auto* o) { o->far_fraction = 0.0; }, "LinkDepthVoteOptions::far_fraction"},
      {[](auto* o) { o->far_fraction = 1.5; }, "LinkDepthVoteOptions::far_fraction"},
      {[](auto* o) { o->min_shared_features = 0; }, "LinkDepthVoteOptions::min_shared_features"},
      {[](auto* o) { o->angular_noise_deg = -0.1; }, "LinkDepthVoteOptions::angular_noise_deg"},
      {[](auto* o) { o->angular_noise_deg = testing::kNan; }, "LinkDepthVoteOptions::angular_noise_deg"},
  });
}

}  // namespace
}  // namespace sfm_pruning
