#include "sfm_pruning/global/global_engine.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <utility>

#include "sfm_pruning/global/bundle_observations.hpp"
#include "sfm_pruning/view_graph/components.hpp"

namespace sfm_pruning {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `stage` and appends its wall time to the report.
template <typename Stage>
void Timed(const std::string& name, GlobalEngineReport* report, Stage&& stage) {
  const Clock::time_point start = Clock::now();
  stage();
  report->timings.push_back({name, SecondsSince(start)});
}

// Unregisters the views that observe fewer than `min_observations` landmarks: their poses are
// erased, their observations removed, and landmarks left with fewer than two observations go.
// Returns the unregistered view ids.
std::vector<IndexT> UnregisterWeakViews(size_t min_observations, SfmData* scene) {
  std::map<IndexT, size_t> counts;
  for (const auto& [landmark_id, landmark] : scene->structure) {
    for (const auto& [view_id, observation] : landmark.observations) ++counts[view_id];
  }
  std::set<IndexT> weak;
  for (const IndexT view_id : scene->PosedViewIds()) {
    if (counts[view_id] < min_observations) weak.insert(view_id);
  }
  if (weak.empty()) return {};
  for (const IndexT view_id : weak) scene->poses.erase(scene->views.at(view_id).id_pose);
  for (auto it = scene->structure.begin(); it != scene->structure.end();) {
    auto& observations = it->second.observations;
    for (const IndexT view_id : weak) observations.erase(view_id);
    it = observations.size() < 2 ? scene->structure.erase(it) : std::next(it);
  }
  return {weak.begin(), weak.end()};
}

// Both positioning methods solve with Ceres under the engine's seed, threads, tolerances and
// progress; their own options keep only what differs (loss, scale bound, rejection rounds).
PositioningSolverOptions WithEngineSolverSettings(const GlobalEngineOptions& options, PositioningSolverOptions solver,
                                                  const ProgressCallback& progress) {
  solver.seed = options.seed;
  solver.num_threads = options.num_threads;
  solver.function_tolerance = options.positioning_function_tolerance;
  solver.max_num_iterations = options.positioning_max_num_iterations;
  solver.max_num_resolve_iterations = options.positioning_max_num_resolve_iterations;
  solver.num_random_starts = options.positioning_random_starts;
  solver.start_screening_iterations = options.positioning_start_screening_iterations;
  solver.progress = progress;
  return solver;
}

bool Fail(const std::string& message, GlobalEngineReport* report) {
  report->success = false;
  report->message = message;
  return false;
}

// 1. Rotation averaging: `rotations` of the views it keeps, `kept` = the graph among them.
bool AverageRotations(const GlobalEngineOptions& options, const ViewGraph& graph, GlobalEngineReport* report,
                      std::map<IndexT, std::string>* dropped, std::map<IndexT, Eigen::Matrix3d>* rotations,
                      ViewGraph* kept, const ProgressCallback& progress) {
  ViewGraph work = graph;
  Timed("rotation averaging", report, [&]() {
    report->rotation = EstimateGlobalRotations(&work, options.rotation, rotations, progress);
  });
  if (!report->rotation.success) return Fail("rotation averaging: " + report->rotation.failure_reason, report);
  const NodeGroup initial_component = LargestComponent(graph);
  const std::set<IndexT> initial(initial_component.begin(), initial_component.end());
  for (const IndexT view_id : report->rotation.dropped_views) {
    dropped->emplace(view_id, initial.count(view_id) > 0 ? "cut off by the rotation filter"
                                                         : "outside the largest component");
  }
  report->num_filtered_edges = report->rotation.filtered_edges.size();
  const std::set<IndexT> estimated(report->rotation.estimated_views.begin(), report->rotation.estimated_views.end());
  *kept = work.InducedSubgraph(estimated);
  report->num_rotation_edges = kept->NumValidEdges();
  return true;
}

// 2. Tracks of `kept` (min length 3; 2 for graphs of at most 3 views), from the links the depth
// votes keep (link_depth_votes.hpp).
bool BuildEngineTracks(const GlobalEngineOptions& options, const ViewGraph& kept, const SfmData& views_and_intrinsics,
                       const FeaturesPerView& features, size_t num_views, GlobalEngineReport* report,
                       TrackBuildingOptions* track_options, TrackBuildingResult* tracks) {
  *track_options = options.tracks;
  if (num_views <= 3) track_options->min_track_length = std::min<size_t>(track_options->min_track_length, 2);
  Timed("tracks", report, [&]() {
    if (!options.link_depth_votes.enabled) {
      *tracks = BuildTracks(kept, *track_options);
      return;
    }
    const LinkDepthVoteResult votes =
        DropDepthInconsistentLinks(options.link_depth_votes, kept, views_and_intrinsics, features);
    report->num_depth_inconsistent_links = votes.num_dropped_links;
    *tracks = BuildTracks(votes.graph, *track_options);
  });
  report->num_tracks = tracks->tracks.size();
  report->track_counts = *tracks;
  report->track_counts.tracks.clear();
  return !tracks->tracks.empty() || Fail("no track of the required length", report);
}

// 3. Positioning.
bool PositionViews(const GlobalEngineOptions& options, const ViewGraph& kept,
                   const std::map<IndexT, Eigen::Matrix3d>& rotations, const std::vector<Track>& tracks,
                   size_t min_track_length, const FeaturesPerView& features, SfmData* out, GlobalEngineReport* report,
                   const ProgressCallback& progress) {
  Timed("positioning", report, [&]() {
    if (options.positioning == PositioningMethod::kGlobalPositioning) {
      GlobalPositioningOptions positioning = options.global_positioning;
      positioning.solver = WithEngineSolverSettings(options, positioning.solver, progress);
      const bool on_stars = options.positioning_tracks == PositioningTracks::kMatchStars;
      const std::vector<Track> stars =
          on_stars ? BuildMatchStarTracks(kept, min_track_length) : std::vector<Track>{};
      report->positioning =
          PositionCamerasAndPoints(positioning, rotations, tracks, features, out, on_stars ? &stars : nullptr);
    } else {
      TranslationAveragingOptions averaging = options.translation_averaging;
      averaging.solver = WithEngineSolverSettings(options, averaging.solver, progress);
      report->positioning =
          PositionCamerasByTranslationAveraging(averaging, kept, rotations, tracks, features, out).positioning;
    }
  });
  return report->positioning.success || Fail("positioning: " + report->positioning.message, report);
}

// 4a. The rounds of adjust -> filter -> retriangulate, then the last adjust -> filter, with `bundle`.
bool RunBundleSchedule(const GlobalEngineOptions& options, const BundleAdjustmentOptions& bundle, SfmData* out,
                       GlobalEngineReport* report, const ProgressCallback& progress) {
  const size_t num_adjustments = static_cast<size_t>(std::max(options.num_bundle_rounds, 0)) + 1;
  for (size_t round = 0; round < num_adjustments; ++round) {
    ReportProgress(progress, "bundle adjustment", round, num_adjustments);
    BundleAdjustmentOptions round_options = bundle;
    const bool is_last = round + 1 == num_adjustments;
    round_options.function_tolerance =
        is_last ? options.final_function_tolerance : options.intermediate_function_tolerance;
    if (!is_last) {
      round_options.max_num_iterations =
          std::min(round_options.max_num_iterations, options.intermediate_max_num_iterations);
    }
    report->bundle_adjustments.push_back(
        round == 0 ? AdjustBundleOnSubset(round_options, options.first_bundle_subsampling, options.retriangulation, out)
                   : AdjustBundle(round_options, out));
    if (!report->bundle_adjustments.back().success) return false;
    const StructureFilteringResult filtered = FilterStructure(options.filtering, out);
    if (round + 1 < num_adjustments) RetriangulateLandmarks(options.retriangulation, &filtered.removed, out);
  }
  ReportProgress(progress, "bundle adjustment", num_adjustments, num_adjustments);
  return true;
}

// 4. Bundle adjustment; then the weak views go. With the distortion evidence test, the schedule
// runs with the distortion held; when one more adjustment with it free pays BIC's price, the data
// determine it, and the schedule runs again from the positioned model with it free throughout
// (a distortion estimated from the start, as without the test, so the filter judges the
// observations with it).
bool AdjustAndFilter(const GlobalEngineOptions& options, SfmData* out, GlobalEngineReport* report,
                     std::map<IndexT, std::string>* dropped, const ProgressCallback& progress) {
  BundleAdjustmentOptions bundle = options.bundle;
  bundle.num_threads = options.num_threads;
  const bool test_distortion = options.distortion_needs_evidence && bundle.refine_distortion;
  bool adjusted = true;
  Timed("bundle adjustment", report, [&]() {
    if (!test_distortion) {
      adjusted = RunBundleSchedule(options, bundle, out, report, progress);
      return;
    }
    const SfmData positioned = *out;
    BundleAdjustmentOptions held = bundle;
    held.refine_distortion = false;
    adjusted = RunBundleSchedule(options, held, out, report, progress);
    if (!adjusted) return;
    BundleAdjustmentOptions free = bundle;
    free.function_tolerance = options.final_function_tolerance;
    report->distortion = SelectDistortionByEvidence(free, out);
    if (report->distortion.kept) {
      *out = positioned;
      adjusted = RunBundleSchedule(options, bundle, out, report, progress);
    }
  });
  if (!adjusted) return Fail("bundle adjustment: " + report->bundle_adjustments.back().message, report);
  report->final_rms_px = report->bundle_adjustments.back().final_rms_px;

  for (const IndexT view_id : UnregisterWeakViews(options.min_observations_per_view, out)) {
    dropped->emplace(view_id, "too few observations after filtering");
  }
  SetLandmarkReprojectionErrors(out);  // each point's ERROR in the COLMAP model
  return true;
}

// RunGlobalEngine's stages after the graph copy; false (with report->message) on failure.
bool RunStages(const GlobalEngineOptions& options, const ViewGraph& graph, const FeaturesPerView& features,
               SfmData* out, GlobalEngineReport* report, std::map<IndexT, std::string>* dropped,
               const ProgressCallback& progress) {
  std::map<IndexT, Eigen::Matrix3d> rotations;
  ViewGraph kept;
  if (!AverageRotations(options, graph, report, dropped, &rotations, &kept, progress)) return false;
  TrackBuildingOptions track_options;
  TrackBuildingResult tracks;
  if (!BuildEngineTracks(options, kept, *out, features, rotations.size(), report, &track_options, &tracks)) {
    return false;
  }
  if (!PositionViews(options, kept, rotations, tracks.tracks, track_options.min_track_length, features, out, report,
                     progress)) {
    return false;
  }
  for (const auto& [view_id, rotation] : rotations) {
    if (!out->IsPosed(view_id)) dropped->emplace(view_id, "not positioned (no usable track)");
  }
  return !options.bundle_adjust || AdjustAndFilter(options, out, report, dropped, progress);
}

// RefineGlobalModel's stages: the views `initial` poses keep those poses; the tracks of the graph
// among them are triangulated from them (the positioning's angular filter), then adjusted.
bool RunRefinementStages(const GlobalEngineOptions& options, const ViewGraph& graph, const SfmData& initial,
                         const FeaturesPerView& features, SfmData* out, GlobalEngineReport* report,
                         std::map<IndexT, std::string>* dropped, const ProgressCallback& progress) {
  std::map<IndexT, Eigen::Matrix3d> rotations;
  std::map<IndexT, Eigen::Vector3d> centers;
  std::set<IndexT> posed;
  for (const IndexT view_id : initial.PosedViewIds()) {
    const Pose& pose = initial.PoseOf(initial.views.at(view_id));
    rotations[view_id] = pose.rotation;
    centers[view_id] = pose.center;
    posed.insert(view_id);
  }
  for (const IndexT view_id : graph.Nodes()) {
    if (posed.count(view_id) == 0) dropped->emplace(view_id, "not posed by the model refined");
  }
  const ViewGraph kept = graph.InducedSubgraph(posed);
  report->num_rotation_edges = kept.NumValidEdges();
  TrackBuildingOptions track_options;
  TrackBuildingResult tracks;
  if (!BuildEngineTracks(options, kept, initial, features, posed.size(), report, &track_options, &tracks)) {
    return false;
  }
  Timed("triangulation from the poses", report, [&]() {
    report->positioning =
        TriangulateFromPoses(options.global_positioning, rotations, centers, tracks.tracks, features, out);
  });
  if (!report->positioning.success) return Fail("triangulation: " + report->positioning.message, report);
  return !options.bundle_adjust || AdjustAndFilter(options, out, report, dropped, progress);
}

// RunGlobalEngine and RefineGlobalModel around their stages: the output reset to the views and
// intrinsics of `base`, the counts of the report, and on failure an output without poses.
template <typename Stages>
void RunEngine(const ViewGraph& graph, const SfmData& base, SfmData* out, GlobalEngineReport* report,
               Stages&& stages) {
  GlobalEngineReport local;
  if (report == nullptr) report = &local;
  *report = {};
  const Clock::time_point start = Clock::now();
  *out = base;
  out->poses.clear();
  out->structure.clear();
  report->num_input_views = graph.NumNodes();
  report->num_input_edges = graph.NumValidEdges();

  std::map<IndexT, std::string> dropped;
  if (report->num_input_edges == 0) {
    Fail("the view graph has no edges", report);
  } else if (stages(report, &dropped)) {
    report->success = true;
  } else {
    out->poses.clear();
    out->structure.clear();
  }
  for (const auto& [view_id, reason] : dropped) report->dropped_views.push_back({view_id, reason});
  report->num_registered_views = out->PosedViewIds().size();
  report->num_landmarks = out->structure.size();
  for (const auto& [landmark_id, landmark] : out->structure) report->num_observations += landmark.observations.size();
  report->total_seconds = SecondsSince(start);
}

}  // namespace

