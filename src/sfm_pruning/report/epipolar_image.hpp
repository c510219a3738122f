// Drawing an epipolar check (epipolar_check.hpp) as one image: the reference image with the
// point (red dot in a white ring), then every other image with the estimated epipolar curve
// (red), the true one (dashed green, with ground truth) and the point's matched feature (white
// ring). Without an image folder each panel is a dark canvas with the view's observed features,
// which is how synthetic scenes (features without pixels) are shown.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sfm_pruning/report/epipolar_check.hpp"

namespace sfm_pruning {

struct EpipolarImageOptions {
  int panel_height = 320;  // every panel is scaled to this height
  std::optional<std::filesystem::path> images_dir;  // images by RelativeImagePath below it
  std::string title;  // drawn above the panels when not empty

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// Encoded image bytes; `extension` is ".png" or ".jpg". Throws Error naming the file when an
// image of images_dir is missing or does not decode (export/image_files.hpp).
std::vector<uint8_t> RenderEpipolarCheck(const EpipolarCheck& check, const SfmData& model,
                                         const EpipolarImageOptions& options, const std::string& extension);

}  // namespace sfm_pruning
