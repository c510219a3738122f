#include "software/commands/pruning_options.hpp"

#include <CLI/CLI.hpp>

#include <map>
#include <string>

#include "software/cli_checks.hpp"
#include "software/help_format.hpp"

namespace prunesfm {

namespace {

const std::map<std::string, sfm_pruning::AuditModelSchedule>& AuditModelNames() {
  using AuditModelSchedule = sfm_pruning::AuditModelSchedule;
  static const std::map<std::string, AuditModelSchedule> names{{"positioned", AuditModelSchedule::kPositioning},
                                                                {"adjusted", AuditModelSchedule::kLightAdjustment},
                                                                {"full", AuditModelSchedule::kFull}};
  return names;
}

// First in the group: CLI11 stores the options' values in the order they are defined, so the
// preset is applied before, and overridden by, any flag given with it.
void AddPresetFlag(CLI::App* group, sfm_pruning::ViewGraphPruningOptions* options) {
  group->add_option_function<std::string>(
          "--prune_preset",
          [options](const std::string& preset) {
            if (preset == "paper") sfm_pruning::ApplyPaperMethod(options);
          },
          "default: the paper's method with PruneSfM's additions; paper: every addition off (flags given "
          "with it still apply)")
      ->check(CLI::IsMember({"default", "paper"}))
      ->default_str("default");
}

// The capture-order prior (capture_order.hpp).
void AddCaptureOrderFlags(CLI::App* group, sfm_pruning::CaptureOrderOptions* capture_order) {
  using Use = sfm_pruning::CaptureOrderOptions::Use;
  group->add_option("--prune_capture_order_use", capture_order->use,
                    "Whether the image order is the capture order (photos taken along a path): auto decides "
                    "from the view graph, sequential and unordered say so (docs/pruning.md)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, Use>{{"auto", Use::kAuto},
                                                                     {"sequential", Use::kSequential},
                                                                     {"unordered", Use::kUnordered}},
                                          CLI::ignore_case))
      ->default_str(sfm_pruning::CaptureOrderUseName(capture_order->use));
  group->add_option("--prune_capture_order_neighbour_window_views", capture_order->neighbour_window_views,
                    "Images at most this many places apart in the capture order are capture neighbours")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  group->add_option("--prune_capture_order_partition_weight_factor", capture_order->partition_weight_factor,
                    "Louvain weight of an edge between capture neighbours, as a multiple of its weight")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  group->add_option("--prune_capture_path_window_views", capture_order->path_window_views,
                    "Capture path: images at most this many places apart give the path's rotations and model")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  group->add_option("--prune_capture_path_max_deviation_deg", capture_order->path_max_deviation_deg,
                    "Capture path: an edge whose rotation deviates from the path's by more than this (or the "
                    "path's drift between its images, if larger) is removed before the partition; 0: off")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str();
  group->add_option("--prune_capture_path_max_direction_deviation_deg",
                    capture_order->path_max_direction_deviation_deg,
                    "Capture path: an edge between images further apart than the path's window whose translation "
                    "direction deviates by more than this (or the path's drift, if larger) from the model solved from "
                    "the path's edges is removed before the partition; 0: off")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str();
}

