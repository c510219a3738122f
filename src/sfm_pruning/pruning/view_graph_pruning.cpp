#include "sfm_pruning/pruning/view_graph_pruning.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/pruning/subgraph_cycle_consistency.hpp"
#include "sfm_pruning/util/parallel_for.hpp"
#include "sfm_pruning/util/statistics.hpp"
#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Pairs (k1 < k2) of accepted subgraphs joined by at least one valid edge, in increasing order.
std::vector<std::pair<int, int>> ConnectedSubgraphPairs(const ViewGraph& graph,
                                                        const std::vector<AcceptedSubgraph>& accepted) {
  std::set<std::pair<int, int>> connected;
  for (const EdgeOfSubgraphs& edge : EdgesOfAcceptedSubgraphs(graph, accepted)) {
    if (edge.k_first != edge.k_second) {
      connected.emplace(std::min(edge.k_first, edge.k_second), std::max(edge.k_first, edge.k_second));
    }
  }
  return {connected.begin(), connected.end()};
}

// The alignment options of a pair with `num_edges` connecting edges: the sample fraction lowered
// so that a sample holds at most max_sample_size edges (ViewGraphPruningOptions).
SubgraphAlignmentOptions PairAlignmentOptions(const ViewGraphPruningOptions& options, size_t num_edges) {
  SubgraphAlignmentOptions alignment = options.alignment;
  if (options.max_sample_size > 0 && alignment.sample_fraction * static_cast<double>(num_edges) >=
                                         static_cast<double>(options.max_sample_size + 1)) {
    alignment.sample_fraction = (static_cast<double>(options.max_sample_size) + 0.5) / static_cast<double>(num_edges);
  }
  return alignment;
}

// Mean camera centre and median distance of the centres to it, in the subgraph's frame.
SubgraphFrame FrameOfSubgraph(const SubgraphSolution& solution) {
  SubgraphFrame frame;
  if (solution.poses.empty()) return frame;
  frame.center = SubgraphMeanCentre(solution);  // not SubgraphMeanPose: its rotation mean is unused here
  std::vector<double> distances;
  for (const auto& [view_id, pose] : solution.poses) distances.push_back((pose.center - frame.center).norm());
  frame.radius = Median(std::move(distances));
  return frame;
}

// A pair aligned with its second subgraph as the reference, turned round so that k2_to_k1 and beta
// map the second into the first like every other pair's (the edge decisions name both views and
// need nothing; mean_rotation / mean_translation stay the reference's chain).
void ExpressFromTheFirstSubgraph(SubgraphAlignmentResult* alignment) {
  if (alignment->has_frame_transform) alignment->k2_to_k1 = alignment->k2_to_k1.Inverse();
  if (alignment->beta > 0.0) alignment->beta = 1.0 / alignment->beta;
}

// What the loop check decided for one pair of subgraphs.
struct PairVerdict {
  bool cut = false;                // every connecting edge is removed
  bool keep_all = false;           // a forest pair without a transform keeps every connecting edge
  InterSubgraphVerdict reason = InterSubgraphVerdict::kLoopInconsistent;  // when cut
  EdgeInvalidation invalidation;   // when cut
  // Voting edges removed by the verification along verified paths: why each disagrees (the
  // deviation that failed against the chained transform, and its widened bound); reason kNone: kept.
  std::vector<EdgeInvalidation> disagreements;
};

// Invalidates the edge `pair` (first < second) with `why` and records it in `removed`; false, and
// nothing recorded, when it was already invalid. k1 / k2: its subgraphs, -1 when not recorded.
bool RemoveEdge(const ViewPair& pair, int k1, int k2, InterSubgraphVerdict verdict, const EdgeInvalidation& why,
                ViewGraph* graph, std::vector<RemovedEdge>* removed) {
  if (!graph->InvalidateEdge(pair.first, pair.second, why)) return false;
  removed->push_back({pair, k1, k2, verdict, why});
  return true;
}

// Whether the pair's transform can take part in a loop: a transform no connecting edge agrees with
// is no evidence (real street: two such pairs, fitted on samples of doppelgangers, closed a
// triangle with each other).
bool HasUsableTransform(const SubgraphAlignmentResult& alignment) {
  return alignment.has_frame_transform && alignment.consensus_size > 0;
}

// A pair that nothing decided between its edges (no usable transform, no rotation-only consensus)
// keeps all of them if it is kept at all: they are its evidence.
bool KeepsAllIfKept(const SubgraphAlignmentResult& alignment) {
  return !HasUsableTransform(alignment) && alignment.status != SubgraphAlignmentStatus::kRotationOnly;
}

