// Decoding one image file to 8-bit grey levels with OpenCV (EXIF orientation applied), with the
// reason when it fails instead of an exception: an image that does not decode is skipped by the
// caller, never fatal to a run.
#pragma once

#include <filesystem>
#include <string>

#include <opencv2/core/mat.hpp>

namespace sfm_pruning {

struct DecodedImage {
  cv::Mat pixels;       // CV_8UC1; empty on failure
  std::string problem;  // why it failed; empty on success
  bool ok() const { return problem.empty(); }
};

// A JPEG or PNG cut short does not decode (util/image_file_integrity.hpp): libjpeg would give a
// picture whose missing rows are grey.
DecodedImage DecodeGrayImage(const std::filesystem::path& path);

}  // namespace sfm_pruning
