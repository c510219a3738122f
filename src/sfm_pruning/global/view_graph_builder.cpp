#include "sfm_pruning/global/view_graph_builder.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <utility>

#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

// One pair to verify: its putative (or already verified) matches and, when known, its pose.
struct PairJob {
  ViewPair pair;
  const std::vector<FeatureMatch>* matches = nullptr;
  const RelativePose* given_pose = nullptr;
};

struct PairOutcome {
  bool accepted = false;
  std::string reason;
  std::vector<FeatureMatch> inliers;
  RelativePose pose;
  double rotation_std_deg = std::numeric_limits<double>::infinity();  // when verified here
  size_t num_inliers = 0;
};

uint64_t Mix(uint64_t x) {  // splitmix64 finaliser
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Why a view cannot take part, or empty.
std::string ViewProblem(const SfmData& scene, const FeaturesPerView& features, IndexT view_id) {
  const auto view = scene.views.find(view_id);
  if (view == scene.views.end()) return "not in the scene";
  if (scene.intrinsics.count(view->second.id_intrinsic) == 0) return "no intrinsics";
  if (features.count(view_id) == 0) return "no features";
  return {};
}

PairOutcome VerifyPair(const ViewGraphBuildOptions& options, const SfmData& scene, const FeaturesPerView& features,
                       const PairJob& job) {
  PairOutcome outcome;
  for (IndexT id : {job.pair.first, job.pair.second}) {
    const std::string problem = ViewProblem(scene, features, id);
    if (!problem.empty()) {
      outcome.reason = "view " + std::to_string(id) + ": " + problem;
      return outcome;
    }
  }
  const int min_inliers = options.two_view.min_num_inliers;
  if (job.given_pose != nullptr) {
    outcome.num_inliers = job.matches->size();
    if (static_cast<int>(outcome.num_inliers) < min_inliers) {
      outcome.reason = "too few inliers: " + std::to_string(outcome.num_inliers) + " < " + std::to_string(min_inliers);
      return outcome;
    }
    outcome.accepted = true;
    outcome.inliers = *job.matches;
    outcome.pose = *job.given_pose;
    return outcome;
  }
  TwoViewGeometryOptions two_view = options.two_view;
  two_view.relative_pose.ransac.seed = PairSeed(options.seed, job.pair.first, job.pair.second);
  const View& view_i = scene.views.at(job.pair.first);
  const View& view_j = scene.views.at(job.pair.second);
  TwoViewGeometry geometry = EstimateTwoViewGeometry(features.at(job.pair.first), scene.IntrinsicsOf(view_i),
                                                     features.at(job.pair.second), scene.IntrinsicsOf(view_j),
                                                     *job.matches, two_view);
  outcome.num_inliers = static_cast<size_t>(std::max(geometry.num_inliers, 0));
  outcome.accepted = geometry.success;
  outcome.reason = std::move(geometry.reason);
  if (geometry.success) {
    outcome.inliers = std::move(geometry.inlier_matches);
    outcome.pose = geometry.relative_pose;
    outcome.rotation_std_deg = geometry.rotation_std_deg;
  }
  return outcome;
}

// Verifies the jobs on options.num_threads workers; outcomes in job order.
std::vector<PairOutcome> VerifyAll(const ViewGraphBuildOptions& options, const SfmData& scene,
                                   const FeaturesPerView& features, const std::vector<PairJob>& jobs,
                                   const ProgressCallback& progress) {
  std::vector<PairOutcome> outcomes(jobs.size());
  std::atomic<size_t> next{0};
  std::atomic<size_t> done{0};
  std::mutex mutex;  // guards the progress callback and the first error
  std::exception_ptr error;
  const auto work = [&]() {
    for (size_t k = next++; k < jobs.size(); k = next++) {
      try {
        outcomes[k] = VerifyPair(options, scene, features, jobs[k]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        next = jobs.size();
        return;
      }
      const size_t finished = ++done;
      std::lock_guard<std::mutex> lock(mutex);
      ReportProgress(progress, "verifying pairs", finished, jobs.size());
    }
  };
  const size_t num_workers =
      std::min<size_t>(static_cast<size_t>(std::max(options.num_threads, 1)), std::max<size_t>(jobs.size(), 1));
  std::vector<std::thread> workers;
  for (size_t w = 1; w < num_workers; ++w) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (error) std::rethrow_exception(error);
  return outcomes;
}

ViewGraph BuildFromJobs(const ViewGraphBuildOptions& options, const SfmData& scene, const FeaturesPerView& features,
                        const std::vector<PairJob>& jobs, ViewGraphBuildReport* report,
                        const ProgressCallback& progress) {
  ViewGraphBuildReport local;
  ViewGraphBuildReport& out = report != nullptr ? *report : local;
  out = {};
  out.num_pairs = jobs.size();

  ViewGraph graph;
  for (const auto& [view_id, view] : scene.views) graph.AddNode(view_id);
  const std::vector<PairOutcome> outcomes = VerifyAll(options, scene, features, jobs, progress);
  for (size_t k = 0; k < jobs.size(); ++k) {
    const PairOutcome& outcome = outcomes[k];
    if (!outcome.accepted) {
      out.rejected_pairs.push_back({jobs[k].pair, outcome.reason, jobs[k].matches->size(), outcome.num_inliers});
      continue;
    }
    graph.AddEdge(jobs[k].pair.first, jobs[k].pair.second, outcome.inliers, outcome.pose).rotation_std_deg =
        outcome.rotation_std_deg;
    ++out.num_verified_pairs;
  }

  std::map<IndexT, std::string> dropped;
  for (const IndexT view_id : graph.Nodes()) {
    if (!graph.ValidNeighbors(view_id).empty()) continue;
    const std::string problem = ViewProblem(scene, features, view_id);
    dropped[view_id] = problem.empty() ? "no verified pair" : problem;
  }
  if (options.keep_largest_component) {
    const LargestComponentSelection selection = KeepLargestComponent(&graph);
    for (const IndexT view_id : selection.dropped) dropped.emplace(view_id, "outside the largest component");
  }
  for (const auto& [view_id, reason] : dropped) out.dropped_views.push_back({view_id, reason});
  out.num_edges = graph.NumValidEdges();
  return graph;
}

}  // namespace

uint64_t PairSeed(uint64_t base_seed, IndexT a, IndexT b) {
  const uint64_t lo = std::min(a, b);
  const uint64_t hi = std::max(a, b);
  return Mix(Mix(Mix(base_seed) ^ lo) ^ hi);
}

ViewGraph BuildViewGraphFromMatches(const ViewGraphBuildOptions& options, const SfmData& views_and_intrinsics,
                                    const FeaturesPerView& features, const PairwiseMatches& putative,
                                    ViewGraphBuildReport* report, const ProgressCallback& progress) {
  options.Check();
  std::vector<PairJob> jobs;
  jobs.reserve(putative.size());
  for (const auto& [pair, matches] : putative) jobs.push_back({pair, &matches, nullptr});
  return BuildFromJobs(options, views_and_intrinsics, features, jobs, report, progress);
}

ViewGraph BuildViewGraphFromVerifiedPairs(const ViewGraphBuildOptions& options, const SfmData& views_and_intrinsics,
                                          const FeaturesPerView& features, const VerifiedPairs& verified,
                                          ViewGraphBuildReport* report, const ProgressCallback& progress) {
  options.Check();
  std::vector<PairJob> jobs;
  jobs.reserve(verified.size());
  for (const auto& [pair, entry] : verified) {
    jobs.push_back({pair, &entry.inliers, entry.relative_pose ? &*entry.relative_pose : nullptr});
  }
  return BuildFromJobs(options, views_and_intrinsics, features, jobs, report, progress);
}

void ViewGraphBuildOptions::Check() const {
  // seed and num_threads take any value (<= 0 threads: 1).
  two_view.Check();
}

}  // namespace sfm_pruning
