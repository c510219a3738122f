#include "sfm_pruning/pruning/consistency_tests.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>

#include "sfm_pruning/util/statistics.hpp"

namespace sfm_pruning {
namespace {

ErrorSummary Summarize(const std::vector<double>& values) {
  ErrorSummary summary;
  summary.count = values.size();
  summary.max_deg = Max(values);
  summary.median_deg = Median(values);
  return summary;
}

void TestLoops(const ViewGraph& graph, const ConsistencyTestOptions& options, ConsistencyReport* report) {
  const CycleSearchResult search = FindBoundedCycles(graph, options.cycles);
  report->loop_search_truncated = search.truncated;
  std::vector<double> errors;
  errors.reserve(search.cycles.size());
  for (const ViewCycle& cycle : search.cycles) {
    const double error_deg = LoopRotationErrorDeg(graph, cycle);
    const double threshold_deg = LoopRotationThresholdDeg(cycle.size(), options.loop_step_deg);
    errors.push_back(error_deg);
    if (error_deg > threshold_deg) {
      ConsistencyViolation violation;
      violation.test = ConsistencyTest::kLoop;
      violation.loop = cycle;
      violation.value = error_deg;
      violation.threshold = threshold_deg;
      report->violations.push_back(std::move(violation));
    }
  }
  report->loop_error = Summarize(errors);
}

void TestRelativeToAbsolute(const ViewGraph& graph, const SubgraphSolution& solution,
                            const ConsistencyTestOptions& options, ConsistencyReport* report) {
  std::vector<double> rotation_errors;
  std::vector<double> translation_errors;
  std::vector<ConsistencyViolation> translation_violations;
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const auto pose_i = solution.poses.find(pair.first);
    const auto pose_j = solution.poses.find(pair.second);
    if (pose_i == solution.poses.end() || pose_j == solution.poses.end()) {
      ++report->num_unposed_edges;
      return;
    }
    const RelativePose implied = RelativePoseBetween(pose_i->second, pose_j->second);
    if (options.test_relative_rotation) {
      const double e_r = RadToDeg(RotationAngleBetween(edge.relative_pose.rotation, implied.rotation));
      rotation_errors.push_back(e_r);
      if (e_r > options.max_relative_rotation_error_deg) {
        report->violations.push_back({ConsistencyTest::kRelativeRotation, pair, {}, e_r,
                                      options.max_relative_rotation_error_deg});
      }
    }
    if (options.test_relative_translation && edge.relative_pose.translation.norm() > options.min_translation_norm &&
        implied.translation.norm() > options.min_translation_norm) {
      const double e_t = RadToDeg(AngleBetweenVectors(edge.relative_pose.translation, implied.translation));
      translation_errors.push_back(e_t);
      if (e_t > options.max_relative_translation_error_deg) {
        report->violations.push_back({ConsistencyTest::kRelativeTranslation, pair, {}, e_t,
                                      options.max_relative_translation_error_deg});
      }
    }
  });
  report->relative_rotation_error = Summarize(rotation_errors);
  report->relative_translation_error = Summarize(translation_errors);
}

}  // namespace

const char* ConsistencyTestName(ConsistencyTest test) {
  switch (test) {
    case ConsistencyTest::kLoop: return "loop";
    case ConsistencyTest::kRelativeRotation: return "relative_rotation";
    case ConsistencyTest::kRelativeTranslation: return "relative_translation";
    case ConsistencyTest::kBaselineRatio: return "baseline_ratio";
  }
  return "unknown";
}

ConsistencyReport TestSubgraphConsistency(const ViewGraph& graph, const SubgraphSolution& solution,
                                          const ConsistencyTestOptions& options) {
  ConsistencyReport report;
  if (options.test_loops) TestLoops(graph, options, &report);
  if (options.test_relative_rotation || options.test_relative_translation) {
    TestRelativeToAbsolute(graph, solution, options, &report);
  }
  report.consistent = report.violations.empty();
  return report;
}

void TestBaselineRatios(const ViewGraph& graph, const SubgraphSolution& solution, const SfmData& views_and_intrinsics,
                        const FeaturesPerView& features, const ConsistencyTestOptions& options,
                        ConsistencyReport* report) {
  if (!(options.max_baseline_ratio_factor > 0.0)) return;
  for (const BaselineRatioCheck& check :
       MeasureBaselineRatios(graph, solution, views_and_intrinsics, features, options.baseline_ratio)) {
    if (check.Factor() <= options.max_baseline_ratio_factor) continue;
    ConsistencyViolation violation;
    violation.test = ConsistencyTest::kBaselineRatio;
    violation.loop = {check.view_i, check.view_j, check.view_k};
    violation.value = check.Factor();
    violation.threshold = options.max_baseline_ratio_factor;
    report->violations.push_back(std::move(violation));
    report->consistent = false;
  }
}

void ConsistencyTestOptions::Check() const {
  RequirePositiveAtMost(loop_step_deg, 180.0, "ConsistencyTestOptions::loop_step_deg");
  cycles.Check();
  RequirePositiveAtMost(max_relative_rotation_error_deg, 180.0, "ConsistencyTestOptions::max_relative_rotation_error_deg");
  RequirePositiveAtMost(max_relative_translation_error_deg, 180.0,
                        "ConsistencyTestOptions::max_relative_translation_error_deg");
  RequireAtLeast(min_translation_norm, 0.0, "ConsistencyTestOptions::min_translation_norm");
  // 0 switches the baseline-ratio test off; a factor below 1 would reject equal ratios.
  if (max_baseline_ratio_factor != 0.0) {
    RequireAtLeast(max_baseline_ratio_factor, 1.0, "ConsistencyTestOptions::max_baseline_ratio_factor (or 0: off)");
  }
  baseline_ratio.Check();
}

}  // namespace sfm_pruning
