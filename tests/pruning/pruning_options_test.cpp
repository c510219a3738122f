// Every pruning options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;

TEST(PruningOptions, DefaultsPass) { EXPECT_NO_THROW(ViewGraphPruningOptions().Check()); }

TEST(PruningOptions, EachStructNamesItsBadField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ExpectEachCaseNamesItsField<ViewGraphPruningOptions>({
      {[](ViewGraphPruningOptions* o) { o->max_sample_size = 1; }, "ViewGraphPruningOptions::max_sample_size"},
      {[](ViewGraphPruningOptions* o) { o->trust_prior_edges = -1.0; }, "ViewGraphPruningOptions::trust_prior_edges"},
      {[](ViewGraphPruningOptions* o) { o->num_threads = 0; }, "ViewGraphPruningOptions::num_threads"},
      {[](ViewGraphPruningOptions* o) { o->partition.max_depth = -1; }, "RecursivePartitionOptions::max_depth"},
      {[&](ViewGraphPruningOptions* o) { o->partition.louvain.resolution = nan; },
       "LouvainOptions::resolution"},
      {[](ViewGraphPruningOptions* o) { o->partition.consistency.max_relative_rotation_error_deg = 0.0; },
       "ConsistencyTestOptions::max_relative_rotation_error_deg"},
      {[](ViewGraphPruningOptions* o) { o->partition.consistency.max_baseline_ratio_factor = 0.5; },
       "ConsistencyTestOptions::max_baseline_ratio_factor"},
      {[](ViewGraphPruningOptions* o) { o->partition.consistency.baseline_ratio.min_parallax_deg = 95.0; },
       "BaselineRatioOptions::min_parallax_deg"},
      {[](ViewGraphPruningOptions* o) { o->alignment.sample_fraction = 1.5; },
       "SubgraphAlignmentOptions::sample_fraction"},
      {[](ViewGraphPruningOptions* o) { o->alignment.min_sample_size = 1; },
       "SubgraphAlignmentOptions::min_sample_size"},
      {[](ViewGraphPruningOptions* o) { o->alignment.placement.min_correspondences = 3; },
       "EdgePlacementOptions::min_correspondences"},
      {[](ViewGraphPruningOptions* o) { o->loops.max_scale_ratio = 0.9; }, "SubgraphLoopOptions::max_scale_ratio"},
      {[](ViewGraphPruningOptions* o) { o->audit.keep_agreement = 0.9; }, "ModelEdgeAuditOptions::keep_agreement"},
      {[](ViewGraphPruningOptions* o) { o->audit.readmit_agreement = 1.5; },
       "ModelEdgeAuditOptions::readmit_agreement"},
      {[](ViewGraphPruningOptions* o) { o->landmark_check.max_angle_deg = -5.0; },
       "LandmarkMatchCheckOptions::max_angle_deg"},
  });
  // Off values are not out of range.
  EXPECT_EQ(CheckMessage<ViewGraphPruningOptions>([](ViewGraphPruningOptions* o) {
              o->max_sample_size = 0;
              o->partition.consistency.max_baseline_ratio_factor = 0.0;
              o->landmark_check.max_angle_deg = 0.0;
            }),
            "");
}

TEST(PruningOptions, PruneViewGraphRefusesBadOptionsBeforeAnyWork) {
  ViewGraphPruningOptions options;
  options.alignment.num_ransac_iterations = 0;
  ViewGraph graph;
  EXPECT_THROW(PruneViewGraph(options, &graph, SfmData(), FeaturesPerView(), nullptr), std::invalid_argument);
}

// GLOBAL_PRUNED's options check the pruning's and the final solve's.
TEST(PruningOptions, PrunedGlobalEngineOptionsCheckThePruningAndTheFinalSolve) {
  EXPECT_NO_THROW(PrunedGlobalEngineOptions().Check());
  PrunedGlobalEngineOptions seeded;
  seeded.SetSeedAndThreads(7, 4, 2);
  EXPECT_NO_THROW(seeded.Check());
  ExpectEachCaseNamesItsField<PrunedGlobalEngineOptions>({
      {[](PrunedGlobalEngineOptions* o) { o->pruning.num_threads = 0; }, "ViewGraphPruningOptions::num_threads"},
      {[](PrunedGlobalEngineOptions* o) { o->pruning.audit.keep_agreement = 1.5; },
       "ModelEdgeAuditOptions::keep_agreement"},
      {[](PrunedGlobalEngineOptions* o) { o->engine.num_threads = 0; }, "GlobalEngineOptions::num_threads"},
      {[](PrunedGlobalEngineOptions* o) { o->engine.bundle.function_tolerance = -1.0; },
       "BundleAdjustmentOptions::function_tolerance"},
  });
}

TEST(PruningOptions, PruneAndAuditRefusesBadOptionsBeforeAnyWork) {
  PrunedGlobalEngineOptions options;
  options.engine.num_bundle_rounds = -1;
  ViewGraph pruned;
  SfmData model;
  PrunedGlobalEngineReport report;
  EXPECT_THROW(PruneAndAudit(options, ViewGraph(), SfmData(), FeaturesPerView(), &pruned, &model, &report),
               std::invalid_argument);
  EXPECT_THROW(RunPrunedGlobalEngine(options, ViewGraph(), SfmData(), FeaturesPerView(), &model, &report),
               std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