// Whether the pair's kept edges (all of them when all_edges) include one between capture neighbours.
bool JoinsCaptureNeighbours(const SubgraphAlignmentResult& alignment, bool all_edges, const CaptureOrder& order) {
  return std::any_of(alignment.edges.begin(), alignment.edges.end(), [&](const InterSubgraphEdgeDecision& decision) {
    return (decision.kept || all_edges) && order.AreNeighbours(decision.placement.view_i, decision.placement.view_j);
  });
}

// The measure that broke a cycle and its bound (SubgraphLoopOptions, widened by the loop factor):
// the rotation in degrees if it failed, else the scale ratio, else the translation fraction.
EdgeInvalidation CycleInvalidation(const SubgraphCycle& cycle, const SubgraphLoopOptions& options) {
  const CycleBounds bounds = WidenedCycleBounds(cycle.loop_factor, options);
  const EdgeInvalidReason reason = EdgeInvalidReason::kSubgraphLoopInconsistent;
  if (cycle.rotation_deg > bounds.rotation_deg) {
    return {reason, cycle.rotation_deg, bounds.rotation_deg, EdgeMeasure::kDegrees};
  }
  if (cycle.scale_ratio > bounds.scale_ratio) {
    return {reason, cycle.scale_ratio, bounds.scale_ratio, EdgeMeasure::kScaleRatio};
  }
  return {reason, cycle.translation_fraction, bounds.translation_fraction, EdgeMeasure::kTranslationFraction};
}

// Method::kTriangleVote: the triangle vote, then the longer cycles, over the pairs with a usable
// transform. Fills the report's triangles, cycles and triangle counts.
std::vector<PairVerdict> VoteOnTriangles(const std::vector<std::pair<int, int>>& pairs,
                                         const std::vector<SubgraphAlignmentResult>& alignments,
                                         const std::vector<double>& trust, const std::vector<SubgraphFrame>& frames,
                                         const SubgraphLoopOptions& options, ViewGraphPruningReport* out) {
  std::vector<SubgraphLink> links;
  std::vector<size_t> pair_of_link;
  for (size_t p = 0; p < pairs.size(); ++p) {
    if (!HasUsableTransform(alignments[p])) continue;
    links.push_back({pairs[p].first, pairs[p].second, alignments[p].k2_to_k1, alignments[p].consensus_size, trust[p]});
    pair_of_link.push_back(p);
  }
  const SubgraphLoopResult loops = FindLoopInconsistentLinks(links, frames, options);
  out->triangles = loops.triangles;
  out->cycles = loops.cycles;
  std::vector<PairVerdict> verdicts(pairs.size());
  for (size_t l = 0; l < links.size(); ++l) {
    out->pairs[pair_of_link[l]].consistent_triangles = loops.consistent_triangles[l];
    out->pairs[pair_of_link[l]].inconsistent_triangles = loops.inconsistent_triangles[l];
  }
  for (const RejectedLink& rejected : loops.rejected) {
    const size_t p = pair_of_link[rejected.link];
    verdicts[p].cut = true;
    verdicts[p].invalidation = {EdgeInvalidReason::kSubgraphLoopInconsistent,
                                static_cast<double>(rejected.inconsistent_triangles),
                                static_cast<double>(rejected.consistent_triangles), EdgeMeasure::kBrokenLoops};
    out->pairs[p].rejected_by_loops = true;
    out->pairs[p].rejected_by_cycle = rejected.cycle;
  }
  return verdicts;
}

// The connecting edges of a pair (s1, s2) judged against the transform X_s1 = k2_to_k1(X_s2) chained
// along verified pairs (ForestTransformCheck), from the subgraph that placed the other's views, with
// the edge thresholds widened by the chain's loop factor: per edge, why it disagrees (the deviation
// that failed and its widened bound); reason kNone for an edge that agrees or did not vote.
std::vector<EdgeInvalidation> DisagreementsWithChain(const SubgraphAlignmentResult& alignment,
                                                     const SubgraphSolution& s1, const SubgraphSolution& s2,
                                                     bool placed_by_second, const ChainedTransform& chained,
                                                     const SubgraphAlignmentOptions& options) {
  SubgraphAlignmentOptions widened = options;
  widened.max_rotation_deviation_deg *= static_cast<double>(chained.loop_factor);
  widened.max_translation_deviation_fraction *= static_cast<double>(chained.loop_factor);
  const std::vector<EdgeAgainstTransform> judged =
      placed_by_second ? JudgeEdgesAgainstTransform(alignment, s2, s1, chained.k2_to_k1.Inverse(), widened)
                       : JudgeEdgesAgainstTransform(alignment, s1, s2, chained.k2_to_k1, widened);
  std::vector<EdgeInvalidation> why(judged.size());
  const EdgeInvalidReason reason = EdgeInvalidReason::kSubgraphLoopInconsistent;
  for (size_t e = 0; e < judged.size(); ++e) {
    const EdgeAgainstTransform& edge = judged[e];
    if (!edge.voted || edge.agrees) continue;
    why[e] = edge.rotation_deviation_deg > widened.max_rotation_deviation_deg
                 ? EdgeInvalidation{reason, edge.rotation_deviation_deg, widened.max_rotation_deviation_deg,
                                    EdgeMeasure::kDegrees}
                 : EdgeInvalidation{reason, edge.translation_deviation_fraction,
                                    widened.max_translation_deviation_fraction, EdgeMeasure::kTranslationFraction};
  }
  return why;
}

