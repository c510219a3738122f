// The self-contained HTML page of `prunesfm report`: inline CSS, SVG and a few lines of JS,
// pictures as data URIs, nothing fetched. Sections: summary, view graph before/after pruning,
// top view of cameras and points, epipolar checks, per-stage timings, accepted subgraphs.
// With a second run (--compare) every section shows both runs side by side.
//
// Deterministic: the same runs, options and seed give the same bytes (no dates, seeded layout
// and alignment).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/report/run_folder.hpp"

namespace sfm_pruning {

struct EpipolarRequest {
  std::string image;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

struct HtmlReportInput {
  std::string title;  // defaults to the run folder's name
  std::vector<RunFolder> runs;  // 1 or 2 (the second is the comparison)
  std::optional<SfmData> ground_truth;
  std::string ground_truth_source;
  std::optional<std::filesystem::path> images_dir;
  std::vector<EpipolarRequest> checks;  // empty: num_auto_checks chosen from the first run
  size_t num_auto_checks = 2;
  size_t max_other_views = 3;
  uint64_t seed = 0;  // graph layout and the evaluation's alignment
};

// Throws Error for a check whose image is not registered in the first run, or an image that
// is missing from images_dir or does not decode.
std::string BuildHtmlReport(const HtmlReportInput& input);

}  // namespace sfm_pruning
