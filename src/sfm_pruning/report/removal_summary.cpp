#include "sfm_pruning/report/removal_summary.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "sfm_pruning/report/svg_builder.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// The removed edges of one group, collected before their medians are taken.
struct GroupValues {
  std::vector<double> values;
  std::vector<double> thresholds;
  std::set<std::pair<int, int>> subgraph_pairs;
};

RemovalGroup Summarise(const std::pair<std::string, std::string>& key, const GroupValues& values) {
  RemovalGroup group;
  group.reason = key.first;
  group.measure = key.second;
  group.edges = values.values.size();
  group.subgraph_pairs = values.subgraph_pairs.size();
  group.median_value = Median(values.values);
  group.median_threshold = Median(values.thresholds);
  return group;
}

// Most edges first; ties by reason, then measure, so the order does not depend on the map's.
bool MoreEdges(const RemovalGroup& a, const RemovalGroup& b) {
  return std::tie(b.edges, a.reason, a.measure) < std::tie(a.edges, b.reason, b.measure);
}

std::string Percent(double share) { return FormatNumber(100.0 * share, 0) + " %"; }

// What a translation fraction of `reason` is a fraction of.
std::string TranslationReference(const std::string& reason) {
  if (reason == "inter_subgraph_inconsistent") return "the two subgraphs' mean offset";
  if (reason == "subgraph_loop_inconsistent") return "the loop's mean side";
  return "the length it is held to";
}

}  // namespace

RemovalSummary SummariseRemovals(const RunViewGraph& graph) {
  std::map<IndexT, int> subgraph_of;
  for (const RunGraphView& view : graph.views) subgraph_of[view.view_id] = view.subgraph;
  using GroupKey = std::pair<std::string, std::string>;
  std::map<GroupKey, GroupValues> by_reason;
  struct PairValues {
    size_t removed = 0, kept = 0;
    std::map<GroupKey, GroupValues> by_reason;
  };
  std::map<std::pair<int, int>, PairValues> by_pair;

  RemovalSummary summary;
  summary.edges = graph.edges.size();
  for (const RunGraphEdge& edge : graph.edges) {
    int a = subgraph_of.count(edge.i) != 0 ? subgraph_of.at(edge.i) : -1;
    int b = subgraph_of.count(edge.j) != 0 ? subgraph_of.at(edge.j) : -1;
    if (a < 0 || b < 0) a = b = -1;  // outside the partition: one group
    const std::pair<int, int> pair(std::min(a, b), std::max(a, b));
    PairValues& pair_values = by_pair[pair];
    if (!edge.removed) {
      ++pair_values.kept;
      continue;
    }
    ++summary.removed;
    ++pair_values.removed;
    const GroupKey key(edge.reason, edge.measure);
    for (GroupValues* values : {&by_reason[key], &pair_values.by_reason[key]}) {
      values->values.push_back(edge.value);
      values->thresholds.push_back(edge.threshold);
      values->subgraph_pairs.insert(pair);
    }
  }

  for (const auto& [key, values] : by_reason) summary.groups.push_back(Summarise(key, values));
  std::sort(summary.groups.begin(), summary.groups.end(), MoreEdges);
  for (const auto& [pair, values] : by_pair) {
    if (values.removed == 0) continue;
    SubgraphPairRemovals removals;
    removals.a = pair.first;
    removals.b = pair.second;
    removals.removed = values.removed;
    removals.kept = values.kept;
    bool first = true;
    for (const auto& [key, group_values] : values.by_reason) {
      const RemovalGroup group = Summarise(key, group_values);
      if (first || MoreEdges(group, removals.main)) removals.main = group;
      first = false;
    }
    summary.pairs.push_back(removals);
  }
  std::stable_sort(summary.pairs.begin(), summary.pairs.end(),
                   [](const SubgraphPairRemovals& x, const SubgraphPairRemovals& y) { return x.removed > y.removed; });
  return summary;
}