// Method::kTrustedForest over every connected pair (trusted_link_forest.hpp).
std::vector<PairVerdict> JudgeAgainstTrustedForest(const std::vector<std::pair<int, int>>& pairs,
                                                   const std::vector<SubgraphAlignmentResult>& alignments,
                                                   const std::vector<double>& trust, const std::vector<double>& coverage,
                                                   const std::vector<char>& capture_linked,
                                                   const std::vector<SubgraphFrame>& frames,
                                                   const SubgraphLoopOptions& options,
                                                   const ForestTransformCheck& check_against_forest,
                                                   const std::vector<std::vector<EdgeInvalidation>>& disagreements,
                                                   ViewGraphPruningReport* out) {
  std::vector<SubgraphPairLink> links(pairs.size());
  for (size_t p = 0; p < pairs.size(); ++p) {
    const SubgraphAlignmentResult& alignment = alignments[p];
    const bool has_transform = HasUsableTransform(alignment);
    links[p] = {pairs[p].first, pairs[p].second, has_transform, alignment.k2_to_k1, trust[p],
                has_transform ? alignment.consensus_size : alignment.edges.size(), coverage[p],
                alignment.edges.size(), capture_linked[p] != 0};
  }
  const TrustedForestResult forest = SelectLinksByTrustedForest(links, frames, options, check_against_forest);
  out->cycles = forest.cycles;
  std::vector<PairVerdict> verdicts(pairs.size());
  for (size_t p = 0; p < pairs.size(); ++p) {
    SubgraphPairReport& report = out->pairs[p];
    report.judged_by_forest = true;
    report.forest_decision = forest.decisions[p];
    switch (forest.decisions[p]) {
      case LinkDecision::kForest:
        // Nothing says which edges of such a pair are wrong, and the pair is needed.
        verdicts[p].keep_all = KeepsAllIfKept(alignments[p]);
        break;
      case LinkDecision::kClosesCycle:
      case LinkDecision::kKeptUnverified:
        break;
      case LinkDecision::kBreaksCycle: {
        verdicts[p].cut = true;
        verdicts[p].invalidation = CycleInvalidation(forest.cycles[static_cast<size_t>(forest.cycle_of[p])], options);
        report.rejected_by_loops = true;
        report.rejected_by_cycle = forest.cycle_of[p];
        break;
      }
      case LinkDecision::kAgreesWithForest:
        verdicts[p].disagreements = disagreements[p];
        break;
      case LinkDecision::kContradictsForest: {
        // Every edge of the pair is recorded with the disagreement of the edge that came closest.
        verdicts[p].cut = true;
        double closest = std::numeric_limits<double>::infinity();
        for (const EdgeInvalidation& why : disagreements[p]) {
          if (why.reason == EdgeInvalidReason::kNone || why.value / why.threshold >= closest) continue;
          closest = why.value / why.threshold;
          verdicts[p].invalidation = why;
        }
        break;
      }
      case LinkDecision::kRedundantUnverified:
        verdicts[p].cut = true;
        verdicts[p].reason = InterSubgraphVerdict::kUnverified;
        verdicts[p].invalidation = {EdgeInvalidReason::kUnverifiedSubgraphPair, trust[p], 0.0};
        break;
    }
  }
  return verdicts;
}

// The landmark check on the edges between subgraphs, through the transforms of the pairs that have
// one (their kept edges agree with it); edges left with too few matches are removed.
void CheckMatchesOfAlignedPairs(const LandmarkMatchCheckOptions& options, const SfmData& views_and_intrinsics,
                                const FeaturesPerView& features, ViewGraph* graph, ViewGraphPruningReport* out) {
  std::vector<AlignedSubgraphs> aligned;
  for (const SubgraphPairReport& pair : out->pairs) {
    if (pair.has_frame_transform) aligned.push_back({pair.k1, pair.k2, pair.k2_to_k1});
  }
  out->landmark_check =
      CheckMatchesAgainstLandmarks(options, out->partition.accepted, aligned, views_and_intrinsics, features, graph);
  for (const EdgeOfSubgraphs& edge : out->landmark_check.emptied) {
    const double left = static_cast<double>(graph->FindEdge(edge.pair.first, edge.pair.second)->matches.size());
    const EdgeInvalidation why{EdgeInvalidReason::kLandmarkDisagreement, left, static_cast<double>(options.min_matches)};
    RemoveEdge(edge.pair, edge.k_first, edge.k_second, InterSubgraphVerdict::kLandmarkDisagreement, why, graph,
               &out->removed_edges);
  }
}

}  // namespace