// Subgraph partition.
void AddPartitionFlags(CLI::App* group, sfm_pruning::RecursivePartitionOptions* partition) {
  group->add_option("--prune_recursive", partition->recursive,
                    "Partition inconsistent communities again (false: one Louvain pass, ablation)")
      ->capture_default_str();
  group->add_option("--prune_max_depth", partition->max_depth, "Depth at which communities are no longer split")
      ->check(NonNegativeValue())
      ->capture_default_str();
  group->add_option("--prune_louvain_resolution", partition->louvain.resolution,
                    "Modularity resolution gamma of Louvain (1 = classic modularity)")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_bisect_unsplittable", partition->bisect_unsplittable,
                    "Cut an inconsistent community that Louvain returns whole in two by spectral bisection "
                    "instead of accepting it (not in the paper; docs/pruning.md)")
      ->capture_default_str();
  using EdgeWeight = sfm_pruning::RecursivePartitionOptions::EdgeWeight;
  group->add_option("--prune_edge_weight", partition->edge_weight,
                    "Edge similarity of the Louvain partition. inliers: the paper's inlier count; distinctive: "
                    "each inlier weighs 1/(views its features match in), so repeated structure seen by every "
                    "view counts little (docs/pruning.md)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, EdgeWeight>{{"inliers", EdgeWeight::kInliers},
                                            {"distinctive", EdgeWeight::kDistinctiveMatches}},
          CLI::ignore_case))
      ->default_str("distinctive");
}

// Consistency tests of a community's solution.
void AddConsistencyTestFlags(CLI::App* group, sfm_pruning::ConsistencyTestOptions* consistency) {
  group->add_option("--prune_test_loops", consistency->test_loops, "Loop rotation consistency test on/off")
      ->capture_default_str();
  group->add_option("--prune_test_relative_rotation", consistency->test_relative_rotation,
                    "Relative-to-absolute rotation test (e_r) on/off")
      ->capture_default_str();
  group->add_option("--prune_test_relative_translation", consistency->test_relative_translation,
                    "Translation direction test (e_t) on/off")
      ->capture_default_str();
  group->add_option("--prune_max_baseline_ratio_factor", consistency->max_baseline_ratio_factor,
                    "Baseline-ratio test (not in the paper): two edges of a view that triangulate the same "
                    "features measure the ratio of their baselines; a community fails when its solution's ratio "
                    "differs by more than this factor (0: off; docs/pruning.md)")
      ->check(NonNegativeValue())
      ->capture_default_str();
  group->add_option("--prune_loop_step_deg", consistency->loop_step_deg,
                    "A loop of l cameras may deviate by this * floor((l-1)/2) degrees")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_max_cycle_length", consistency->cycles.max_cycle_length,
                    "Longest loop tested, in cameras (paper: fewer than 8)")
      ->check(RangeValue(3, 64))
      ->capture_default_str();
  group->add_option("--prune_max_relative_rotation_error_deg", consistency->max_relative_rotation_error_deg,
                    "e_r threshold")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_max_relative_translation_error_deg", consistency->max_relative_translation_error_deg,
                    "e_t threshold")
      ->check(PositiveValue())
      ->capture_default_str();
}

