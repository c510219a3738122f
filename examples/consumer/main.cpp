// GLOBAL_PRUNED through the library API, as another project uses it: a generated object whose
// two halves look alike (16 views around it) goes through the reconstruction controller
// (verification, pruning, the final solve), then the pose accuracy is measured against the
// scene's ground truth. Exit code 0 when the model is accurate (AUC@10 >= 90), 1 otherwise.
#include <cstdio>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/pipeline/reconstruction.hpp"

int main() {
  using namespace sfm_pruning;
  SyntheticSceneOptions scene_options;
  scene_options.scene = "orbit_symmetric";
  scene_options.seed = 1;
  scene_options.num_views = 16;
  const SyntheticScene scene = GenerateSyntheticScene(scene_options);

  // The controller sees the views, intrinsics, features and matches, not the true poses
  // (ReadColmapInput or ReadOpenMvgInput fill the same input from files).
  ReconstructionInput input;
  input.source = scene.name;
  input.scene = scene.ground_truth;
  input.scene.poses.clear();
  input.scene.structure.clear();
  input.features = scene.features;
  input.putative = scene.putative_matches;

  ReconstructionOptions options;
  options.engine = ReconstructionEngine::kGlobalPruned;
  options.intrinsics.cameras =
      IntrinsicsRefinementOptions::Cameras::kNone;  // the generated cameras are exact
  options.Check();
  const ReconstructionResult result =
      Reconstruct(options, input, {}, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  if (!result.success) {
    std::fprintf(stderr, "GLOBAL_PRUNED failed: %s\n", result.message.c_str());
    return 1;
  }
  const EvaluationReport evaluation = EvaluateModel(result.model, scene.ground_truth);
  double auc10 = 0.0;
  for (const AucAtThreshold& auc : evaluation.auc) {
    if (auc.threshold_deg == 10.0) auc10 = auc.auc_percent;
  }
  std::printf("GLOBAL_PRUNED on %s: %zu of %zu views registered, %zu of %zu edges removed, AUC@10 %.1f\n",
              scene.name.c_str(), evaluation.num_registered_images, scene.ground_truth.views.size(),
              result.pruning->removed_edges.size(), result.view_graph.edges.size(), auc10);
  return auc10 >= 90.0 ? 0 : 1;
}
