// Ground truth of synthetic scenes: determinism, reprojection, feature ids.
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

SyntheticSceneOptions SmallOptions(const std::string& scene, uint64_t seed = 7) {
  SyntheticSceneOptions options;
  options.scene = scene;
  options.seed = seed;
  options.num_views = 10;
  options.point_density_scale = 0.4;
  return options;
}

bool SameFeatures(const FeaturesPerView& a, const FeaturesPerView& b) {
  if (a.size() != b.size()) return false;
  for (const auto& [view, fa] : a) {
    const auto it = b.find(view);
    if (it == b.end()) return false;
    const FeatureSet& fb = it->second;
    if (fa.size() != fb.size() || fa.descriptors != fb.descriptors) return false;
    // Byte comparison: the same seed must give the same floats, not merely close ones.
    if (std::memcmp(fa.keypoints.data(), fb.keypoints.data(), fa.size() * sizeof(Keypoint)) != 0) return false;
  }
  return true;
}

TEST(SyntheticScene, SameSeedGivesIdenticalScene) {
  for (const char* name : {"orbit_symmetric", "street"}) {
    const SyntheticScene a = GenerateSyntheticScene(SmallOptions(name));
    const SyntheticScene b = GenerateSyntheticScene(SmallOptions(name));
    EXPECT_TRUE(a.ground_truth == b.ground_truth) << name;
    EXPECT_TRUE(SameFeatures(a.features, b.features)) << name;
    EXPECT_EQ(a.putative_matches, b.putative_matches) << name;
    EXPECT_EQ(a.feature_landmarks, b.feature_landmarks) << name;
    EXPECT_EQ(a.twin_landmarks, b.twin_landmarks) << name;
    EXPECT_FALSE(a.putative_matches.empty()) << name;
  }
}

TEST(SyntheticScene, ThreadsDoNotChangeTheMatches) {
  SyntheticSceneOptions options = SmallOptions("street");
  const SyntheticScene one = GenerateSyntheticScene(options);
  options.num_threads = 2;
  const SyntheticScene two = GenerateSyntheticScene(options);
  EXPECT_FALSE(one.putative_matches.empty());
  EXPECT_EQ(one.putative_matches, two.putative_matches);
}

TEST(SyntheticScene, DifferentSeedGivesDifferentScene) {
  const SyntheticScene a = GenerateSyntheticScene(SmallOptions("orbit_symmetric", 1));
  const SyntheticScene b = GenerateSyntheticScene(SmallOptions("orbit_symmetric", 2));
  EXPECT_FALSE(a.ground_truth == b.ground_truth);
  EXPECT_FALSE(SameFeatures(a.features, b.features));
}

// Every observation lies within the pixel noise of its landmark's projection, and the noise has
// the requested standard deviation.
TEST(SyntheticScene, ObservationsReprojectWithinNoise) {
  for (const double sigma : {0.0, 1.0, 2.5}) {
    SyntheticSceneOptions options = SmallOptions("orbit_symmetric");
    options.noise_px = sigma;
    const SyntheticScene scene = GenerateSyntheticScene(options);
    const SfmData& gt = scene.ground_truth;
    double sum_sq = 0.0;
    size_t count = 0;
    for (const auto& [id, landmark] : gt.structure) {
      for (const auto& [view_id, observation] : landmark.observations) {
        const View& view = gt.views.at(view_id);
        const Eigen::Vector2d projected = gt.IntrinsicsOf(view).Project(gt.PoseOf(view).ToCamera(landmark.X));
        const double error = (projected - observation.x).norm();
        // 2-D Gaussian: beyond 6 sigma has probability exp(-18); float keypoints add ~1e-4 px.
        ASSERT_LE(error, 6.0 * sigma + 1e-3) << "landmark " << id << " view " << view_id;
        sum_sq += error * error;
        ++count;
      }
    }
    ASSERT_GT(count, 1000u);
    const double rms_per_axis = std::sqrt(sum_sq / (2.0 * count));
    EXPECT_NEAR(rms_per_axis, sigma, 0.05 * sigma + 1e-3) << "sigma " << sigma;
  }
}

TEST(SyntheticScene, ObservationsIndexTheirFeatures) {
  const SyntheticScene scene = GenerateSyntheticScene(SmallOptions("street"));
  size_t checked = 0;
  for (const auto& [id, landmark] : scene.ground_truth.structure) {
    ASSERT_GE(landmark.observations.size(), 2u);
    for (const auto& [view_id, observation] : landmark.observations) {
      const FeatureSet& features = scene.features.at(view_id);
      ASSERT_LT(observation.id_feat, features.size());
      EXPECT_EQ(features.Position(observation.id_feat), observation.x);
      EXPECT_EQ(scene.feature_landmarks.at(view_id)[observation.id_feat], id);
      ++checked;
    }
  }
  EXPECT_GT(checked, 500u);
  // Every feature has a descriptor, and clutter exists but does not dominate (clutter_ratio 0.3).
  size_t clutter = 0, total = 0;
  for (const auto& [view_id, features] : scene.features) {
    EXPECT_EQ(features.descriptors.size(), features.size());
    for (IndexT landmark : scene.feature_landmarks.at(view_id)) clutter += landmark == kUndefinedIndex;
    total += features.size();
  }
  EXPECT_NEAR(static_cast<double>(clutter) / total, 0.3 / 1.3, 0.02);
}

TEST(SyntheticScene, CamerasAndIntrinsicsFollowTheOptions) {
  SyntheticSceneOptions options = SmallOptions("clean");
  options.image_width = 1600;
  options.image_height = 1200;
  const SyntheticScene scene = GenerateSyntheticScene(options);
  ASSERT_EQ(scene.ground_truth.views.size(), 10u);
  ASSERT_EQ(scene.ground_truth.intrinsics.size(), 1u);
  const CameraIntrinsics& k = scene.ground_truth.intrinsics.at(0);
  EXPECT_EQ(k.width(), 1600u);
  EXPECT_DOUBLE_EQ(k.FocalLength(), 1.2 * 1600);
  EXPECT_NO_THROW(ValidateSfmData(scene.ground_truth, "synthetic"));
  for (const auto& [id, view] : scene.ground_truth.views) EXPECT_TRUE(scene.ground_truth.IsPosed(id));
}

TEST(SyntheticScene, RejectsBadOptions) {
  SyntheticSceneOptions options = SmallOptions("nowhere");
  EXPECT_THROW(GenerateSyntheticScene(options), Error);
  options = SmallOptions("clean");
  options.outlier_ratio = 1.0;
  EXPECT_THROW(GenerateSyntheticScene(options), Error);
  options = SmallOptions("clean");
  options.num_views = 1;
  EXPECT_THROW(GenerateSyntheticScene(options), Error);
  // Infinite clutter would never finish and an infinite density would exhaust memory: refused
  // before any work, as is NaN, which fails every comparison.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double SyntheticSceneOptions::*field :
       {&SyntheticSceneOptions::clutter_ratio, &SyntheticSceneOptions::point_density_scale,
        &SyntheticSceneOptions::noise_px, &SyntheticSceneOptions::focal_px, &SyntheticSceneOptions::max_incidence_deg,
        &SyntheticSceneOptions::street_module_width_m}) {
    for (const double value : {inf, nan, 1e308}) {
      options = SmallOptions("clean");
      options.*field = value;
      EXPECT_THROW(GenerateSyntheticScene(options), Error) << value;
    }
  }
}

}  // namespace
}  // namespace sfm_pruning