void ApplyPaperMethod(ViewGraphPruningOptions* options) {
  options->capture_order.use = CaptureOrderOptions::Use::kUnordered;
  options->partition.edge_weight = RecursivePartitionOptions::EdgeWeight::kInliers;
  options->partition.bisect_unsplittable = false;
  options->partition.consistency.max_baseline_ratio_factor = 0.0;
  options->max_sample_size = 0;
  options->alignment.max_enumerated_samples = 0;
  options->alignment.hypothesis_selection = SubgraphAlignmentOptions::HypothesisSelection::kLargestConsensus;
  options->alignment.rotation_only_fallback = false;
  options->loops.enabled = false;
  options->trust_prior_edges = 0.0;
  options->landmark_check.max_angle_deg = 0.0;
  options->audit.enabled = false;
  options->missing_correspondences.enabled = false;
}

void PruneViewGraph(const ViewGraphPruningOptions& options, ViewGraph* graph, const SfmData& views_and_intrinsics,
                    const FeaturesPerView& features, ViewGraphPruningReport* report,
                    const ProgressCallback& progress) {
  options.Check();
  const auto total_start = std::chrono::steady_clock::now();
  ViewGraphPruningReport local;
  ViewGraphPruningReport& out = report != nullptr ? *report : local;
  out = ViewGraphPruningReport();
  out.num_input_edges = graph->NumValidEdges();

  // 0. The capture order, and the edges whose rotation the capture path's contradicts, then those
  // whose translation direction the model solved from the path contradicts.
  auto start = std::chrono::steady_clock::now();
  NodeGroup component = LargestComponent(*graph);
  ViewGraph component_graph = graph->InducedSubgraph(std::set<IndexT>(component.begin(), component.end()));
  const CaptureOrder capture_order(options.capture_order, component_graph);
  out.capture_order = capture_order.Evidence();
  out.capture_order_used = capture_order.Used();
  // Removes the edges a capture-path check contradicts; the largest component may shrink.
  const auto remove_deviations = [&](const std::vector<CapturePathDeviation>& deviations,
                                     InterSubgraphVerdict verdict, EdgeInvalidReason reason) {
    for (const CapturePathDeviation& deviation : deviations) {
      RemoveEdge(deviation.pair, -1, -1, verdict, {reason, deviation.deviation_deg, deviation.bound_deg}, graph,
                 &out.removed_edges);
    }
    if (deviations.empty()) return;
    component = LargestComponent(*graph);
    component_graph = graph->InducedSubgraph(std::set<IndexT>(component.begin(), component.end()));
  };
  out.capture_path = CheckAgainstCapturePath(options.capture_order, capture_order, component_graph);
  remove_deviations(out.capture_path.removed, InterSubgraphVerdict::kCapturePathRotation,
                    EdgeInvalidReason::kRotationResidual);
  out.capture_path_directions = CheckDirectionsAgainstCapturePath(options.capture_order, capture_order, component_graph,
                                                                  options.partition.engine, views_and_intrinsics, features);
  remove_deviations(out.capture_path_directions.removed, InterSubgraphVerdict::kCapturePathDirection,
                    EdgeInvalidReason::kTranslationDirection);
  if (out.capture_path.applied || out.capture_path_directions.solved) {
    out.timings.push_back({"capture path", SecondsSince(start)});
    start = std::chrono::steady_clock::now();
  }

  // 1. Recursive partition of the largest component.
  out.partition =
      PartitionViewGraph(options.partition, component_graph, views_and_intrinsics, features, capture_order, progress);
  out.timings.push_back({"subgraph partition", SecondsSince(start)});

  // 2. Alignment of every connected pair of subgraphs (decisions only, the graph is unchanged).
  start = std::chrono::steady_clock::now();
  const std::vector<AcceptedSubgraph>& accepted = out.partition.accepted;
  const std::vector<std::pair<int, int>> pairs = ConnectedSubgraphPairs(*graph, accepted);
  const PairTrust pair_trust(options.link_trust, component_graph, accepted, views_and_intrinsics,
                             options.alignment.placement, options.trust_prior_edges);
  std::vector<SubgraphAlignmentResult> alignments(pairs.size());
  std::vector<char> placed_by_second(pairs.size(), 0);
  ParallelFor(
      pairs.size(), options.num_threads,
      [&](size_t p) {
        const SubgraphSolution& s1 = accepted[static_cast<size_t>(pairs[p].first)].solution;
        const SubgraphSolution& s2 = accepted[static_cast<size_t>(pairs[p].second)].solution;
        const size_t num_edges = ConnectingEdges(*graph, s1.view_ids, s2.view_ids).size();
        // The subgraph with more points places the other's views: a tiny subgraph of two views may
        // have none, and then no edge of the pair could vote.
        const bool second_places = s2.landmarks.size() > s1.landmarks.size();
        placed_by_second[p] = second_places ? 1 : 0;
        alignments[p] = AlignSubgraphPair(*graph, second_places ? s2 : s1, second_places ? s1 : s2,
                                          views_and_intrinsics, features, PairAlignmentOptions(options, num_edges));
        if (second_places) ExpressFromTheFirstSubgraph(&alignments[p]);
      },
      progress, "inter-subgraph pruning");

  // 3. The loop check: a pair whose frame transform breaks the loops of subgraphs is cut whole.
  out.reference_distinctive_share = pair_trust.ReferenceShare();
  out.reference_coverage = pair_trust.ReferenceCoverage();
  std::vector<double> trust(pairs.size());
  std::vector<double> coverage(pairs.size());
  std::vector<char> capture_linked(pairs.size(), 0);
  for (size_t p = 0; p < pairs.size(); ++p) {
    const bool all_edges = KeepsAllIfKept(alignments[p]);
    trust[p] = pair_trust.Of(alignments[p], all_edges);
    coverage[p] = pair_trust.RelativeCoverageOf(alignments[p], all_edges);
    capture_linked[p] = JoinsCaptureNeighbours(alignments[p], all_edges, capture_order);
  }
  std::vector<SubgraphFrame> frames;
  for (const AcceptedSubgraph& subgraph : accepted) frames.push_back(FrameOfSubgraph(subgraph.solution));
  out.pairs.resize(pairs.size());
  std::vector<PairVerdict> verdicts(pairs.size());
  if (options.loops.enabled && options.loops.method == SubgraphLoopOptions::Method::kTrustedForest) {
    std::vector<std::vector<EdgeInvalidation>> disagreements(pairs.size());
    const ForestTransformCheck check = [&](size_t p, const ChainedTransform& chained) -> std::optional<bool> {
      const SubgraphSolution& s1 = accepted[static_cast<size_t>(pairs[p].first)].solution;
      const SubgraphSolution& s2 = accepted[static_cast<size_t>(pairs[p].second)].solution;
      disagreements[p] =
          DisagreementsWithChain(alignments[p], s1, s2, placed_by_second[p] != 0, chained, options.alignment);
      bool any_voted = false;
      bool any_agrees = false;
      for (size_t e = 0; e < alignments[p].edges.size(); ++e) {
        if (!alignments[p].edges[e].voted) continue;
        any_voted = true;
        any_agrees = any_agrees || disagreements[p][e].reason == EdgeInvalidReason::kNone;
      }
      if (!any_voted) return std::nullopt;
      return any_agrees;
    };
    verdicts = JudgeAgainstTrustedForest(pairs, alignments, trust, coverage, capture_linked, frames, options.loops,
                                         check, disagreements, &out);
  } else {
    verdicts = VoteOnTriangles(pairs, alignments, trust, frames, options.loops, &out);
  }

  // 4. The decisions applied to the graph.
  for (size_t p = 0; p < pairs.size(); ++p) {
    const auto [k1, k2] = pairs[p];
    SubgraphAlignmentResult& alignment = alignments[p];
    const PairVerdict& verdict = verdicts[p];
    for (size_t e = 0; e < verdict.disagreements.size(); ++e) {
      if (verdict.disagreements[e].reason == EdgeInvalidReason::kNone) continue;
      alignment.edges[e].kept = false;
      alignment.edges[e].verdict = InterSubgraphVerdict::kLoopInconsistent;
    }
    for (InterSubgraphEdgeDecision& decision : alignment.edges) {
      if (verdict.keep_all) decision.kept = true;
      if (verdict.cut) {
        if (decision.kept || verdict.reason == InterSubgraphVerdict::kLoopInconsistent) {
          decision.verdict = verdict.reason;
        }
        decision.kept = false;
      }
    }
    SubgraphPairReport& pair_report = out.pairs[p];
    pair_report.k1 = k1;
    pair_report.k2 = k2;
    pair_report.status = alignment.status;
    pair_report.num_edges = alignment.edges.size();
    pair_report.num_voting_edges = alignment.num_voting_edges;
    pair_report.beta = alignment.beta;
    pair_report.hypotheses = alignment.hypotheses;
    pair_report.selected_hypothesis = alignment.selected_hypothesis;
    pair_report.has_frame_transform = alignment.has_frame_transform;
    pair_report.k2_to_k1 = alignment.k2_to_k1;
    pair_report.trust = trust[p];
    pair_report.capture_linked = capture_linked[p] != 0;
    pair_report.coverage = coverage[p];
    for (size_t e = 0; e < alignment.edges.size(); ++e) {
      const InterSubgraphEdgeDecision& decision = alignment.edges[e];
      if (decision.kept) continue;
      EdgeInvalidation why = verdict.cut && decision.verdict == verdict.reason
                                 ? verdict.invalidation
                                 : InterSubgraphInvalidation(decision, options.alignment);
      if (e < verdict.disagreements.size() && verdict.disagreements[e].reason != EdgeInvalidReason::kNone) {
        why = verdict.disagreements[e];
      }
      if (RemoveEdge(MakeViewPair(decision.placement.view_i, decision.placement.view_j), k1, k2, decision.verdict,
                     why, graph, &out.removed_edges)) {
        ++pair_report.num_removed_edges;
      }
    }
  }
  out.timings.push_back({"inter-subgraph pruning", SecondsSince(start)});
  if (options.landmark_check.max_angle_deg > 0.0) {
    start = std::chrono::steady_clock::now();
    CheckMatchesOfAlignedPairs(options.landmark_check, views_and_intrinsics, features, graph, &out);
    out.timings.push_back({"landmark check of matches", SecondsSince(start)});
  }
  out.num_output_edges = graph->NumValidEdges();
  out.total_seconds = SecondsSince(total_start);
}

