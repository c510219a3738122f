#include "sfm_pruning/global/link_depth_votes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/geometry/triangulation.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

// One end of a link: the feature `feature` of view `view` takes part in match `match` of edge
// `edge` (index in ValidEdgePairs order) with log(floored inverse depth) `log_rho` in that view.
struct LinkEnd {
  IndexT view = 0;
  IndexT feature = 0;
  size_t edge = 0;
  size_t match = 0;
  double log_rho = 0.0;
  bool far = false;  // at the floor (far_fraction of the edge's median)
  // How far log_rho may be off by the angular noise alone: noise / parallax angle of the match
  // (the parallax floored like rho).
  double log_noise = 0.0;
};

// One match triangulated along its edge.
struct LinkDepths {
  double rho_first = 0.0;   // inverse depth in the first view
  double rho_second = 0.0;  // in the second
  double parallax_rad = 0.0;
};

// Inverse depths of one match in both views (distances along the unit rays, baseline |t| = 1) from
// the two-view midpoint triangulation, and the angle between the rays. Parallel rays: 0 (at
// infinity); negative: behind that camera.
LinkDepths Triangulate(const RelativePose& pose, const Eigen::Vector3d& ray_first, const Eigen::Vector3d& ray_second) {
  LinkDepths depths;
  depths.parallax_rad = AngleBetweenVectors(ray_first, pose.rotation.transpose() * ray_second);
  if (const std::optional<TwoViewPoint> point = TriangulateTwoView(pose, ray_first, ray_second, 1e-7)) {
    depths.rho_first = 1.0 / point->depth_i;
    depths.rho_second = 1.0 / point->depth_j;
  }
  return depths;
}

// far_fraction times the median of the positive, finite values (a tiny positive number when there
// is none).
double FloorOf(const std::vector<double>& values, double far_fraction) {
  std::vector<double> positive;
  for (const double value : values) {
    if (value > 0.0 && std::isfinite(value)) positive.push_back(value);
  }
  return positive.empty() ? 1e-12 : std::max(far_fraction * Median(std::move(positive)), 1e-12);
}

// The link ends of one edge's matches (`depths` in match order).
void AddLinkEnds(const LinkDepthVoteOptions& options, const ViewPair& pair, size_t edge_index,
                 const std::vector<FeatureMatch>& matches, const std::vector<LinkDepths>& depths,
                 std::vector<LinkEnd>* ends) {
  std::vector<double> rho_first, rho_second, parallax;
  for (const LinkDepths& link : depths) {
    rho_first.push_back(link.rho_first);
    rho_second.push_back(link.rho_second);
    parallax.push_back(link.parallax_rad);
  }
  const double floor_first = FloorOf(rho_first, options.far_fraction);
  const double floor_second = FloorOf(rho_second, options.far_fraction);
  const double parallax_floor = FloorOf(parallax, options.far_fraction);
  const double noise_rad = DegToRad(options.angular_noise_deg);
  for (size_t k = 0; k < matches.size(); ++k) {
    const double log_noise = noise_rad / std::max(depths[k].parallax_rad, parallax_floor);
    const bool far_first = !std::isfinite(rho_first[k]) || rho_first[k] <= floor_first;
    const bool far_second = !std::isfinite(rho_second[k]) || rho_second[k] <= floor_second;
    ends->push_back({pair.first, matches[k].i, edge_index, k, std::log(far_first ? floor_first : rho_first[k]),
                     far_first, log_noise});
    ends->push_back({pair.second, matches[k].j, edge_index, k, std::log(far_second ? floor_second : rho_second[k]),
                     far_second, log_noise});
  }
}

// The link ends of every valid edge whose two views have intrinsics and features.
std::vector<LinkEnd> CollectLinkEnds(const LinkDepthVoteOptions& options, const std::vector<ViewPair>& pairs,
                                     const ViewGraph& graph, const SfmData& views_and_intrinsics,
                                     const FeaturesPerView& features) {
  std::vector<LinkEnd> ends;
  for (size_t edge_index = 0; edge_index < pairs.size(); ++edge_index) {
    const ViewPair& pair = pairs[edge_index];
    const ViewGraphEdge& edge = *graph.FindEdge(pair.first, pair.second);
    const CameraIntrinsics* first = views_and_intrinsics.FindIntrinsics(pair.first);
    const CameraIntrinsics* second = views_and_intrinsics.FindIntrinsics(pair.second);
    const auto first_features = features.find(pair.first);
    const auto second_features = features.find(pair.second);
    if (first == nullptr || second == nullptr || first_features == features.end() ||
        second_features == features.end()) {
      continue;
    }
    std::vector<LinkDepths> depths(edge.matches.size());
    bool usable = true;
    for (size_t k = 0; k < edge.matches.size(); ++k) {
      const FeatureMatch& match = edge.matches[k];
      if (match.i >= first_features->second.size() || match.j >= second_features->second.size()) {
        usable = false;
        break;
      }
      const Eigen::Vector3d ray_first = first->Unproject(first_features->second.Position(match.i)).normalized();
      const Eigen::Vector3d ray_second = second->Unproject(second_features->second.Position(match.j)).normalized();
      depths[k] = Triangulate(edge.relative_pose, ray_first, ray_second);
    }
    if (usable) AddLinkEnds(options, pair, edge_index, edge.matches, depths, &ends);
  }
  // Grouped by feature; within a feature by edge.
  std::sort(ends.begin(), ends.end(), [](const LinkEnd& a, const LinkEnd& b) {
    return std::tie(a.view, a.feature, a.edge, a.match) < std::tie(b.view, b.feature, b.edge, b.match);
  });
  return ends;
}

