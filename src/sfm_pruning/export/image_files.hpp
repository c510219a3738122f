// Reading and writing image files for export, with one-line errors naming the file.
#pragma once

#include <filesystem>

#include <opencv2/core.hpp>

namespace sfm_pruning {

// The image exactly as stored: its depth and channels, no EXIF rotation (the pixels the model's
// cameras were calibrated on, as COLMAP reads them). Throws Error naming the file when it is
// missing or does not decode.
cv::Mat ReadImageAsStored(const std::filesystem::path& path);

// The image as 8-bit BGR (grey expanded, alpha dropped), no EXIF rotation.
cv::Mat ReadColorImage(const std::filesystem::path& path);

// Writes with the encoder the extension selects, JPEG at `jpeg_quality` (0-100), creating the
// parent folder. Throws Error naming the file on failure.
void WriteImage(const std::filesystem::path& path, const cv::Mat& image, int jpeg_quality);

}  // namespace sfm_pruning