void PrunedGlobalEngineOptions::SetSeedAndThreads(uint64_t seed, int num_threads, int solver_threads) {
  engine.seed = seed;
  engine.num_threads = solver_threads;
  pruning.partition.engine.seed = seed;
  // Communities in parallel, each engine run on one thread: the partition is then the same for
  // any thread count (a multi-threaded Ceres sums in a thread-dependent order).
  pruning.partition.engine.num_threads = 1;
  pruning.partition.num_threads = num_threads;
  pruning.partition.louvain.seed = seed;
  pruning.alignment.seed = seed;
  pruning.num_threads = num_threads;
}

namespace {

// The valid edges of `graph` between two different accepted subgraphs: those the pruning decided.
std::vector<ViewPair> InterSubgraphEdges(const ViewGraph& graph, const std::vector<AcceptedSubgraph>& accepted) {
  std::vector<ViewPair> edges;
  for (const EdgeOfSubgraphs& edge : EdgesOfAcceptedSubgraphs(graph, accepted)) {
    if (edge.k_first != edge.k_second) edges.push_back(edge.pair);
  }
  return edges;
}

// Applies the audit's verdicts to `pruned` and to the pruning report; returns whether any edge changed.
bool ApplyAudit(const ModelEdgeAuditOptions& options, ViewGraph* pruned, PrunedGlobalEngineReport* result) {
  std::vector<RemovedEdge>& removed = result->pruning.removed_edges;
  bool changed = false;
  for (const EdgeAgreement& agreement : result->pruning.audit) {
    if (agreement.transferred < options.min_transferred_matches) continue;
    ViewGraphEdge* edge = pruned->MutableEdge(agreement.pair.first, agreement.pair.second);
    const auto entry = std::find_if(removed.begin(), removed.end(),
                                    [&](const RemovedEdge& r) { return r.pair == agreement.pair; });
    if (!edge->is_valid && agreement.Share() >= options.readmit_agreement && entry != removed.end()) {
      edge->is_valid = true;
      edge->invalidation = EdgeInvalidation();
      removed.erase(entry);
      ++result->pruning.audit_readmitted;
      changed = true;
    } else if (edge->is_valid && agreement.Share() < options.keep_agreement) {
      const EdgeInvalidation why{EdgeInvalidReason::kModelDisagreement, agreement.Share(), options.keep_agreement};
      RemoveEdge(agreement.pair, -1, -1, InterSubgraphVerdict::kModelDisagreement, why, pruned, &removed);
      ++result->pruning.audit_removed;
      changed = true;
    }
  }
  result->pruning.num_output_edges = pruned->NumValidEdges();
  return changed;
}

// Whether views a and b are joined by a path of `adjacency` other than the edge (a, b) itself.
bool JoinedWithoutEdge(const std::map<IndexT, std::vector<IndexT>>& adjacency, const ViewPair& pair) {
  std::set<IndexT> reached{pair.first};
  std::vector<IndexT> frontier{pair.first};
  while (!frontier.empty()) {
    const IndexT view = frontier.back();
    frontier.pop_back();
    const auto neighbours = adjacency.find(view);
    if (neighbours == adjacency.end()) continue;
    for (const IndexT next : neighbours->second) {
      if (view == pair.first && next == pair.second) continue;
      if (next == pair.second) return true;
      if (reached.insert(next).second) frontier.push_back(next);
    }
  }
  return false;
}

// Removes the edges of round.removed from *pruned, lowest observed share first, except one whose
// removal would cut views off from the rest: an edge that alone joins some views to the others is
// their only placement, and without it the final solve drops them. Those edges leave round.removed.
void RemoveEdgesBelowTheBound(MissingCorrespondenceRound* round, ViewGraph* pruned, std::vector<RemovedEdge>* removed) {
  std::map<ViewPair, double> share;
  for (const EdgeObservedShare& edge : round->edges) share[edge.pair] = edge.Share();
  std::vector<ViewPair> order = round->removed;
  std::stable_sort(order.begin(), order.end(),
                   [&](const ViewPair& a, const ViewPair& b) { return share.at(a) < share.at(b); });
  std::map<IndexT, std::vector<IndexT>> adjacency = pruned->ValidAdjacency();
  round->removed.clear();
  for (const ViewPair& pair : order) {
    if (!JoinedWithoutEdge(adjacency, pair)) continue;
    auto& first = adjacency[pair.first];
    first.erase(std::remove(first.begin(), first.end(), pair.second), first.end());
    auto& second = adjacency[pair.second];
    second.erase(std::remove(second.begin(), second.end(), pair.first), second.end());
    const EdgeInvalidation why{EdgeInvalidReason::kMissingCorrespondences, share.at(pair), round->bound};
    RemoveEdge(pair, -1, -1, InterSubgraphVerdict::kMissingCorrespondences, why, pruned, removed);
    round->removed.push_back(pair);
  }
}

// The rounds of the missing-correspondence check (MissingCorrespondenceOptions): solve *pruned
// into *model with the final solve's schedule, judge the kept edges between subgraphs, remove the
// ones below the round's bound; again while a round removes edges.
PrunedGlobalEngineStep CheckMissingCorrespondences(const PrunedGlobalEngineOptions& options,
                                                   const SfmData& views_and_intrinsics,
                                                   const FeaturesPerView& features, ViewGraph* pruned,
                                                   SfmData* model, PrunedGlobalEngineReport* report,
                                                   const ProgressCallback& progress) {
  const MissingCorrespondenceOptions& check = options.pruning.missing_correspondences;
  ViewGraphPruningReport& pruning = report->pruning;
  for (size_t round = 0; round < check.max_rounds; ++round) {
    RunGlobalEngine(options.engine, *pruned, views_and_intrinsics, features, model, &report->engine, progress);
    pruning.timings.push_back({"solve for the missing-correspondence check", report->engine.total_seconds});
    if (!report->engine.success) return PrunedGlobalEngineStep::kAuditModelFailed;
    const auto start = std::chrono::steady_clock::now();
    MissingCorrespondenceRound verdict = JudgeObservedShares(
        MeasureObservedShares(*model, InterSubgraphEdges(*pruned, pruning.partition.accepted), check), check);
    RemoveEdgesBelowTheBound(&verdict, pruned, &pruning.removed_edges);
    pruning.num_output_edges = pruned->NumValidEdges();
    const bool changed = !verdict.removed.empty();
    pruning.missing_correspondence_rounds.push_back(std::move(verdict));
    pruning.timings.push_back({"missing-correspondence check", SecondsSince(start)});
    if (!changed) return PrunedGlobalEngineStep::kSolved;
  }
  return PrunedGlobalEngineStep::kSolvedBeforeChanges;
}

// The schedule of the solve before the audit (ModelEdgeAuditOptions::model_schedule).
GlobalEngineOptions AuditModelOptions(const GlobalEngineOptions& final_solve, AuditModelSchedule schedule) {
  GlobalEngineOptions options = final_solve;
  if (schedule == AuditModelSchedule::kPositioning) options.bundle_adjust = false;
  if (schedule == AuditModelSchedule::kLightAdjustment) {
    // One adjustment, stopped as the rounds before the final one are: the audit asks for pixels.
    options.num_bundle_rounds = 0;
    options.final_function_tolerance = options.intermediate_function_tolerance;
    options.bundle.max_num_iterations = options.intermediate_max_num_iterations;
  }
  return options;
}

// The model audit (ModelEdgeAuditOptions) of the pruned graph *pruned; kPruned when it is off.
PrunedGlobalEngineStep AuditTransfers(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                                      const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                      ViewGraph* pruned, SfmData* model, PrunedGlobalEngineReport* report,
                                      const ProgressCallback& progress) {
  if (!options.pruning.audit.enabled) return PrunedGlobalEngineStep::kPruned;
  RunGlobalEngine(AuditModelOptions(options.engine, options.pruning.audit.model_schedule), *pruned,
                  views_and_intrinsics, features, model, &report->engine, progress);
  if (!report->engine.success) return PrunedGlobalEngineStep::kAuditModelFailed;

  const auto start = std::chrono::steady_clock::now();
  report->pruning.audit = AuditEdgesAgainstModel(graph, InterSubgraphEdges(graph, report->pruning.partition.accepted),
                                                 *model, features, options.pruning.audit);
  const bool changed = ApplyAudit(options.pruning.audit, pruned, report);
  report->pruning.timings.push_back({"solve before the audit", report->engine.total_seconds});
  report->pruning.timings.push_back({"model audit", SecondsSince(start)});
  return changed ? PrunedGlobalEngineStep::kAuditedWithChanges : PrunedGlobalEngineStep::kAudited;
}

}  // namespace

