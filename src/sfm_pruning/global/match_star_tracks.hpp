// Match stars: positioning tracks that a wrong match cannot chain together.
//
// Union-find tracks (tracks.hpp) join every match into one component, so a single wrong match
// between two features of different copies of a repeated texture merges two whole tracks: the
// views of one copy then observe the point of the other, and a few such matches move whole runs of
// views by one copy (the synthetic street). A match star
// is one (view, feature) and its direct matches only: a wrong match misplaces one observation of
// one star, so a minority of wrong matches stays a minority in each view, which the positioning's
// robust loss and rejection rounds can outvote.
//
// Measured on the synthetic street's oracle graph (184 true-dominated pairs, a random 20-60 % of
// its 5,473 twin matches kept, two samples each): union-find tracks fold (AUC@10 23.5-50.6), stars
// hold (96.1-97.9); with none 98.4 / 98.5, with all both fold (33.9 / 33.2).
//
// A landmark seen by n views gives up to n stars; identical stars are kept once. The stars only
// drive the positioning solve (which samples a bounded number of tracks per view); the structure
// is still triangulated from the union-find tracks at the solved cameras.
#pragma once

#include <cstddef>
#include <vector>

#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// One star per (view, feature) with a valid match, holding that feature and every feature it is
// matched to; a view matched to it through two different features is left out of the star (one of
// the two matches is wrong and a star cannot tell which). Stars of fewer than min_track_length
// views are dropped, duplicates removed. Sorted (std::map order of Track), so deterministic.
std::vector<Track> BuildMatchStarTracks(const ViewGraph& graph, size_t min_track_length);

}  // namespace sfm_pruning
