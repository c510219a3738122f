// Tracks (METHOD.md §2.2): the inlier matches of the valid view-graph edges chained into
// multi-view correspondences by union-find over (view id, feature id) nodes.
//
// A track that contains two different features of one view is inconsistent (some match in the
// chain is wrong, and we cannot tell which), so it is discarded whole rather than split.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// One track: view id -> feature id (at most one feature per view by construction).
using Track = std::map<IndexT, IndexT>;

struct TrackBuildingOptions {
  // Tracks seen by fewer views are dropped. 3 in general (a 2-view track carries no information
  // that the edge's relative pose did not already give, and cannot be checked); use 2 for tiny
  // (2-3 view) subgraphs that would otherwise have no tracks at all.
  size_t min_track_length = 3;
  // Speed caps for large scenes; 0 = no cap. Tracks are considered longest first (ties: the
  // smaller track, i.e. the smaller first (view, feature) element). A track is kept while at
  // least one of its views still has fewer than `max_tracks_per_view` kept tracks, so every view
  // keeps its best-supported tracks instead of the dense views taking the whole budget.
  size_t max_tracks_per_view = 0;
  // Stops after this many kept tracks (applied after the per-view rule, same order).
  size_t max_num_tracks = 0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct TrackBuildingResult {
  // Kept tracks, sorted by their smallest (view id, feature id) element: a track's index in this
  // list is a deterministic id.
  std::vector<Track> tracks;
  size_t num_candidate_tracks = 0;    // connected components of the match graph
  size_t num_conflicting_tracks = 0;  // dropped: two features of one view
  size_t num_short_tracks = 0;        // dropped: fewer than min_track_length views
  size_t num_capped_tracks = 0;       // dropped by max_tracks_per_view / max_num_tracks
};

// Builds the tracks of the valid edges of `graph` (FeatureMatch::i in ViewPair::first, j in
// ViewPair::second). Invalid edges contribute nothing. Deterministic.
TrackBuildingResult BuildTracks(const ViewGraph& graph, const TrackBuildingOptions& options = {});

}  // namespace sfm_pruning