std::string RemovalReasonInWords(const std::string& reason) {
  static const std::map<std::string, std::string> words = {
      {"inter_subgraph_inconsistent",
       "they disagree with the alignment of their two subgraphs that the inter-subgraph RANSAC chose"},
      {"subgraph_loop_inconsistent", "the alignment of their two subgraphs does not close a loop of subgraphs"},
      {"unverified_subgraph_pair",
       "no loop of subgraphs can check their subgraph pair and its matches are not distinctive enough to keep "
       "it unchecked"},
      {"model_disagreement", "the model solved from the pruned graph does not reproduce their matches"},
      {"landmark_disagreement", "too few of their matches agree with the two subgraphs' landmarks"},
      {"rotation_residual", "their relative rotation disagrees with the averaged rotations"},
      {"translation_direction",
       "their translation direction disagrees with the model solved from the pairs along the capture path"},
      {"missing_correspondences", "their views miss far more of the landmarks the solved model predicts in them "
                                  "than the other edges do"},
      {"too_few_inliers", "they have too few inlier matches"},
      {"low_inlier_ratio", "too few of their putative matches are inliers"},
      {"other", "the inter-subgraph vote could not place or judge them"},
  };
  const auto it = words.find(reason);
  return it != words.end() ? it->second : reason;
}

std::string MeasureValueInWords(const std::string& reason, const std::string& measure, double value) {
  if (measure == "degrees") return FormatNumber(value, 1) + "°";
  if (measure == "translation_fraction") return FormatNumber(value, 2) + " × " + TranslationReference(reason);
  if (measure == "scale_ratio") return "a scale ratio of " + FormatNumber(value, 2);
  if (measure == "broken_loops") return FormatNumber(value, 0) + " broken subgraph triangles";
  if (measure == "trust") return "a trust of " + FormatNumber(value, 2);
  if (measure == "agreeing_share" || measure == "inlier_ratio") return Percent(value);
  if (measure == "matches_left") return FormatNumber(value, 0) + " matches left";
  if (measure == "correspondences") return FormatNumber(value, 0) + " 2D-3D correspondences";
  if (measure == "voting_edges") return FormatNumber(value, 0) + " voting edges";
  if (measure == "inliers") return FormatNumber(value, 0) + " inliers";
  return FormatNumber(value, 2);
}

std::string GroupMeasureInWords(const RemovalGroup& group) {
  const std::string& m = group.measure;
  const double value = group.median_value, bound = group.median_threshold;
  const std::string& r = group.reason;
  if (m == "degrees") {
    return "median " + MeasureValueInWords(r, m, value) + " off, allowed " + MeasureValueInWords(r, m, bound);
  }
  if (m == "translation_fraction") {
    return "median displacement " + MeasureValueInWords(r, m, value) + ", allowed " + FormatNumber(bound, 2) + " ×";
  }
  if (m == "scale_ratio") return "median scale ratio " + FormatNumber(value, 2) + ", allowed " + FormatNumber(bound, 2);
  if (m == "broken_loops") {
    return "median " + MeasureValueInWords(r, m, value) + " against " + FormatNumber(bound, 0) + " closing";
  }
  if (m == "trust") return "median trust " + FormatNumber(value, 2) + " (1: as distinctive as the subgraphs' own edges)";
  if (m == "agreeing_share") {
    return "median " + Percent(value) + " of the matches agree with the model, " + Percent(bound) + " needed";
  }
  if (m == "inlier_ratio") return "median " + Percent(value) + " inliers, " + Percent(bound) + " needed";
  if (m == "voting_edges") return "fewer than " + FormatNumber(bound, 0) + " edges between the subgraphs to vote";
  if (m == "matches_left" || m == "correspondences" || m == "inliers") {
    return "median " + MeasureValueInWords(r, m, value) + ", " + FormatNumber(bound, 0) + " needed";
  }
  return "median " + FormatNumber(value, 2) + ", threshold " + FormatNumber(bound, 2);
}

}  // namespace sfm_pruning