// Inter-subgraph RANSAC.
void AddAlignmentFlags(CLI::App* group, sfm_pruning::ViewGraphPruningOptions* options) {
  sfm_pruning::SubgraphAlignmentOptions* alignment = &options->alignment;
  group->add_option("--prune_num_ransac_iterations", alignment->num_ransac_iterations,
                    "RANSAC rounds per pair of subgraphs (paper ablation: 20 / 30 / 40)")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_max_enumerated_samples", alignment->max_enumerated_samples,
                    "A pair whose RANSAC pool has at most this many distinct samples tries each once instead of "
                    "the random rounds (complete, seed-independent); 0: always the paper's random rounds")
      ->capture_default_str();
  group->add_option("--prune_sample_fraction", alignment->sample_fraction,
                    "Fraction of the connecting edges drawn per RANSAC round")
      ->check(RangeValue(0.0, 1.0))
      ->capture_default_str();
  group->add_option("--prune_max_sample_size", options->max_sample_size,
                    "Cap on the RANSAC sample of a pair (0: no cap, the plain fraction)")
      ->capture_default_str();
  group->add_option("--prune_hypothesis_selection", alignment->hypothesis_selection,
                    "largest_consensus: the paper's vote; match_coverage: rule out RANSAC candidates whose "
                    "edges miss the landmarks their placed views should see (docs/pruning.md)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, sfm_pruning::SubgraphAlignmentOptions::HypothesisSelection>{
              {"largest_consensus", sfm_pruning::SubgraphAlignmentOptions::HypothesisSelection::kLargestConsensus},
              {"match_coverage", sfm_pruning::SubgraphAlignmentOptions::HypothesisSelection::kMatchCoverage}},
          CLI::ignore_case))
      ->default_str("match_coverage");
  group->add_option("--prune_coverage_break_even", alignment->coverage_break_even,
                    "match_coverage: a candidate whose edges match fewer than this fraction of the landmarks "
                    "they should see is ruled out")
      ->check(RangeValue(0.0, 1.0))
      ->capture_default_str();
  group->add_option("--prune_relative_coverage_break_even", alignment->relative_coverage_break_even,
                    "match_coverage, when every candidate is below the break-even: rule out those whose "
                    "coverage is below this fraction of the pair's best (0: the largest wins)")
      ->check(RangeValue(0.0, 1.0))
      ->capture_default_str();
  group->add_option("--prune_max_rotation_deviation_deg", alignment->max_rotation_deviation_deg,
                    "E_r: rotation deviation of an edge from the RANSAC hypothesis")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_max_translation_deviation_fraction", alignment->max_translation_deviation_fraction,
                    "E_t: translation deviation of an edge as a fraction of |mean t|")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_min_edges_for_ransac", alignment->min_edges_for_ransac,
                    "Subgraph pairs with fewer voting edges keep or lose them all (few-edges policy) instead of "
                    "being aligned")
      ->check(RangeValue(2, 1000000))
      ->capture_default_str();
  group->add_option("--prune_rotation_only_fallback", alignment->rotation_only_fallback,
                    "A pair without a supported hypothesis keeps only the largest set of edges that agree on "
                    "the rotation between the subgraphs (false: all its voting edges, the paper)")
      ->capture_default_str();
}

// The model's audit of the pruning (not in the paper; docs/pruning.md).
void AddAuditFlags(CLI::App* group, sfm_pruning::ModelEdgeAuditOptions* audit, bool final_solve) {
  group->add_option("--prune_audit_enabled", audit->enabled,
                    "GLOBAL_PRUNED: judge the edges between subgraphs against the model solved from the pruned "
                    "graph (re-admit removed edges whose matches it transfers, remove kept ones it does not), "
                    "then adjust the audited graph from that model")
      ->capture_default_str();
  group->add_option("--prune_audit_model_schedule", audit->model_schedule,
                    "Model audit: the solve it judges from. positioned: rotation averaging and positioning; "
                    "adjusted: + one bundle adjustment on a subset of the landmarks; full: the final solve's "
                    "schedule")
      ->transform(CLI::CheckedTransformer(AuditModelNames(), CLI::ignore_case))
      ->default_str("adjusted");
  if (final_solve) {  // `prune` stops after the audit: there is no final solve to start
    group->add_option("--prune_audit_refine_final", audit->refine_final,
                      "Model audit: the final solve starts from the audited model's poses (its tracks "
                      "re-triangulated, then adjusted) instead of solving the audited graph from scratch")
        ->capture_default_str();
  }
  group->add_option("--prune_audit_max_transfer_error_px", audit->max_transfer_error_px,
                    "Model audit: a match agrees when its landmark projects within this many pixels of the other "
                    "feature")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_audit_readmit_agreement", audit->readmit_agreement,
                    "Model audit: a removed edge is re-admitted when at least this share of its transferred "
                    "matches agree")
      ->check(RangeValue(0.0, 1.0))
      ->capture_default_str();
  group->add_option("--prune_audit_keep_agreement", audit->keep_agreement,
                    "Model audit: a kept edge is removed when less than this share of its transferred matches "
                    "agree")
      ->check(RangeValue(0.0, 1.0))
      ->capture_default_str();
}

