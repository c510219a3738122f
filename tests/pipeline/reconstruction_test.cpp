#include "sfm_pruning/pipeline/reconstruction.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

// A generated scene as a reconstruction input: views, intrinsics, features and putative
// matches, no poses.
struct GeneratedInput {
  SyntheticScene scene;
  ReconstructionInput input;
};

GeneratedInput MakeInput(const std::string& name, int num_views) {
  SyntheticSceneOptions options;
  options.scene = name;
  options.seed = 1;
  options.num_views = num_views;
  GeneratedInput generated{GenerateSyntheticScene(options), {}};
  generated.input.source = name;
  generated.input.scene = generated.scene.ground_truth;
  generated.input.scene.poses.clear();
  generated.input.scene.structure.clear();
  generated.input.features = generated.scene.features;
  generated.input.putative = generated.scene.putative_matches;
  return generated;
}

double Auc(const SfmData& model, const SfmData& truth, double threshold_deg) {
  for (const AucAtThreshold& auc : EvaluateModel(model, truth).auc) {
    if (auc.threshold_deg == threshold_deg) return auc.auc_percent;
  }
  return 0.0;
}

TEST(Reconstruction, GlobalSolvesACleanScene) {
  const GeneratedInput generated = MakeInput("clean", 12);
  ReconstructionOptions options;
  options.intrinsics.cameras =
      IntrinsicsRefinementOptions::Cameras::kNone;  // the generated cameras are exact
  std::vector<std::string> log;
  const ReconstructionResult result =
      Reconstruct(options, generated.input, {}, [&](const std::string& line) { log.push_back(line); });
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.model.poses.size(), 12u);
  EXPECT_GT(Auc(result.model, generated.scene.ground_truth, 5.0), 95.0);
  EXPECT_FALSE(result.pruning.has_value());
  EXPECT_TRUE(result.refined_intrinsics.empty());
  EXPECT_FALSE(result.calibration.has_value());
  EXPECT_EQ(result.build.num_pairs, generated.input.putative.size());
  EXPECT_GT(result.verification_seconds, 0.0);
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.front().rfind("view graph: ", 0), 0u) << log.front();
}

TEST(Reconstruction, GlobalPrunedUnfoldsASymmetricObject) {
  const GeneratedInput generated = MakeInput("orbit_symmetric", 16);
  ReconstructionOptions options;
  options.engine = ReconstructionEngine::kGlobalPruned;
  options.intrinsics.cameras = IntrinsicsRefinementOptions::Cameras::kNone;
  const ReconstructionResult result = Reconstruct(options, generated.input);
  ASSERT_TRUE(result.success) << result.message;
  ASSERT_TRUE(result.pruning.has_value());
  EXPECT_FALSE(result.pruning->removed_edges.empty());
  EXPECT_GT(Auc(result.model, generated.scene.ground_truth, 10.0), 90.0);
  EXPECT_EQ(result.view_graph.engine, "GLOBAL_PRUNED");
}

TEST(Reconstruction, NoMatchesIsAnErrorNamingTheSource) {
  GeneratedInput generated = MakeInput("clean", 6);
  generated.input.putative.clear();
  try {
    Reconstruct(ReconstructionOptions{}, generated.input);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("clean: no two images match"), std::string::npos) << e.what();
  }
}

TEST(Reconstruction, OptionsAreChecked) {
  const auto rejects = [](auto change) {
    ReconstructionOptions options;
    change(&options);
    EXPECT_THROW(options.Check(), std::invalid_argument);
  };
  rejects([](ReconstructionOptions* o) { o->num_threads = -1; });
  rejects([](ReconstructionOptions* o) { o->solver_threads = 0; });
  rejects([](ReconstructionOptions* o) { o->positioning_random_starts = 0; });
  rejects([](ReconstructionOptions* o) { o->positioning_start_screening_iterations = -1; });
  rejects([](ReconstructionOptions* o) { o->max_epipolar_error_deg = 0.0; });
  rejects([](ReconstructionOptions* o) { o->verification_precision_ratio = 1.5; });
  rejects([](ReconstructionOptions* o) { o->intrinsics.refocus_threshold = 0.0; });
  rejects([](ReconstructionOptions* o) {
    o->positioning = PositioningMethod::kTranslationAveraging;
    o->positioning_tracks = PositioningTracks::kMatchStars;
  });
  EXPECT_NO_THROW(ReconstructionOptions().Check());
}

TEST(Reconstruction, NamesRoundTrip) {
  for (const auto engine : {ReconstructionEngine::kGlobal, ReconstructionEngine::kGlobalPruned}) {
    EXPECT_EQ(ParseReconstructionEngine(ReconstructionEngineName(engine)), engine);
  }
  EXPECT_THROW(ParseReconstructionEngine("INCREMENTAL"), std::invalid_argument);
  using Cameras = IntrinsicsRefinementOptions::Cameras;
  for (const auto cameras : {Cameras::kAuto, Cameras::kGuessed, Cameras::kAll, Cameras::kNone}) {
    EXPECT_EQ(ParseIntrinsicsCameras(IntrinsicsCamerasName(cameras)), cameras);
  }
  EXPECT_THROW(ParseIntrinsicsCameras("SOME"), std::invalid_argument);
}

TEST(IntrinsicsRefinement, AutoRefinesAllButKFileCamerasAndCalibratesOnlyGuessedFocals) {
  ReconstructionInput input = MakeInput("clean", 4).input;
  // Three cameras: 0 guessed, 1 with an EXIF-like prior, 2 from a K file.
  const CameraIntrinsics camera = input.scene.intrinsics.begin()->second;
  input.scene.intrinsics.clear();
  for (IndexT id = 0; id < 3; ++id) input.scene.intrinsics.emplace(id, camera);
  input.guessed_focal = {0};
  input.k_file_intrinsics = {2};
  IntrinsicsRefinementOptions options;
  EXPECT_EQ(RefinedIntrinsics(options, input), (std::set<IndexT>{0, 1}));
  EXPECT_EQ(FocalsToCalibrate(options, input), (std::set<IndexT>{0}));
  const BundleAdjustmentOptions bundle =
      RefiningBundleOptions(options, input, RefinedIntrinsics(options, input));
  EXPECT_EQ(bundle.constant_intrinsics, (std::set<IndexT>{2}));
  EXPECT_EQ(bundle.constant_principal_point, (std::set<IndexT>{1}));
  options.cameras = IntrinsicsRefinementOptions::Cameras::kAll;
  EXPECT_EQ(FocalsToCalibrate(options, input), (std::set<IndexT>{0, 1, 2}));
  options.cameras = IntrinsicsRefinementOptions::Cameras::kNone;
  EXPECT_TRUE(RefinedIntrinsics(options, input).empty());
}

}  // namespace
}  // namespace sfm_pruning
