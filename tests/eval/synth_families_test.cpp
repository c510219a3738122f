// Procedural scene families: each seed draws a scene, the draws span the family's range, twins
// exist where the family says and nowhere in the controls, and every scene is one a pipeline can
// work on (views see features, consecutive views share matches).
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "sfm_pruning/eval/synthetic_families.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"

namespace sfm_pruning {
namespace {

SyntheticSceneOptions FamilyOptions(const std::string& family, uint64_t seed) {
  SyntheticSceneOptions options;
  options.scene = family;
  options.seed = seed;
  options.point_density_scale = 0.5;  // keeps the tests quick; the geometry is the drawn one
  if (family == "family_loop") options.num_views = 240;  // two laps with repeated fronts on the straights
  return options;
}

size_t TrueMatches(const SyntheticScene& scene, IndexT a, IndexT b) {
  const auto it = scene.pair_stats.find(MakeViewPair(a, b));
  return it == scene.pair_stats.end() ? 0 : it->second.num_true;
}

TEST(SyntheticFamilies, AreListedAsScenes) {
  const std::vector<std::string> scenes = SyntheticSceneNames();
  for (const std::string& family : SyntheticFamilyNames()) {
    EXPECT_TRUE(IsSyntheticFamily(family));
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), family), scenes.end()) << family;
  }
  EXPECT_FALSE(IsSyntheticFamily("street"));
}

TEST(SyntheticFamilies, SameSeedGivesTheSameScene) {
  for (const char* family : {"family_street", "family_desk"}) {
    SyntheticSceneOptions options = FamilyOptions(family, 5);
    options.num_views = 8;
    options.point_density_scale = 0.2;
    const SyntheticScene a = GenerateSyntheticScene(options);
    const SyntheticScene b = GenerateSyntheticScene(options);
    EXPECT_EQ(a.description.values, b.description.values) << family;
    EXPECT_EQ(a.description.labels, b.description.labels) << family;
    ASSERT_EQ(a.putative_matches.size(), b.putative_matches.size()) << family;
    for (const auto& [pair, matches] : a.putative_matches) EXPECT_EQ(matches.size(), b.putative_matches.at(pair).size());
  }
}

TEST(SyntheticFamilies, SeedsDrawDifferentScenesAcrossTheFamilyRange) {
  std::set<std::string> folds, shapes;
  std::set<double> module_widths;
  for (uint64_t seed = 0; seed < 24; ++seed) {
    SyntheticSceneOptions options = FamilyOptions("family_courtyard", seed);
    options.num_views = 4;
    options.point_density_scale = 0.1;
    const SyntheticScene scene = GenerateSyntheticScene(options);
    folds.insert(scene.description.labels.at("fold"));
    shapes.insert(scene.description.labels.at("shape"));
  }
  EXPECT_EQ(folds, (std::set<std::string>{"2", "3", "4", "6"}));
  EXPECT_EQ(shapes, (std::set<std::string>{"polygon", "round"}));
  for (uint64_t seed = 0; seed < 6; ++seed) {
    SyntheticSceneOptions options = FamilyOptions("family_street", seed);
    options.num_views = 4;
    options.point_density_scale = 0.1;
    module_widths.insert(GenerateSyntheticScene(options).description.values.at("module_width_m"));
  }
  EXPECT_EQ(module_widths.size(), 6u);
}

TEST(SyntheticFamilies, CaptureConditionsAreDrawnWithinTheirRanges) {
  for (uint64_t seed = 0; seed < 8; ++seed) {
    SyntheticSceneOptions options = FamilyOptions("family_object", seed);
    options.num_views = 0;  // drawn
    options.point_density_scale = 0.1;
    const SyntheticScene scene = GenerateSyntheticScene(options);
    const SyntheticSceneOptions& o = scene.options;
    EXPECT_GE(o.num_views, 32);
    EXPECT_LE(o.num_views, 60);
    EXPECT_GE(o.noise_px, 0.5);
    EXPECT_LE(o.noise_px, 2.0);
    EXPECT_GE(o.outlier_ratio, 0.05);
    EXPECT_LE(o.outlier_ratio, 0.35);
    EXPECT_GE(o.dropout, 0.1);
    EXPECT_LE(o.dropout, 0.4);
    EXPECT_NEAR(o.focal_px / 1024.0, scene.description.values.at("focal_factor"), 1e-9);
  }
}

// Every ambiguous family has twins; the control has none.
TEST(SyntheticFamilies, TwinsWhereTheFamilySays) {
  for (const std::string& family : SyntheticFamilyNames()) {
    for (uint64_t seed : {1u, 100001u}) {
      SyntheticSceneOptions options = FamilyOptions(family, seed);
      // Twins are a property of the layout, not of the matches: few views, or (the loop, whose
      // repeated fronts need its length) few points.
      if (family == "family_loop") {
        options.point_density_scale = 0.05;
      } else {
        options.num_views = 4;
        options.point_density_scale = 0.3;
      }
      const SyntheticScene scene = GenerateSyntheticScene(options);
      const std::string what = family + " seed " + std::to_string(seed);
      EXPECT_EQ(scene.twin_landmarks.empty(), family == "family_control") << what;
      if (family != "family_loop") {  // the loop is sequential_large's layout, which records no draws
        const double share = scene.description.values.at("unique_share");
        EXPECT_GT(share, 0.0) << what;
        EXPECT_LE(share, 1.0) << what;
      }
    }
  }
}

// Every scene is one a pipeline can work on: views see features, consecutive views share matches.
TEST(SyntheticFamilies, ConsecutiveViewsShareTrueMatches) {
  for (const std::string& family : SyntheticFamilyNames()) {
    if (family == "family_loop") continue;  // sequential_large's layout: synth_sequential_test
    SyntheticSceneOptions options = FamilyOptions(family, 2);
    options.point_density_scale = 0.5;  // half the benchmark's points (and a quarter of its matching time)
    const SyntheticScene scene = GenerateSyntheticScene(options);
    const auto num_views = static_cast<IndexT>(scene.ground_truth.views.size());
    for (IndexT v = 0; v < num_views; ++v) EXPECT_GE(scene.features.at(v).size(), 15u) << family << " view " << v;
    size_t linked = 0;
    for (IndexT v = 0; v + 1 < num_views; ++v) linked += TrueMatches(scene, v, v + 1) >= 8 ? 1 : 0;
    EXPECT_GE(linked, (num_views - 1) * 8 / 10) << family;  // consecutive views mostly share 8+ true matches
  }
}

TEST(SyntheticFamilies, UniqueTextureDensityHitsTheShareWithinItsBounds) {
  // 1000 repeated points and 10 m^2 of unique texture: a 20 % share needs 250 points, 25 per m^2.
  EXPECT_NEAR(UniqueTextureDensity(0.2, 1000, 10.0, 0.5, 400.0), 25.0, 1e-9);
  EXPECT_DOUBLE_EQ(UniqueTextureDensity(0.2, 1000, 0.01, 0.5, 400.0), 400.0);
  EXPECT_DOUBLE_EQ(UniqueTextureDensity(0.0, 1000, 10.0, 0.5, 400.0), 0.5);
}

}  // namespace
}  // namespace sfm_pruning