// Calls visit(begin, end) for each run of link ends of one feature.
template <typename Visitor>
void ForEachFeature(const std::vector<LinkEnd>& ends, Visitor&& visit) {
  for (size_t begin = 0; begin < ends.size();) {
    size_t end = begin + 1;
    while (end < ends.size() && ends[end].view == ends[begin].view && ends[end].feature == ends[begin].feature) ++end;
    visit(begin, end);
    begin = end;
  }
}

// The centre of the densest cluster of `values`: the median of the largest set within one window of
// width `window`. Not the median of all: where the pair of edges shares as many twin links as true
// ones, the twins' log ratios spread (their depths are arbitrary) while the true ones agree
// exactly (the baselines' ratio), so the mode finds the true ratio where the median would not.
double DensestClusterCentre(std::vector<double> values, double window) {
  std::sort(values.begin(), values.end());
  size_t best_begin = 0, best_end = 1;
  for (size_t begin = 0, end = 0; begin < values.size(); ++begin) {
    while (end < values.size() && values[end] - values[begin] <= window) ++end;
    if (end - begin > best_end - best_begin) best_begin = begin, best_end = end;
  }
  return values[(best_begin + best_end - 1) / 2];
}

// Per pair of edges (smaller index first) of one view: the log of their baselines' ratio,
// log(rho_first edge / rho_second edge) at the densest cluster over the features they share, when
// they share at least min_shared_features.
std::map<std::pair<size_t, size_t>, double> EdgePairRatios(const LinkDepthVoteOptions& options,
                                                           const std::vector<LinkEnd>& ends) {
  std::map<std::pair<size_t, size_t>, std::vector<double>> samples;
  ForEachFeature(ends, [&](size_t begin, size_t end) {
    for (size_t p = begin; p < end; ++p) {
      for (size_t q = p + 1; q < end; ++q) {
        // A far point says nothing about the baselines' ratio (and the twins at infinity of a
        // repeated facade would all say the same wrong thing).
        if (ends[p].edge == ends[q].edge || ends[p].far || ends[q].far) continue;
        samples[{ends[p].edge, ends[q].edge}].push_back(ends[p].log_rho - ends[q].log_rho);
      }
    }
  });
  std::map<std::pair<size_t, size_t>, double> ratios;
  for (auto& [key, values] : samples) {
    if (values.size() >= options.min_shared_features) {
      ratios.emplace(key, DensestClusterCentre(std::move(values), std::log(options.max_inverse_depth_ratio)));
    }
  }
  return ratios;
}

}  // namespace

LinkDepthVoteResult DropDepthInconsistentLinks(const LinkDepthVoteOptions& options, const ViewGraph& graph,
                                              const SfmData& views_and_intrinsics, const FeaturesPerView& features) {
  options.Check();
  LinkDepthVoteResult result;
  result.graph = graph;
  const std::vector<ViewPair> pairs = graph.ValidEdgePairs();
  for (const ViewPair& pair : pairs) result.num_links += graph.FindEdge(pair.first, pair.second)->matches.size();
  if (!options.enabled) return result;

  const std::vector<LinkEnd> ends = CollectLinkEnds(options, pairs, graph, views_and_intrinsics, features);
  const std::map<std::pair<size_t, size_t>, double> ratios = EdgePairRatios(options, ends);
  const double tolerance = std::log(options.max_inverse_depth_ratio);
  std::vector<std::vector<bool>> dropped(pairs.size());
  ForEachFeature(ends, [&](size_t begin, size_t end) {
    for (size_t p = begin; p < end; ++p) {
      size_t agree = 0, disagree = 0;
      for (size_t q = begin; q < end; ++q) {
        if (ends[q].edge == ends[p].edge) continue;
        const bool ordered = ends[p].edge < ends[q].edge;
        const auto ratio = ratios.find(ordered ? std::make_pair(ends[p].edge, ends[q].edge)
                                               : std::make_pair(ends[q].edge, ends[p].edge));
        if (ratio == ratios.end()) continue;
        const double expected = ordered ? ratio->second : -ratio->second;
        const double allowed = tolerance + ends[p].log_noise + ends[q].log_noise;
        (std::abs(ends[p].log_rho - ends[q].log_rho - expected) <= allowed ? agree : disagree) += 1;
      }
      if (disagree > agree) {
        std::vector<bool>& flags = dropped[ends[p].edge];
        if (flags.empty()) flags.assign(graph.FindEdge(pairs[ends[p].edge].first, pairs[ends[p].edge].second)->matches.size(), false);
        flags[ends[p].match] = true;
      }
    }
  });
  for (size_t edge_index = 0; edge_index < pairs.size(); ++edge_index) {
    if (dropped[edge_index].empty()) continue;
    ViewGraphEdge* edge = result.graph.MutableEdge(pairs[edge_index].first, pairs[edge_index].second);
    std::vector<FeatureMatch> kept;
    for (size_t k = 0; k < edge->matches.size(); ++k) {
      if (dropped[edge_index][k]) {
        ++result.num_dropped_links;
      } else {
        kept.push_back(edge->matches[k]);
      }
    }
    edge->matches = std::move(kept);
  }
  return result;
}

void LinkDepthVoteOptions::Check() const {
  RequireAtLeast(max_inverse_depth_ratio, 1.0, "LinkDepthVoteOptions::max_inverse_depth_ratio");
  RequirePositiveAtMost(far_fraction, 1.0, "LinkDepthVoteOptions::far_fraction");
  RequireAtLeast<size_t>(min_shared_features, 1, "LinkDepthVoteOptions::min_shared_features");
  RequireInRange(angular_noise_deg, 0.0, 10.0, "LinkDepthVoteOptions::angular_noise_deg");
}

}  // namespace sfm_pruning