PrunedGlobalEngineStep PruneAndAudit(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                                     const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                     ViewGraph* pruned, SfmData* model, PrunedGlobalEngineReport* report,
                                     const ProgressCallback& progress) {
  options.Check();
  *report = PrunedGlobalEngineReport();
  *pruned = graph;
  PruneViewGraph(options.pruning, pruned, views_and_intrinsics, features, &report->pruning, progress);
  const PrunedGlobalEngineStep step = AuditTransfers(options, graph, views_and_intrinsics, features, pruned, model,
                                                     report, progress);
  const MissingCorrespondenceOptions& check = options.pruning.missing_correspondences;
  if (!check.enabled || check.max_rounds == 0 || step == PrunedGlobalEngineStep::kAuditModelFailed) return step;
  return CheckMissingCorrespondences(options, views_and_intrinsics, features, pruned, model, report, progress);
}

void RunPrunedGlobalEngine(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                           const SfmData& views_and_intrinsics, const FeaturesPerView& features, SfmData* out,
                           PrunedGlobalEngineReport* report, const ProgressCallback& progress) {
  PrunedGlobalEngineReport local;
  PrunedGlobalEngineReport& result = report != nullptr ? *report : local;
  ViewGraph pruned;
  const PrunedGlobalEngineStep step =
      PruneAndAudit(options, graph, views_and_intrinsics, features, &pruned, out, &result, progress);
  if (step == PrunedGlobalEngineStep::kPruned) {
    RunGlobalEngine(options.engine, pruned, views_and_intrinsics, features, out, &result.engine, progress);
    return;
  }
  if (step == PrunedGlobalEngineStep::kAuditModelFailed || step == PrunedGlobalEngineStep::kSolved) return;
  if (step == PrunedGlobalEngineStep::kSolvedBeforeChanges) {
    RunGlobalEngine(options.engine, pruned, views_and_intrinsics, features, out, &result.engine, progress);
    return;
  }
  if (options.pruning.audit.refine_final) {
    // An adjusted audit model has had the first of the final solve's adjustment rounds.
    GlobalEngineOptions refine = options.engine;
    if (options.pruning.audit.model_schedule != AuditModelSchedule::kPositioning) {
      refine.num_bundle_rounds = std::max(refine.num_bundle_rounds - 1, 0);
    }
    const SfmData audited = std::move(*out);  // RefineGlobalModel resets *out from it
    RefineGlobalModel(refine, pruned, audited, features, out, &result.engine, progress);
  } else if (step == PrunedGlobalEngineStep::kAuditedWithChanges ||
             options.pruning.audit.model_schedule != AuditModelSchedule::kFull) {
    RunGlobalEngine(options.engine, pruned, views_and_intrinsics, features, out, &result.engine, progress);
  }
}

void ViewGraphPruningOptions::Check() const {
  capture_order.Check();
  partition.Check();
  alignment.Check();
  // 0: no cap; otherwise at least the minimal sample of two edges.
  if (max_sample_size != 0) {
    RequireAtLeast<size_t>(max_sample_size, 2, "ViewGraphPruningOptions::max_sample_size (or 0: no cap)");
  }
  loops.Check();
  RequireAtLeast(trust_prior_edges, 0.0, "ViewGraphPruningOptions::trust_prior_edges");
  RequireAtLeast(num_threads, 1, "ViewGraphPruningOptions::num_threads");
  audit.Check();
  landmark_check.Check();
}

void PrunedGlobalEngineOptions::Check() const {
  pruning.Check();
  engine.Check();
}

}  // namespace sfm_pruning
