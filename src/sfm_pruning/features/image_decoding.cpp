#include "sfm_pruning/features/image_decoding.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/image_codecs.hpp"

namespace sfm_pruning {

DecodedImage DecodeGrayImage(const std::filesystem::path& path) {
  DecodedImage image;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    image.problem = "not a readable file";
    return image;
  }
  if (std::filesystem::file_size(path, ec) == 0) {
    image.problem = "empty file";
    return image;
  }
  try {
    image.pixels = ReadImageFile(path, cv::IMREAD_GRAYSCALE);
  } catch (const ImageCodecError& e) {
    image.problem = "does not decode (" + std::string(e.what()) + ")";
    image.pixels.release();
    return image;
  }
  if (image.pixels.empty()) {
    image.problem = "does not decode as an image";
  } else if (image.pixels.depth() != CV_8U) {
    image.pixels.convertTo(image.pixels, CV_8U);
  }
  return image;
}

}  // namespace sfm_pruning
