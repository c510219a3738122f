#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "sfm_pruning/pruning/subgraph_cycle_consistency.hpp"

namespace sfm_pruning {

SubgraphTriangle MeasureSubgraphTriangle(int a, int b, int c, const Similarity3& b_to_a, const Similarity3& c_to_b,
                                         const Similarity3& c_to_a, const SubgraphFrame& frame_a,
                                         const SubgraphFrame& frame_b, const SubgraphFrame& frame_c,
                                         const SubgraphLoopOptions& options) {
  SubgraphTriangle triangle;
  triangle.a = a;
  triangle.b = b;
  triangle.c = c;
  // a -> c -> b -> a: the identity when the three transforms agree.
  const Similarity3 loop = b_to_a.Compose(c_to_b).Compose(c_to_a.Inverse());
  triangle.rotation_deg = RadToDeg(RotationAngleBetween(loop.rotation, Eigen::Matrix3d::Identity()));
  triangle.scale_ratio = loop.scale >= 1.0 ? loop.scale : 1.0 / loop.scale;
  const Eigen::Vector3d centre_b = b_to_a.Apply(frame_b.center);
  const Eigen::Vector3d centre_c = c_to_a.Apply(frame_c.center);
  const double mean_side =
      ((frame_a.center - centre_b).norm() + (frame_a.center - centre_c).norm() + (centre_b - centre_c).norm()) / 3.0;
  const double reference = std::max(mean_side, frame_a.radius);
  const double displacement = (loop.Apply(frame_a.center) - frame_a.center).norm();
  triangle.translation_fraction = reference > 0.0 ? displacement / reference : 0.0;
  triangle.consistent = triangle.rotation_deg <= options.max_rotation_deg &&
                        triangle.scale_ratio <= options.max_scale_ratio &&
                        triangle.translation_fraction <= options.max_translation_fraction;
  return triangle;
}

bool MoreTrustedLink(const SubgraphLink& a, const SubgraphLink& b) {
  if (a.trust != b.trust) return a.trust > b.trust;
  return a.support > b.support;
}

SubgraphLoopResult FindLoopInconsistentLinks(const std::vector<SubgraphLink>& links,
                                             const std::vector<SubgraphFrame>& frames,
                                             const SubgraphLoopOptions& options) {
  SubgraphLoopResult result;
  std::map<std::pair<int, int>, size_t> link_of;  // (k1, k2) -> link
  for (size_t l = 0; l < links.size(); ++l) link_of[{links[l].k1, links[l].k2}] = l;

  // Every triangle once, with the indices of its three links.
  struct Loop {
    size_t ab, bc, ac;
  };
  std::vector<Loop> loops;
  for (const auto& [ab_key, ab] : link_of) {
    const auto [a, b] = ab_key;
    for (auto it = link_of.lower_bound({b, b + 1}); it != link_of.end() && it->first.first == b; ++it) {
      const int c = it->first.second;
      const auto ac = link_of.find({a, c});
      if (ac == link_of.end()) continue;
      const size_t bc = it->second;
      loops.push_back({ab, bc, ac->second});
      result.triangles.push_back(MeasureSubgraphTriangle(
          a, b, c, links[ab].k2_to_k1, links[bc].k2_to_k1, links[ac->second].k2_to_k1,
          frames[static_cast<size_t>(a)], frames[static_cast<size_t>(b)], frames[static_cast<size_t>(c)], options));
    }
  }
  // Triangles per link among the links still active.
  std::vector<bool> active(links.size(), true);
  std::vector<size_t> bad;
  std::vector<size_t> good;
  const auto count_triangles = [&]() {
    bad.assign(links.size(), 0);
    good.assign(links.size(), 0);
    for (size_t t = 0; t < loops.size(); ++t) {
      const Loop& loop = loops[t];
      if (!active[loop.ab] || !active[loop.bc] || !active[loop.ac]) continue;
      std::vector<size_t>& count = result.triangles[t].consistent ? good : bad;
      ++count[loop.ab];
      ++count[loop.bc];
      ++count[loop.ac];
    }
  };
  count_triangles();
  result.consistent_triangles = good;
  result.inconsistent_triangles = bad;
  if (!options.enabled) return result;

  while (true) {
    int best = -1;
    for (size_t l = 0; l < links.size(); ++l) {
      if (!active[l] || bad[l] <= good[l]) continue;
      if (best < 0) {
        best = static_cast<int>(l);
        continue;
      }
      const auto b = static_cast<size_t>(best);
      const long margin = static_cast<long>(bad[l]) - static_cast<long>(good[l]);
      const long best_margin = static_cast<long>(bad[b]) - static_cast<long>(good[b]);
      if (margin > best_margin || (margin == best_margin && !MoreTrustedLink(links[l], links[b]))) {
        best = static_cast<int>(l);
      }
    }
    if (best < 0) break;
    const auto rejected = static_cast<size_t>(best);
    active[rejected] = false;
    result.rejected.push_back({rejected, bad[rejected], good[rejected], -1});
    count_triangles();
  }
  RejectCycleInconsistentLinks(links, frames, options, &active, &result);
  return result;
}

void SubgraphLoopOptions::Check() const {
  RequireAtLeast(min_unverified_trust, 0.0, "SubgraphLoopOptions::min_unverified_trust");
  RequireAtLeast(min_unverified_coverage, 0.0, "SubgraphLoopOptions::min_unverified_coverage");
  RequirePositiveAtMost(max_rotation_deg, 180.0, "SubgraphLoopOptions::max_rotation_deg");
  RequireAtLeast(max_scale_ratio, 1.0, "SubgraphLoopOptions::max_scale_ratio");
  RequirePositiveAtMost(max_translation_fraction, 1e6, "SubgraphLoopOptions::max_translation_fraction");
}

}  // namespace sfm_pruning