// Loops of subgraph pairs (not in the paper; docs/pruning.md).
void AddSubgraphLoopFlags(CLI::App* group, sfm_pruning::SubgraphLoopOptions* loops) {
  group->add_option("--prune_subgraph_loops_enabled", loops->enabled,
                    "Cut the pairs of subgraphs whose frame transform breaks more subgraph triangles than it closes")
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_max_rotation_deg", loops->max_rotation_deg,
                    "Subgraph triangle: largest rotation of the composed frame transforms")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_max_translation_fraction", loops->max_translation_fraction,
                    "Subgraph triangle: largest displacement, as a fraction of the triangle's mean side")
      ->check(PositiveValue())
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_max_scale_ratio", loops->max_scale_ratio,
                    "Subgraph triangle: largest scale change of the composed frame transforms")
      ->check(RangeValue(1.0, 1e9))
      ->capture_default_str();
  using LoopMethod = sfm_pruning::SubgraphLoopOptions::Method;
  group->add_option("--prune_subgraph_loops_method", loops->method,
                    "triangle_vote: cut pairs breaking more subgraph triangles than they close, then longer "
                    "cycles; trusted_forest: the most trusted spanning forest of pairs is right, every other "
                    "pair must close its cycle with it (docs/pruning.md)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, LoopMethod>{{"triangle_vote", LoopMethod::kTriangleVote},
                                                                            {"trusted_forest", LoopMethod::kTrustedForest}},
                                          CLI::ignore_case))
      ->default_str("trusted_forest");
  group->add_option("--prune_subgraph_loops_verify_along_verified_paths", loops->verify_along_verified_paths,
                    "trusted_forest: a redundant pair without a transform that its forest path cannot verify "
                    "is judged by its edges against the transform chained along verified pairs, where such a "
                    "path exists (false: by its trust alone)")
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_min_unverified_trust", loops->min_unverified_trust,
                    "trusted_forest: a redundant subgraph pair that no cycle can verify is kept when its trust "
                    "reaches this (1: as distinctive as the edges inside the subgraphs)")
      ->check(NonNegativeValue())
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_min_unverified_coverage", loops->min_unverified_coverage,
                    "trusted_forest: such a pair must also reach this match coverage, relative to the edges "
                    "inside the subgraphs (when it can be measured)")
      ->check(NonNegativeValue())
      ->capture_default_str();
}

// The landmark check of the matches between aligned subgraphs (not in the paper; docs/pruning.md).
void AddLandmarkCheckFlags(CLI::App* group, sfm_pruning::LandmarkMatchCheckOptions* landmark_check) {
  group->add_option("--prune_landmark_check_max_angle_deg", landmark_check->max_angle_deg,
                    "Each kept edge between two aligned subgraphs drops the matches whose landmark, carried into "
                    "the other subgraph by the pair's transform, misses the other feature's ray by more than this "
                    "(degrees; 0: off, the paper). Removes repeated-texture matches inside true pairs")
      ->check(RangeValue(0.0, 90.0))
      ->capture_default_str();
}

// The missing-correspondence check of the kept edges between subgraphs (not in the paper;
// docs/pruning.md).
void AddMissingCorrespondenceFlags(CLI::App* group, sfm_pruning::MissingCorrespondenceOptions* check) {
  group->add_option("--prune_missing_correspondences_enabled", check->enabled,
                    "Solve the pruned graph, remove the kept edges between subgraphs whose views miss the "
                    "landmarks the model predicts in them far more than the scene's other such edges do, and "
                    "solve again (docs/pruning.md)")
      ->capture_default_str();
  group->add_option("--prune_missing_correspondences_max_rounds", check->max_rounds,
                    "Missing correspondences: rounds of solve, judge and remove at most (each costs a solve)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  group->add_option("--prune_missing_correspondences_max_viewing_angle_deg", check->max_viewing_angle_deg,
                    "Missing correspondences: a landmark is predicted in a view that sees it within this angle of "
                    "the observing view's direction")
      ->check(RangeValue(1e-6, 90.0))
      ->capture_default_str();
  group->add_option("--prune_missing_correspondences_max_distance_ratio", check->max_distance_ratio,
                    "Missing correspondences: ... and from within this factor of the observing view's distance")
      ->check(RangeValue(1.0, 1e6))
      ->capture_default_str();
  group->add_option("--prune_missing_correspondences_min_predicted_landmarks", check->min_predicted_landmarks,
                    "Missing correspondences: edges with fewer predicted landmarks in either direction are not judged")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  group->add_option("--prune_missing_correspondences_max_robust_deviations", check->max_robust_deviations,
                    "Missing correspondences: an edge is removed when its observed share (its better direction) lies more than this many "
                    "robust standard deviations (1.4826 x MAD) below the median of the judged edges")
      ->check(RangeValue(1e-6, 1e3))
      ->capture_default_str();
}