GlobalEngineOptions WithFocalSearchSchedule(GlobalEngineOptions options, const FocalSearchSchedule& schedule) {
  options.num_bundle_rounds = 0;
  options.first_bundle_subsampling.max_tracks_per_view = schedule.max_tracks_per_view;
  options.bundle.max_num_iterations = schedule.max_num_iterations;
  return options;
}

void RunGlobalEngine(const GlobalEngineOptions& options, const ViewGraph& graph, const SfmData& views_and_intrinsics,
                     const FeaturesPerView& features, SfmData* out, GlobalEngineReport* report,
                     const ProgressCallback& progress) {
  options.Check();
  RunEngine(graph, views_and_intrinsics, out, report, [&](GlobalEngineReport* r, std::map<IndexT, std::string>* d) {
    return RunStages(options, graph, features, out, r, d, progress);
  });
}

void RefineGlobalModel(const GlobalEngineOptions& options, const ViewGraph& graph, const SfmData& initial,
                       const FeaturesPerView& features, SfmData* out, GlobalEngineReport* report,
                       const ProgressCallback& progress) {
  options.Check();
  RunEngine(graph, initial, out, report, [&](GlobalEngineReport* r, std::map<IndexT, std::string>* d) {
    return RunRefinementStages(options, graph, initial, features, out, r, d, progress);
  });
}

