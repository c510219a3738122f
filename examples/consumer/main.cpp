// The GLOBAL_PRUNED engine through the library API, as another project uses it: a generated
// object whose two halves look alike (16 views around it), verification, pruning and the final
// solve, then the pose accuracy against the scene's ground truth.
// Exit code 0 when the model is accurate (AUC@10 >= 90), 1 otherwise.
#include <cstdio>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"

int main() {
  using namespace sfm_pruning;
  SyntheticSceneOptions scene_options;
  scene_options.scene = "orbit_symmetric";
  scene_options.seed = 1;
  scene_options.num_views = 16;
  const SyntheticScene scene = GenerateSyntheticScene(scene_options);

  // The engine sees the views and intrinsics only, not the true poses.
  SfmData views_and_intrinsics = scene.ground_truth;
  views_and_intrinsics.poses.clear();
  views_and_intrinsics.structure.clear();

  const ViewGraph graph = BuildViewGraphFromMatches(ViewGraphBuildOptions{}, views_and_intrinsics,
                                                    scene.features, scene.putative_matches);
  PrunedGlobalEngineOptions options;
  options.SetSeedAndThreads(/*seed=*/0, /*num_threads=*/1);
  SfmData model;
  PrunedGlobalEngineReport report;
  RunPrunedGlobalEngine(options, graph, views_and_intrinsics, scene.features, &model, &report);
  if (!report.engine.success) {
    std::fprintf(stderr, "GLOBAL_PRUNED failed: %s\n", report.engine.message.c_str());
    return 1;
  }
  const EvaluationReport evaluation = EvaluateModel(model, scene.ground_truth);
  double auc10 = 0.0;
  for (const AucAtThreshold& auc : evaluation.auc) {
    if (auc.threshold_deg == 10.0) auc10 = auc.auc_percent;
  }
  std::printf("GLOBAL_PRUNED on %s: %zu of %zu views registered, %zu of %zu edges removed, AUC@10 %.1f\n",
              scene.name.c_str(), evaluation.num_registered_images, scene.ground_truth.views.size(),
              report.pruning.removed_edges.size(), graph.Edges().size(), auc10);
  return auc10 >= 90.0 ? 0 : 1;
}
