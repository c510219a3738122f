// Landmark colours sampled from the images.
#pragma once

#include <filesystem>

#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Sets each landmark's colour to the mean, over its observations, of the image colour at the
// observation (bilinear at the raw pixel position, read from image_root / view path, 8-bit RGB),
// rounded to the nearest integer. Observations outside their image do not count; a landmark
// with none inside keeps its colour. Only images holding observations are read, in parallel
// ("sampling point colours"); the result does not depend on num_threads. Throws Error naming an
// image that is missing or does not decode.
void ColorLandmarksFromImages(SfmData* data, const std::filesystem::path& image_root, int num_threads = 1,
                              const ProgressCallback& progress = {});

}  // namespace sfm_pruning
