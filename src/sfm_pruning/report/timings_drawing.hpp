// Per-stage wall times of one or more runs as horizontal bars (one row per stage, one bar per
// run, stages in the order they first appear), with the total per run.
#pragma once

#include <string>
#include <vector>

#include "sfm_pruning/report/palette.hpp"
#include "sfm_pruning/report/run_folder.hpp"

namespace sfm_pruning {

struct TimedRun {
  std::string label;  // e.g. "GLOBAL_PRUNED"
  std::vector<StageSeconds> stages;
};

// Colour of run `index` in the timing bars and the legends of a comparison.
Rgb RunColor(size_t index);

std::string DrawTimingsSvg(const std::vector<TimedRun>& runs, double width = 1000.0);

}  // namespace sfm_pruning
