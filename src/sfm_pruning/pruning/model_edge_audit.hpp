// The pruning's decisions reviewed against the model solved from the pruned graph (PruneSfM's
// addition to the paper; docs/pruning.md, "The model's audit of the pruning").
//
// Why: the inter-subgraph pruning decides each edge from subgraph solutions, and a subgraph of two
// or three views places its neighbours poorly (a true edge placed 10° off by the 26 landmarks of a
// two-view subgraph is cut as inconsistent). Where a stretch of the scene is joined to the rest by
// only a few true edges, losing some of them bends the final model (synthetic street: the pruned
// graph minus two twins 90.8 AUC@10, with its true edges back 95.6). The model solved from the
// pruned graph is a far better judge of one edge than any subgraph: a true match (f_i, f_j) has its
// landmark, seen through f_i, project onto f_j in view j; a twin match pairs f_i with the copy of its
// point one period away, which projects hundreds of pixels off.
//
// AuditEdgesAgainstModel measures, for every given edge with both views posed in the model, the
// share of its matches whose landmark (through either feature) projects within
// max_transfer_error_px of the other feature. The caller re-admits removed edges that agree and
// removes kept ones that do not, then adjusts the audited graph from the model's poses
// (RunPrunedGlobalEngine).
#pragma once

#include <cstddef>
#include <vector>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// How far the solve before the audit goes.
enum class AuditModelSchedule {
  kPositioning,       // rotation averaging and positioning only
  kLightAdjustment,   // + one adjustment on a subset of the landmarks (the others re-triangulated),
                      //   with the iteration cap and tolerance of the rounds before the final one
  kFull,              // the final solve's schedule
};

struct ModelEdgeAuditOptions {
  // Off by default: on the development split of the scene families (6 seeds per family) the
  // audit's re-admissions lock in the fold of a model solved from a pruned graph that kept some twin
  // edges (objects whose faces print alike: median AUC@10 4.2 with it, 30.6 without), and its
  // removals cost one twin-free control 5.0 (docs/pruning.md).
  bool enabled = false;
  double max_transfer_error_px = 8.0;
  // An edge with fewer matches on landmarks of the model is not judged (left as the pruning decided).
  size_t min_transferred_matches = 10;
  // Share of the transferred matches within max_transfer_error_px: a removed edge at or above
  // readmit_agreement is re-admitted, a kept one below keep_agreement removed. The gap is for the
  // edges whose matches are part true, part twin (synthetic street at 0.08° verification: true
  // edges 0.6–1.0, their twin matches are near the epipolar line too; pure twins ≤ 0.14; edges of
  // 25–56 true and 57–88 twin matches 0.45–0.79, which bend the model when re-admitted).
  double readmit_agreement = 0.8;
  double keep_agreement = 0.2;
  // The model the audit judges from, and the final solve after it. A full solve before the final
  // one doubled GLOBAL_PRUNED's reconstruction time (sequential_large@1000: 178.7 s of 414.9 s;
  // docs/pruning.md). The audit needs each landmark within a few pixels, not the final accuracy;
  // and the audited graph differs from the solved one by a few edges, so the final solve can start
  // from the audited model's poses (RefineGlobalModel) instead of solving from scratch.
  AuditModelSchedule model_schedule = AuditModelSchedule::kLightAdjustment;
  bool refine_final = true;  // false: the final solve from scratch (RunGlobalEngine)

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct EdgeAgreement {
  ViewPair pair{kUndefinedIndex, kUndefinedIndex};
  size_t transferred = 0;  // matches with a landmark through either feature
  size_t agreeing = 0;     // ... that project within the bound
  double Share() const {
    return transferred > 0 ? static_cast<double>(agreeing) / static_cast<double>(transferred) : 0.0;
  }
};

// One entry per edge of `edges` (in order) that exists in `graph` with both views posed in `model`.
std::vector<EdgeAgreement> AuditEdgesAgainstModel(const ViewGraph& graph, const std::vector<ViewPair>& edges,
                                                  const SfmData& model, const FeaturesPerView& features,
                                                  const ModelEdgeAuditOptions& options);

}  // namespace sfm_pruning
