#include "sfm_pruning/global/track_subsampling.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace sfm_pruning {
namespace {

using ViewEntries = std::vector<std::pair<size_t, Eigen::Vector2d>>;  // (track index, pixel)

// The view's tracks by grid cell of its pixel bounding box, each cell ranked longest first
// (ties: smaller track index, since entries come in increasing track order).
std::vector<std::vector<size_t>> TracksByCell(const ViewEntries& entries, const std::vector<SampledTrack>& tracks,
                                              size_t cells) {
  Eigen::Vector2d low = entries.front().second;
  Eigen::Vector2d high = low;
  for (const auto& [track, pixel] : entries) {
    low = low.cwiseMin(pixel);
    high = high.cwiseMax(pixel);
  }
  const Eigen::Vector2d extent = (high - low).cwiseMax(1e-9);
  const auto cell_of = [&](double value, double lower, double size) {
    return std::min(cells - 1, static_cast<size_t>((value - lower) / size * static_cast<double>(cells)));
  };
  std::vector<std::vector<size_t>> by_cell(cells * cells);
  for (const auto& [track, pixel] : entries) {
    by_cell[cell_of(pixel.y(), low.y(), extent.y()) * cells + cell_of(pixel.x(), low.x(), extent.x())].push_back(track);
  }
  for (std::vector<size_t>& cell : by_cell) {
    std::stable_sort(cell.begin(), cell.end(), [&](size_t a, size_t b) {
      return tracks[a].size() > tracks[b].size();
    });
  }
  return by_cell;
}

}  // namespace

std::vector<size_t> SelectWellDistributedTracks(const std::vector<SampledTrack>& tracks,
                                                const TrackSubsamplingOptions& options) {
  std::vector<size_t> all(tracks.size());
  std::iota(all.begin(), all.end(), size_t{0});
  const size_t cap = options.max_tracks_per_view;
  if (cap == 0) return all;
  std::map<IndexT, ViewEntries> per_view;
  for (size_t t = 0; t < tracks.size(); ++t) {
    for (const SampledObservation& observation : tracks[t]) per_view[observation.view_id].emplace_back(t, observation.pixel);
  }
  if (std::none_of(per_view.begin(), per_view.end(), [&](const auto& view) { return view.second.size() > cap; })) {
    return all;
  }

  std::vector<bool> selected(tracks.size(), false);
  std::map<IndexT, size_t> num_selected;  // selected tracks each view observes
  const auto select = [&](size_t track) {
    selected[track] = true;
    for (const SampledObservation& observation : tracks[track]) ++num_selected[observation.view_id];
  };
  const size_t cells = std::max<size_t>(options.grid_cells, 1);
  for (const auto& [view_id, entries] : per_view) {
    const size_t& mine = num_selected[view_id];
    if (mine >= cap) continue;
    const std::vector<std::vector<size_t>> by_cell = TracksByCell(entries, tracks, cells);
    std::vector<size_t> next(by_cell.size(), 0);
    for (bool took_any = true; took_any && mine < cap;) {  // one round robin over the cells
      took_any = false;
      for (size_t c = 0; c < by_cell.size() && mine < cap; ++c) {
        while (next[c] < by_cell[c].size() && selected[by_cell[c][next[c]]]) ++next[c];
        if (next[c] == by_cell[c].size()) continue;
        select(by_cell[c][next[c]++]);
        took_any = true;
      }
    }
  }
  std::vector<size_t> kept;
  for (size_t t = 0; t < tracks.size(); ++t) {
    if (selected[t]) kept.push_back(t);
  }
  return kept;
}

void TrackSubsamplingOptions::Check() const {
  // max_tracks_per_view takes any count (0: every track); an image needs one cell at least.
  RequireAtLeast<size_t>(grid_cells, 1, "TrackSubsamplingOptions::grid_cells");
}

}  // namespace sfm_pruning