void GlobalEngineOptions::Check() const {
  rotation.Check();
  tracks.Check();
  link_depth_votes.Check();
  global_positioning.Check();
  translation_averaging.Check();
  bundle.Check();
  filtering.Check();
  retriangulation.Check();
  RequireAtLeast(num_bundle_rounds, 0, "GlobalEngineOptions::num_bundle_rounds");
  first_bundle_subsampling.Check();
  // The overrides of the solvers' own settings, with the same bounds as those.
  RequireAtLeast(positioning_function_tolerance, 0.0, "GlobalEngineOptions::positioning_function_tolerance");
  RequireAtLeast(positioning_max_num_iterations, 0, "GlobalEngineOptions::positioning_max_num_iterations");
  RequireAtLeast(positioning_max_num_resolve_iterations, 0,
                 "GlobalEngineOptions::positioning_max_num_resolve_iterations");
  RequireAtLeast(positioning_random_starts, 1, "GlobalEngineOptions::positioning_random_starts");
  RequireAtLeast(positioning_start_screening_iterations, 0,
                 "GlobalEngineOptions::positioning_start_screening_iterations");
  RequireAtLeast(intermediate_function_tolerance, 0.0,
                 "GlobalEngineOptions::intermediate_function_tolerance");
  RequireAtLeast(final_function_tolerance, 0.0, "GlobalEngineOptions::final_function_tolerance");
  RequireAtLeast(intermediate_max_num_iterations, 0, "GlobalEngineOptions::intermediate_max_num_iterations");
  // min_observations_per_view and seed take any value.
  RequireAtLeast(num_threads, 1, "GlobalEngineOptions::num_threads");
}

}  // namespace sfm_pruning
