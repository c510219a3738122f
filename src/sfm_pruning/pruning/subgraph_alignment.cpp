#include "sfm_pruning/pruning/subgraph_alignment.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <random>

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/ransac_samples.hpp"

namespace sfm_pruning {
namespace {

using Options = SubgraphAlignmentOptions;

struct Hypothesis {
  double beta = 1.0;
  Eigen::Matrix3d mean_rotation = Eigen::Matrix3d::Identity();  // geodesic (Karcher) mean
  Eigen::Vector3d mean_translation = Eigen::Vector3d::Zero();
};

struct EdgeCoverage {
  size_t expected = 0;
  size_t matched = 0;
};

struct Deviation {
  double rotation_deg = 0.0;
  double translation = 0.0;
};

// β*, t̄ and r̄ of a sample; empty when the sample has no scale information or β* ≤ 0 (a negative
// scale would mirror k2).
std::optional<Hypothesis> FitHypothesis(const std::vector<ChainedRelativePose>& chains,
                                        const std::vector<size_t>& sample) {
  std::vector<ChainedRelativePose> sampled;
  sampled.reserve(sample.size());
  for (size_t index : sample) sampled.push_back(chains[index]);
  const std::optional<double> beta = SolveChainScale(sampled);
  if (!beta || !(*beta > 0.0)) return std::nullopt;
  Hypothesis hypothesis;
  hypothesis.beta = *beta;
  std::vector<Eigen::Matrix3d> rotations;
  for (const ChainedRelativePose& chain : sampled) {
    hypothesis.mean_translation += chain.Translation(*beta);
    rotations.push_back(chain.rotation);
  }
  hypothesis.mean_translation /= static_cast<double>(sampled.size());
  hypothesis.mean_rotation = GeodesicMeanRotation(rotations).rotation;
  return hypothesis;
}

// E_r is the angle to the geodesic mean, not the paper's |Log(R_e) − mean Log(R_s)|: the two agree
// to first order, but the Log jumps from ω to −ω near 180° and a chained rotation c1 -> c2 can be
// anything.
Deviation MeasureDeviation(const ChainedRelativePose& chain, const Hypothesis& hypothesis) {
  Deviation deviation;
  deviation.rotation_deg = RadToDeg(RotationAngleBetween(hypothesis.mean_rotation, chain.rotation));
  deviation.translation = (chain.Translation(hypothesis.beta) - hypothesis.mean_translation).norm();
  return deviation;
}

struct Consensus {
  std::vector<bool> inlier;
  size_t count = 0;
  double total_error = 0.0;  // Σ over inliers of E_r / thr_r + E_t / thr_t
};

Consensus CountConsensus(const std::vector<ChainedRelativePose>& chains, const Hypothesis& hypothesis,
                         const Options& options) {
  Consensus consensus;
  consensus.inlier.assign(chains.size(), false);
  const double translation_threshold = options.max_translation_deviation_fraction * hypothesis.mean_translation.norm();
  for (size_t k = 0; k < chains.size(); ++k) {
    const Deviation deviation = MeasureDeviation(chains[k], hypothesis);
    if (deviation.rotation_deg <= options.max_rotation_deviation_deg && deviation.translation <= translation_threshold) {
      consensus.inlier[k] = true;
      ++consensus.count;
      consensus.total_error += deviation.rotation_deg / std::max(options.max_rotation_deviation_deg, 1e-300) +
                               deviation.translation / std::max(translation_threshold, 1e-300);
    }
  }
  return consensus;
}

size_t SampleSize(size_t num_voting, const Options& options) {
  const auto fraction = static_cast<size_t>(std::floor(options.sample_fraction * static_cast<double>(num_voting)));
  return std::min(num_voting, std::max(options.min_sample_size, fraction));
}

void ApplyPolicyToVoters(SubgraphAlignmentResult* result, InterSubgraphVerdict verdict, bool keep) {
  for (InterSubgraphEdgeDecision& decision : result->edges) {
    if (!decision.voted) continue;
    decision.verdict = verdict;
    decision.kept = keep;
  }
}

struct Candidate {
  Hypothesis hypothesis;
  Consensus consensus;  // over every voting edge
  int iteration = -1;
  int num_samples = 0;      // of its RANSAC run
  bool enumerated = false;  // that run tried every sample (RansacSamples)
};

// One RANSAC run whose samples are drawn from `pool` (indices into chains); the consensus is
// counted over every chain. Empty when every sample was degenerate.
std::optional<Candidate> RansacOverPool(const std::vector<ChainedRelativePose>& chains,
                                        const std::vector<size_t>& pool, const Options& options, std::mt19937_64* rng,
                                        SubgraphAlignmentResult* result) {
  const size_t n = pool.size();
  const size_t sample_size = SampleSize(n, options);
  if (result->sample_size == 0) result->sample_size = sample_size;
  RansacSamples samples(n, sample_size, options.num_ransac_iterations, options.max_enumerated_samples, rng);
  std::optional<Candidate> best;
  for (int iteration = 0; iteration < samples.size(); ++iteration) {
    std::vector<size_t> sample = samples.Next();
    for (size_t& k : sample) k = pool[k];  // the pool is ascending, so the sample stays sorted
    const std::optional<Hypothesis> hypothesis = FitHypothesis(chains, sample);
    if (!hypothesis) continue;
    ++result->num_valid_hypotheses;
    Consensus consensus = CountConsensus(chains, *hypothesis, options);
    const bool better = !best || consensus.count > best->consensus.count ||
                        (consensus.count == best->consensus.count &&
                         consensus.total_error < best->consensus.total_error);
    if (better) best = Candidate{*hypothesis, std::move(consensus), iteration};
  }
  if (best) {
    best->num_samples = samples.size();
    best->enumerated = samples.enumerated();
  }
  return best;
}

// The consensus's coverage sums and its score Σ (matched − break_even · expected) landmarks.
void ScoreCoverage(const Consensus& consensus, const std::vector<EdgeCoverage>& coverage, const Options& options,
                   AlignmentHypothesis* summary) {
  for (size_t k = 0; k < coverage.size(); ++k) {
    if (!consensus.inlier[k]) continue;
    summary->expected_landmarks += coverage[k].expected;
    summary->matched_landmarks += coverage[k].matched;
  }
  summary->coverage_score =
      static_cast<double>(summary->matched_landmarks) -
      options.coverage_break_even * static_cast<double>(summary->expected_landmarks);
}

// When every candidate falls below the absolute break-even: a candidate whose coverage is below
// relative_coverage_break_even times the best candidate's is ruled out (none with
// relative_coverage_break_even = 0: the largest of all wins).
std::vector<bool> RelativelyRuledOut(const std::vector<AlignmentHypothesis>& hypotheses, const Options& options) {
  double best = 0.0;
  for (const AlignmentHypothesis& h : hypotheses) best = std::max(best, h.Coverage());
  std::vector<bool> out;
  for (const AlignmentHypothesis& h : hypotheses) {
    out.push_back(h.Coverage() < options.relative_coverage_break_even * best);
  }
  return out;
}

// Options::rotation_only_fallback: every voter tried as the centre, the largest set of voters whose
// chained rotations lie within max_rotation_deviation_deg of it (ties: the smaller total
// deviation, then the earlier centre). Decides the voters when that set has two edges or more.
bool ApplyRotationOnlyConsensus(const std::vector<ChainedRelativePose>& chains,
                                const std::vector<size_t>& voter_edge_index, const Options& options,
                                SubgraphAlignmentResult* result) {
  const double threshold = options.max_rotation_deviation_deg;
  size_t best_centre = 0;
  size_t best_count = 0;
  double best_total = 0.0;
  for (size_t centre = 0; centre < chains.size(); ++centre) {
    size_t count = 0;
    double total = 0.0;
    for (const ChainedRelativePose& chain : chains) {
      const double deviation = RadToDeg(RotationAngleBetween(chains[centre].rotation, chain.rotation));
      if (deviation > threshold) continue;
      ++count;
      total += deviation;
    }
    if (count > best_count || (count == best_count && total < best_total)) {
      best_centre = centre;
      best_count = count;
      best_total = total;
    }
  }
  if (best_count < 2) return false;
  result->status = SubgraphAlignmentStatus::kRotationOnly;
  result->consensus_size = best_count;
  result->mean_rotation = chains[best_centre].rotation;
  for (size_t k = 0; k < chains.size(); ++k) {
    InterSubgraphEdgeDecision& decision = result->edges[voter_edge_index[k]];
    decision.rotation_deviation_deg = RadToDeg(RotationAngleBetween(chains[best_centre].rotation, chains[k].rotation));
    decision.kept = decision.rotation_deviation_deg <= threshold;
    decision.verdict = decision.kept ? InterSubgraphVerdict::kConsistent : InterSubgraphVerdict::kRotationDeviation;
  }
  return true;
}

// The paper's step: one RANSAC run over every voter. With kMatchCoverage (an addition) the RANSAC
// runs again on the voters that no candidate so far explains, for up to max_hypotheses candidates,
// each later one backed by a consensus of its own (not just the leftovers).
std::vector<Candidate> FindCandidates(const std::vector<ChainedRelativePose>& chains, const Options& options,
                                      SubgraphAlignmentResult* result) {
  std::mt19937_64 rng(options.seed);
  std::vector<size_t> pool(chains.size());
  std::iota(pool.begin(), pool.end(), size_t{0});
  const size_t min_consensus = std::max<size_t>(options.min_edges_for_ransac, 2);
  const size_t max_candidates =
      options.hypothesis_selection == Options::HypothesisSelection::kMatchCoverage ? options.max_hypotheses : 1;
  std::vector<Candidate> candidates;
  while (candidates.size() < std::max<size_t>(max_candidates, 1)) {
    std::optional<Candidate> candidate = RansacOverPool(chains, pool, options, &rng, result);
    if (!candidate) break;
    if (!candidates.empty() && candidate->consensus.count < min_consensus) break;
    candidates.push_back(std::move(*candidate));
    std::vector<size_t> rest;
    for (size_t k : pool) {
      bool explained = false;
      for (const Candidate& c : candidates) explained = explained || c.consensus.inlier[k];
      if (!explained) rest.push_back(k);
    }
    if (rest.size() < min_consensus) break;
    pool = std::move(rest);
  }
  return candidates;
}

bool AnyCandidateSupported(const std::vector<Candidate>& candidates) {
  return std::any_of(candidates.begin(), candidates.end(), [](const Candidate& c) { return c.consensus.count > 0; });
}

// The selection among the candidates; records each in result->hypotheses. The paper's rule is the
// largest consensus. The match-coverage policy first rules out the candidates whose edges miss
// more landmarks than the break-even (or, when that rules out every one, as on real images, those
// far below the best: RelativelyRuledOut), and a candidate that no edge agrees with (its own sample
// failed the thresholds) expects nothing, so its coverage cannot rule it out: it never wins over one
// that some edges support (real street, seed 9: an empty candidate beat one of 3 edges and the pair
// lost its transform). With a single candidate the rules change nothing.
size_t SelectCandidate(const std::vector<Candidate>& candidates, const std::vector<EdgeCoverage>& coverage,
                       const Options& options, SubgraphAlignmentResult* result) {
  for (const Candidate& candidate : candidates) {
    AlignmentHypothesis summary;
    summary.consensus_size = candidate.consensus.count;
    summary.beta = candidate.hypothesis.beta;
    ScoreCoverage(candidate.consensus, coverage, options, &summary);
    summary.num_samples = candidate.num_samples;
    summary.enumerated = candidate.enumerated;
    result->hypotheses.push_back(summary);
  }
  std::vector<bool> ruled_out(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c) ruled_out[c] = result->hypotheses[c].coverage_score < 0.0;
  if (std::all_of(ruled_out.begin(), ruled_out.end(), [](bool out) { return out; })) {
    ruled_out = RelativelyRuledOut(result->hypotheses, options);
  }
  const bool supported = AnyCandidateSupported(candidates);
  for (size_t c = 0; c < candidates.size(); ++c) {
    if (result->hypotheses[c].consensus_size == 0 && supported) ruled_out[c] = true;
    result->hypotheses[c].ruled_out = ruled_out[c];
  }
  size_t chosen = 0;
  for (size_t c = 1; c < candidates.size(); ++c) {
    const bool larger = result->hypotheses[c].consensus_size > result->hypotheses[chosen].consensus_size;
    const bool better = ruled_out[chosen] ? (!ruled_out[c] || larger) : (!ruled_out[c] && larger);
    if (better) chosen = c;
  }
  result->selected_hypothesis = static_cast<int>(chosen);
  return chosen;
}

// The verdict of every voter under the selected candidate: kept when in its consensus, else
// removed for the deviation that failed (rotation first).
void ApplyCandidate(const std::vector<ChainedRelativePose>& chains, const std::vector<size_t>& voter_edge_index,
                    const Candidate& candidate, const Options& options, SubgraphAlignmentResult* result) {
  const Hypothesis& best = candidate.hypothesis;
  result->best_iteration = candidate.iteration;
  result->status = SubgraphAlignmentStatus::kAligned;
  result->beta = best.beta;
  result->mean_rotation = best.mean_rotation;
  result->mean_translation = best.mean_translation;
  result->consensus_size = candidate.consensus.count;
  const double translation_threshold = options.max_translation_deviation_fraction * best.mean_translation.norm();
  for (size_t k = 0; k < chains.size(); ++k) {
    InterSubgraphEdgeDecision& decision = result->edges[voter_edge_index[k]];
    const Deviation deviation = MeasureDeviation(chains[k], best);
    decision.rotation_deviation_deg = deviation.rotation_deg;
    decision.translation_deviation = deviation.translation;
    decision.translation_threshold = translation_threshold;
    decision.kept = candidate.consensus.inlier[k];
    decision.verdict = decision.kept ? InterSubgraphVerdict::kConsistent
                       : deviation.rotation_deg > options.max_rotation_deviation_deg
                           ? InterSubgraphVerdict::kRotationDeviation
                           : InterSubgraphVerdict::kTranslationDeviation;
  }
}

// The inter-subgraph RANSAC of a pair with enough voters: the candidates (the paper's run, plus the
// match-coverage policy's further runs), then the policy for a pair that no candidate's edges
// support (the rotation-only fallback, else every voter kept unjudged), else the selected
// candidate's verdicts.
void RunRansac(const std::vector<ChainedRelativePose>& chains, const std::vector<EdgeCoverage>& coverage,
               const std::vector<size_t>& voter_edge_index, const Options& options, SubgraphAlignmentResult* result) {
  const std::vector<Candidate> candidates = FindCandidates(chains, options, result);
  if (!AnyCandidateSupported(candidates) && options.rotation_only_fallback &&
      ApplyRotationOnlyConsensus(chains, voter_edge_index, options, result)) {
    return;
  }
  if (candidates.empty()) {
    result->status = SubgraphAlignmentStatus::kNoValidHypothesis;
    ApplyPolicyToVoters(result, InterSubgraphVerdict::kUnjudged, true);
    return;
  }
  const size_t chosen = SelectCandidate(candidates, coverage, options, result);
  ApplyCandidate(chains, voter_edge_index, candidates[chosen], options, result);
}

}  // namespace

const char* SubgraphAlignmentStatusName(SubgraphAlignmentStatus status) {
  switch (status) {
    case SubgraphAlignmentStatus::kNoEdges: return "no_edges";
    case SubgraphAlignmentStatus::kAligned: return "aligned";
    case SubgraphAlignmentStatus::kTooFewVotingEdges: return "too_few_voting_edges";
    case SubgraphAlignmentStatus::kNoValidHypothesis: return "no_valid_hypothesis";
    case SubgraphAlignmentStatus::kRotationOnly: return "rotation_only";
  }
  return "unknown";
}

const char* InterSubgraphVerdictName(InterSubgraphVerdict verdict) {
  switch (verdict) {
    case InterSubgraphVerdict::kConsistent: return "consistent";
    case InterSubgraphVerdict::kRotationDeviation: return "rotation_deviation";
    case InterSubgraphVerdict::kTranslationDeviation: return "translation_deviation";
    case InterSubgraphVerdict::kCannotVote: return "cannot_vote";
    case InterSubgraphVerdict::kFewEdges: return "few_edges";
    case InterSubgraphVerdict::kUnjudged: return "unjudged";
    case InterSubgraphVerdict::kLoopInconsistent: return "loop_inconsistent";
    case InterSubgraphVerdict::kUnverified: return "unverified";
    case InterSubgraphVerdict::kModelDisagreement: return "model_disagreement";
    case InterSubgraphVerdict::kLandmarkDisagreement: return "landmark_disagreement";
    case InterSubgraphVerdict::kCapturePathRotation: return "capture_path_rotation";
    case InterSubgraphVerdict::kCapturePathDirection: return "capture_path_direction";
    case InterSubgraphVerdict::kMissingCorrespondences: return "missing_correspondences";
  }
  return "unknown";
}

std::vector<ViewPair> SubgraphAlignmentResult::KeptEdges() const {
  std::vector<ViewPair> kept;
  for (const auto& decision : edges) {
    if (decision.kept) kept.push_back({decision.placement.view_i, decision.placement.view_j});
  }
  return kept;
}

std::vector<ViewPair> SubgraphAlignmentResult::RemovedEdges() const {
  std::vector<ViewPair> removed;
  for (const auto& decision : edges) {
    if (!decision.kept) removed.push_back({decision.placement.view_i, decision.placement.view_j});
  }
  return removed;
}

EdgeInvalidation InterSubgraphInvalidation(const InterSubgraphEdgeDecision& decision, const Options& options) {
  EdgeInvalidation why;
  if (decision.kept) return why;
  switch (decision.verdict) {
    case InterSubgraphVerdict::kRotationDeviation:
      return {EdgeInvalidReason::kInterSubgraphInconsistent, decision.rotation_deviation_deg,
              options.max_rotation_deviation_deg};
    case InterSubgraphVerdict::kTranslationDeviation: {
      const double relative = decision.translation_threshold > 0.0
                                  ? decision.translation_deviation * options.max_translation_deviation_fraction /
                                        decision.translation_threshold
                                  : decision.translation_deviation;
      return {EdgeInvalidReason::kInterSubgraphInconsistent, relative, options.max_translation_deviation_fraction,
              EdgeMeasure::kTranslationFraction};
    }
    case InterSubgraphVerdict::kCannotVote:
      return {EdgeInvalidReason::kOther, static_cast<double>(decision.placement.num_correspondences),
              static_cast<double>(options.placement.min_correspondences), EdgeMeasure::kCorrespondences};
    case InterSubgraphVerdict::kFewEdges:
      return {EdgeInvalidReason::kOther, 0.0, static_cast<double>(options.min_edges_for_ransac),
              EdgeMeasure::kVotingEdges};
    default:
      return {EdgeInvalidReason::kOther, 0.0, 0.0};
  }
}

SubgraphAlignmentResult AlignSubgraphPair(const ViewGraph& graph, const SubgraphSolution& k1,
                                          const SubgraphSolution& k2, const SfmData& views_and_intrinsics,
                                          const FeaturesPerView& features, const Options& options) {
  SubgraphAlignmentResult result;
  const std::vector<ViewPair> connecting = ConnectingEdges(graph, k1.view_ids, k2.view_ids);
  if (connecting.empty()) return result;

  const std::map<ObservationKey, IndexT> landmarks_k1 = IndexLandmarksByObservation(k1);
  const Pose mean_k1 = SubgraphMeanPose(k1);
  const Pose mean_k2 = SubgraphMeanPose(k2);
  std::vector<ChainedRelativePose> chains;
  std::vector<EdgeCoverage> coverage;
  std::vector<size_t> voter_edge_index;
  for (const ViewPair& edge : connecting) {
    InterSubgraphEdgeDecision decision;
    decision.placement = PlaceViewInSubgraph(graph, edge.first, edge.second, k1, landmarks_k1, views_and_intrinsics,
                                             features, options.placement);
    const auto pose_j_in_k2 = k2.poses.find(edge.second);
    decision.j_posed_in_k2 = pose_j_in_k2 != k2.poses.end();
    decision.voted = decision.placement.status == EdgePlacementStatus::kPlaced && decision.j_posed_in_k2;
    if (decision.voted) {
      chains.push_back(ChainRelativePose(mean_k1, decision.placement.pose_j_in_k1, pose_j_in_k2->second, mean_k2));
      coverage.push_back({decision.placement.num_expected_landmarks, decision.placement.num_matched_landmarks});
      voter_edge_index.push_back(result.edges.size());
    } else {
      decision.verdict = InterSubgraphVerdict::kCannotVote;
      decision.kept = options.non_voting_edges == Options::NonVotingPolicy::kKeep;
    }
    result.edges.push_back(decision);
  }
  result.num_voting_edges = chains.size();
  if (chains.size() < std::max<size_t>(options.min_edges_for_ransac, 2)) {
    result.status = SubgraphAlignmentStatus::kTooFewVotingEdges;
    ApplyPolicyToVoters(&result, InterSubgraphVerdict::kFewEdges,
                        options.few_edges == Options::FewEdgesPolicy::kKeepAll);
    return result;
  }
  RunRansac(chains, coverage, voter_edge_index, options, &result);
  if (result.status == SubgraphAlignmentStatus::kAligned) {
    result.has_frame_transform = true;
    result.k2_to_k1 =
        FrameSimilarityOfChain(mean_k1, mean_k2, result.mean_rotation, result.mean_translation, result.beta);
  }
  return result;
}

std::vector<EdgeAgainstTransform> JudgeEdgesAgainstTransform(const SubgraphAlignmentResult& alignment,
                                                             const SubgraphSolution& k1, const SubgraphSolution& k2,
                                                             const Similarity3& k2_to_k1, const Options& options) {
  const Pose mean_k1 = SubgraphMeanPose(k1);
  const Pose mean_k2 = SubgraphMeanPose(k2);
  const RelativePose implied = RelativePoseBetween(mean_k1, k2_to_k1.Apply(mean_k2));
  Hypothesis hypothesis;
  hypothesis.beta = k2_to_k1.scale;
  hypothesis.mean_rotation = implied.rotation;
  hypothesis.mean_translation = implied.translation;
  const double translation_scale = std::max(hypothesis.mean_translation.norm(), 1e-300);
  std::vector<EdgeAgainstTransform> judged(alignment.edges.size());
  for (size_t e = 0; e < alignment.edges.size(); ++e) {
    const InterSubgraphEdgeDecision& decision = alignment.edges[e];
    const auto pose_j_in_k2 = k2.poses.find(decision.placement.view_j);
    if (!decision.voted || pose_j_in_k2 == k2.poses.end()) continue;
    const Deviation deviation = MeasureDeviation(
        ChainRelativePose(mean_k1, decision.placement.pose_j_in_k1, pose_j_in_k2->second, mean_k2), hypothesis);
    EdgeAgainstTransform& edge = judged[e];
    edge.voted = true;
    edge.rotation_deviation_deg = deviation.rotation_deg;
    edge.translation_deviation_fraction = deviation.translation / translation_scale;
    edge.agrees = edge.rotation_deviation_deg <= options.max_rotation_deviation_deg &&
                  edge.translation_deviation_fraction <= options.max_translation_deviation_fraction;
  }
  return judged;
}

void SubgraphAlignmentOptions::Check() const {
  placement.Check();
  RequireInRange(num_ransac_iterations, 1, 1000000, "SubgraphAlignmentOptions::num_ransac_iterations");
  RequirePositiveAtMost(sample_fraction, 1.0, "SubgraphAlignmentOptions::sample_fraction");
  // β* needs two edges (chained_relative_pose.hpp).
  RequireAtLeast<size_t>(min_sample_size, 2, "SubgraphAlignmentOptions::min_sample_size");
  RequirePositiveAtMost(max_rotation_deviation_deg, 180.0, "SubgraphAlignmentOptions::max_rotation_deviation_deg");
  RequirePositiveAtMost(max_translation_deviation_fraction, 1e6,
                        "SubgraphAlignmentOptions::max_translation_deviation_fraction");
  RequireAtLeast<size_t>(max_hypotheses, 1, "SubgraphAlignmentOptions::max_hypotheses");
  RequireInRange(coverage_break_even, 0.0, 1.0, "SubgraphAlignmentOptions::coverage_break_even");
  RequireInRange(relative_coverage_break_even, 0.0, 1.0, "SubgraphAlignmentOptions::relative_coverage_break_even");
}

}  // namespace sfm_pruning
