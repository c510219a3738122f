#include "software/commands/pruning_report_json.hpp"

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "sfm_pruning/util/atomic_file.hpp"

namespace prunesfm {
namespace {

nlohmann::json ViewPairJson(const sfm_pruning::ViewPair& pair) { return nlohmann::json::array({pair.first, pair.second}); }

// Each violation of a node's consistency tests: which test, on which edge or loop, by how much.
nlohmann::json ViolationsJson(const std::vector<sfm_pruning::ConsistencyViolation>& violations) {
  using sfm_pruning::ConsistencyTest;
  nlohmann::json list = nlohmann::json::array();
  for (const sfm_pruning::ConsistencyViolation& v : violations) {
    nlohmann::json entry = {{"test", sfm_pruning::ConsistencyTestName(v.test)}};
    if (v.test == ConsistencyTest::kBaselineRatio) {
      // A factor, not an angle: (i, j, k) with i the view both edges share.
      entry["views"] = v.loop;
      entry["factor"] = v.value;
      entry["threshold_factor"] = v.threshold;
    } else {
      entry["value_deg"] = v.value;
      entry["threshold_deg"] = v.threshold;
      if (v.test == ConsistencyTest::kLoop) {
        entry["loop"] = v.loop;
      } else {
        entry["edge"] = ViewPairJson(v.edge);
      }
    }
    list.push_back(std::move(entry));
  }
  return list;
}

nlohmann::json ErrorSummaryJson(const sfm_pruning::ErrorSummary& s) {
  return nlohmann::json{{"count", s.count}, {"max_deg", s.max_deg}, {"median_deg", s.median_deg}};
}

// The consistency tests' outcome on a tested node, added to its entry.
void AddConsistencyJson(const sfm_pruning::ConsistencyReport& consistency, nlohmann::json* entry) {
  using sfm_pruning::ConsistencyTest;
  // Every test's count, zeros included (baseline_ratio is 0 when the test is off).
  std::map<std::string, size_t> counts;
  for (const ConsistencyTest test : {ConsistencyTest::kLoop, ConsistencyTest::kRelativeRotation,
                                     ConsistencyTest::kRelativeTranslation, ConsistencyTest::kBaselineRatio}) {
    counts[sfm_pruning::ConsistencyTestName(test)] = 0;
  }
  for (const sfm_pruning::ConsistencyViolation& v : consistency.violations) {
    ++counts[sfm_pruning::ConsistencyTestName(v.test)];
  }
  (*entry)["consistent"] = consistency.consistent;
  (*entry)["violations"] = std::move(counts);
  (*entry)["violation_list"] = ViolationsJson(consistency.violations);
  (*entry)["loop_error"] = ErrorSummaryJson(consistency.loop_error);
  (*entry)["relative_rotation_error"] = ErrorSummaryJson(consistency.relative_rotation_error);
  (*entry)["relative_translation_error"] = ErrorSummaryJson(consistency.relative_translation_error);
}

// "tree": every node of the recursive partition.
nlohmann::json TreeJson(const sfm_pruning::RecursivePartitionResult& partition) {
  nlohmann::json nodes = nlohmann::json::array();
  for (size_t i = 0; i < partition.nodes.size(); ++i) {
    const sfm_pruning::SubgraphNode& node = partition.nodes[i];
    nlohmann::json entry = {{"id", i},
                            {"parent", node.parent},
                            {"depth", node.depth},
                            {"size", node.view_ids.size()},
                            {"edges", node.num_edges},
                            {"status", sfm_pruning::SubgraphStatusName(node.status)},
                            {"children", node.children},
                            {"accepted_index", node.accepted_index},
                            {"seconds", node.seconds}};
    if (node.bisected) entry["split_by"] = "spectral_bisection";
    if (node.solved) {
      entry["engine_success"] = node.engine_success;
      if (!node.engine_message.empty()) entry["engine_message"] = node.engine_message;
      entry["registered"] = node.num_registered;
      entry["landmarks"] = node.num_landmarks;
    }
    if (node.consistency_tested) AddConsistencyJson(node.consistency, &entry);
    entry["view_ids"] = node.view_ids;
    nodes.push_back(std::move(entry));
  }
  return nodes;
}

// A JSON array of `element(item)` for each item, in order.
template <typename T, typename ElementJson>
nlohmann::json ArrayJson(const std::vector<T>& items, ElementJson element) {
  nlohmann::json list = nlohmann::json::array();
  for (const T& item : items) list.push_back(element(item));
  return list;
}

// One RANSAC candidate of a subgraph pair.
nlohmann::json HypothesisJson(const sfm_pruning::AlignmentHypothesis& h) {
  return {{"consensus_edges", h.consensus_size},
          {"beta", h.beta},
          {"expected_landmarks", h.expected_landmarks},
          {"matched_landmarks", h.matched_landmarks},
          {"coverage_score", h.coverage_score},
          {"ruled_out", h.ruled_out},
          {"samples", h.num_samples},
          {"enumerated", h.enumerated}};
}

// "subgraph_pairs": a connected pair's alignment, loop check and trust.
nlohmann::json SubgraphPairJson(const sfm_pruning::SubgraphPairReport& pair) {
  using namespace sfm_pruning;
  nlohmann::json entry = {{"hypotheses", ArrayJson(pair.hypotheses, HypothesisJson)},
                          {"selected_hypothesis", pair.selected_hypothesis},
                          {"k1", pair.k1},
                          {"k2", pair.k2},
                          {"status", SubgraphAlignmentStatusName(pair.status)},
                          {"edges", pair.num_edges},
                          {"voting_edges", pair.num_voting_edges},
                          {"removed_edges", pair.num_removed_edges},
                          {"beta", pair.beta},
                          {"consistent_triangles", pair.consistent_triangles},
                          {"inconsistent_triangles", pair.inconsistent_triangles},
                          {"rejected_by_loops", pair.rejected_by_loops},
                          {"rejected_by_cycle", pair.rejected_by_cycle},
                          {"trust", pair.trust},
                          {"coverage", pair.coverage},
                          {"capture_linked", pair.capture_linked}};
  if (pair.judged_by_forest) {
    entry["forest_decision"] = LinkDecisionName(pair.forest_decision);
  }
  if (pair.has_frame_transform) {
    entry["frame_rotation_deg"] =
        RadToDeg(RotationAngleBetween(pair.k2_to_k1.rotation, Eigen::Matrix3d::Identity()));
  }
  return entry;
}

// "subgraph_triangles": a loop of aligned pairs.
nlohmann::json SubgraphTriangleJson(const sfm_pruning::SubgraphTriangle& triangle) {
  return {{"subgraphs", {triangle.a, triangle.b, triangle.c}},
          {"rotation_deg", triangle.rotation_deg},
          {"scale_ratio", triangle.scale_ratio},
          {"translation_fraction", triangle.translation_fraction},
          {"consistent", triangle.consistent}};
}

// "subgraph_cycles": a longer cycle judged.
nlohmann::json SubgraphCycleJson(const sfm_pruning::SubgraphCycle& cycle) {
  return {{"subgraphs", cycle.subgraphs},
          {"rotation_deg", cycle.rotation_deg},
          {"scale_ratio", cycle.scale_ratio},
          {"translation_fraction", cycle.translation_fraction},
          {"loop_factor", cycle.loop_factor},
          {"consistent", cycle.consistent}};
}

// "removed_edges": a removed edge with its reason and measured error.
nlohmann::json RemovedEdgeJson(const sfm_pruning::RemovedEdge& edge) {
  using namespace sfm_pruning;
  return {{"pair", ViewPairJson(edge.pair)},
          {"k1", edge.k1},
          {"k2", edge.k2},
          {"verdict", InterSubgraphVerdictName(edge.verdict)},
          {"reason", EdgeInvalidReasonName(edge.invalidation.reason)},
          {"value", edge.invalidation.value},
          {"threshold", edge.invalidation.threshold},
          {"measure", EdgeMeasureName(edge.invalidation.Measure())}};
}

// "landmark_check": the counts of the landmark check of the matches between aligned subgraphs.
nlohmann::json LandmarkCheckJson(const sfm_pruning::LandmarkMatchCheckReport& check) {
  return {{"edges", check.num_edges},
          {"matches", check.num_matches},
          {"tested", check.num_tested},
          {"dropped", check.num_dropped},
          {"edges_removed", check.emptied.size()}};
}

// "model_audit": every judged edge and what changed.
nlohmann::json ModelAuditJson(const sfm_pruning::ViewGraphPruningReport& pruning) {
  const auto agreement_json = [](const sfm_pruning::EdgeAgreement& agreement) {
    return nlohmann::json{{"pair", ViewPairJson(agreement.pair)},
                          {"transferred", agreement.transferred},
                          {"agreeing", agreement.agreeing}};
  };
  return {{"edges", ArrayJson(pruning.audit, agreement_json)},
          {"readmitted", pruning.audit_readmitted},
          {"removed", pruning.audit_removed}};
}

// "missing_correspondences": each round of the check, with the edges it removed.
nlohmann::json MissingCorrespondenceRoundJson(const sfm_pruning::MissingCorrespondenceRound& round) {
  return {{"edges_measured", round.edges.size()},
          {"edges_judged", round.num_judged},
          {"median_observed_share", round.median_share},
          {"bound", round.bound},
          {"removed", ArrayJson(round.removed, ViewPairJson)}};
}

// "capture_order": the evidence about the id order and whether the pruning used it.
nlohmann::json CaptureOrderJson(const sfm_pruning::ViewGraphPruningReport& pruning) {
  const sfm_pruning::CaptureOrderEvidence& evidence = pruning.capture_order;
  return {{"used", pruning.capture_order_used},
          {"informative", evidence.informative},
          {"by_edges", evidence.by_edges},
          {"by_rotations", evidence.by_rotations},
          {"views", evidence.num_views},
          {"consecutive_edge_share", evidence.consecutive_edge_share},
          {"edge_density", evidence.edge_density},
          {"consecutive_rotation_ratio", evidence.consecutive_rotation_ratio}};
}

// "capture_path": the capture path's rotation check (the removed edges are in "removed_edges").
nlohmann::json CapturePathJson(const sfm_pruning::CapturePathRotationCheck& check) {
  return {{"applied", check.applied},
          {"path_edges", check.num_path_edges},
          {"path_views", check.num_path_views},
          {"path_pieces", check.num_path_pieces},
          {"path_residual_deg", check.path_residual_deg},
          {"removed", check.removed.size()}};
}

// "capture_path_directions": the direction check against the capture path's model (the removed
// edges are in "removed_edges").
nlohmann::json CapturePathDirectionsJson(const sfm_pruning::CapturePathDirectionCheck& check) {
  return {{"solved", check.solved},
          {"applied", check.applied},
          {"path_edges", check.num_path_edges},
          {"path_views", check.num_path_views},
          {"path_pieces", check.num_path_pieces},
          {"path_residual_deg", check.path_residual_deg},
          {"removed", check.removed.size()}};
}

// "phases": the time of each stage.
nlohmann::json StageTimingJson(const sfm_pruning::StageTiming& timing) {
  return {{"stage", timing.stage}, {"seconds", timing.seconds}};
}

}  // namespace

nlohmann::json PruningReportJson(const sfm_pruning::ViewGraphPruningReport& pruning) {
  return {{"edges_in", pruning.num_input_edges},
          {"edges_out", pruning.num_output_edges},
          {"num_subgraphs", pruning.partition.accepted.size()},
          {"engine_runs", pruning.partition.num_engine_runs},
          {"phases", ArrayJson(pruning.timings, StageTimingJson)},
          {"total_seconds", pruning.total_seconds},
          {"capture_order", CaptureOrderJson(pruning)},
          {"capture_path", CapturePathJson(pruning.capture_path)},
          {"capture_path_directions", CapturePathDirectionsJson(pruning.capture_path_directions)},
          {"reference_distinctive_share", pruning.reference_distinctive_share},
          {"reference_coverage", pruning.reference_coverage},
          {"tree", TreeJson(pruning.partition)},
          {"subgraph_pairs", ArrayJson(pruning.pairs, SubgraphPairJson)},
          {"subgraph_triangles", ArrayJson(pruning.triangles, SubgraphTriangleJson)},
          {"subgraph_cycles", ArrayJson(pruning.cycles, SubgraphCycleJson)},
          {"removed_edges", ArrayJson(pruning.removed_edges, RemovedEdgeJson)},
          {"landmark_check", LandmarkCheckJson(pruning.landmark_check)},
          {"model_audit", ModelAuditJson(pruning)},
          {"missing_correspondences", ArrayJson(pruning.missing_correspondence_rounds, MissingCorrespondenceRoundJson)}};
}

void WriteJsonAtomically(const nlohmann::json& report, const std::filesystem::path& path) {
  sfm_pruning::WriteFileAtomically(path, false, [&](std::ostream& out) { out << report.dump(2) << "\n"; });
}

namespace {

// "; missing correspondences: N edges removed in R rounds", or nothing when the check did not run.
std::string MissingCorrespondenceSummary(const std::vector<sfm_pruning::MissingCorrespondenceRound>& rounds) {
  if (rounds.empty()) return "";
  size_t removed = 0;
  for (const auto& round : rounds) removed += round.removed.size();
  return "; missing correspondences: " + std::to_string(removed) + " edges removed in " +
         std::to_string(rounds.size()) + (rounds.size() == 1 ? " round" : " rounds");
}

}  // namespace

std::string PruningSummary(const sfm_pruning::ViewGraphPruningReport& pruning) {
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.2f", pruning.total_seconds);
  return std::string(pruning.capture_order_used ? "capture order used; " : "") +
         std::to_string(pruning.partition.accepted.size()) + " subgraphs (" +
         std::to_string(pruning.partition.nodes.size()) + " tree nodes, " +
         std::to_string(pruning.partition.num_engine_runs) + " engine runs), removed " +
         std::to_string(pruning.removed_edges.size()) + " of " + std::to_string(pruning.num_input_edges) +
         " edges in " + std::to_string(pruning.pairs.size()) + " subgraph pairs, " + seconds + " s" +
         (pruning.landmark_check.num_edges == 0
              ? std::string()
              : "; landmark check: " + std::to_string(pruning.landmark_check.num_dropped) + " of " +
                    std::to_string(pruning.landmark_check.num_matches) + " matches dropped") +
         (pruning.audit.empty() ? std::string()
                                : "; model audit: " + std::to_string(pruning.audit_readmitted) + " re-admitted, " +
                                      std::to_string(pruning.audit_removed) + " removed") +
         MissingCorrespondenceSummary(pruning.missing_correspondence_rounds);
}

}  // namespace prunesfm