// What ranks the subgraph pairs of the loop check, and the longer cycles it judges.
void AddPairTrustFlags(CLI::App* group, sfm_pruning::ViewGraphPruningOptions* options) {
  group->add_option("--prune_subgraph_loops_min_edges_for_trust", options->loops.min_edges_for_trust,
                    "trusted_forest: subgraph pairs of fewer connecting edges are ranked after all the others")
      ->capture_default_str();
  using LinkTrust = sfm_pruning::PairTrustMeasure;
  group->add_option("--prune_link_trust", options->link_trust,
                    "What ranks subgraph pairs in the loop check: match_coverage, or distinctive (the mean "
                    "distinctiveness of the pair's inliers; repeated structure is matched by many views)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, LinkTrust>{{"match_coverage", LinkTrust::kMatchCoverage},
                                           {"distinctive", LinkTrust::kDistinctiveShare}},
          CLI::ignore_case))
      ->default_str("distinctive");
  group->add_option("--prune_trust_prior_edges", options->trust_prior_edges,
                    "distinctive trust: a pair whose RANSAC kept k edges is ranked by (k * their share + m * "
                    "the share of all its connecting edges) / (k + m), so one kept edge cannot outrank a large "
                    "consensus (0: off; docs/pruning.md)")
      ->check(NonNegativeValue())
      ->capture_default_str();
  group->add_option("--prune_subgraph_loops_max_cycle_length", options->loops.max_cycle_length,
                    "Longest cycle of subgraphs the second loop pass judges (below 4: off); on a broken "
                    "cycle the least trusted pair is cut")
      ->capture_default_str();
}

}  // namespace

std::string AuditModelName(sfm_pruning::AuditModelSchedule schedule) {
  for (const auto& [name, value] : AuditModelNames()) {
    if (value == schedule) return name;
  }
  return "";
}

void AddPruningOptions(CLI::App* cmd, sfm_pruning::ViewGraphPruningOptions* options, bool final_solve) {
  CLI::App* group = cmd->add_option_group(
      "Pruning", "View-graph pruning (GLOBAL_PRUNED, prune): the paper's method with PruneSfM's additions "
                 "(docs/pruning.md)");
  AddPresetFlag(group, options);
  AddCaptureOrderFlags(group, &options->capture_order);
  AddPartitionFlags(group, &options->partition);
  AddConsistencyTestFlags(group, &options->partition.consistency);
  AddAlignmentFlags(group, options);
  AddAuditFlags(group, &options->audit, final_solve);
  // The landmark check's flag keeps its place in --help_all, between the loop check's and the pair
  // ranking's.
  AddSubgraphLoopFlags(group, &options->loops);
  AddLandmarkCheckFlags(group, &options->landmark_check);
  AddPairTrustFlags(group, options);
  AddMissingCorrespondenceFlags(group, &options->missing_correspondences);
  // The preset is the one choice most runs make; every other pruning flag studies or adjusts the
  // method, and `--help` lists them only under --help_all.
  MarkExpertExcept(group, "--prune_preset");
}

}  // namespace prunesfm
