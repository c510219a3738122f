// The scene the engine tests share: a small `clean` synthetic scene (no duplicate structure,
// 1 px noise, 20 % random wrong matches), generated once per test binary.
#pragma once

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/global/global_engine.hpp"

namespace sfm_pruning::testing {

inline const SyntheticScene& CleanScene() {
  static const SyntheticScene scene = []() {
    SyntheticSceneOptions options;
    options.scene = "clean";
    options.seed = 3;
    options.num_views = 20;
    return GenerateSyntheticScene(options);
  }();
  return scene;
}

// The scene's views and intrinsics without poses or structure (what a listing holds).
inline SfmData Listing(const SyntheticScene& scene) {
  SfmData listing = scene.ground_truth;
  listing.poses.clear();
  listing.structure.clear();
  return listing;
}

struct EngineRun {
  ViewGraphBuildReport build;
  GlobalEngineReport engine;
  SfmData model;
};

inline EngineRun RunEngineOn(const SyntheticScene& scene, const PairwiseMatches& matches,
                             const ViewGraphBuildOptions& build_options = {},
                             const GlobalEngineOptions& engine_options = {}) {
  EngineRun run;
  const SfmData listing = Listing(scene);
  const ViewGraph graph = BuildViewGraphFromMatches(build_options, listing, scene.features, matches, &run.build);
  RunGlobalEngine(engine_options, graph, listing, scene.features, &run.model, &run.engine);
  return run;
}

inline double AucAt(const EvaluationReport& report, double threshold_deg) {
  for (const AucAtThreshold& auc : report.auc) {
    if (auc.threshold_deg == threshold_deg) return auc.auc_percent;
  }
  return -1.0;
}

}  // namespace sfm_pruning::testing
