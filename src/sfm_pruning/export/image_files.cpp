#include "sfm_pruning/export/image_files.hpp"

#include <string>
#include <system_error>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/image_codecs.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;
namespace {

cv::Mat Decode(const fs::path& path, int flags) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) throw FileError(path.string(), "no such image file");
  cv::Mat image;
  try {
    image = ReadImageFile(path, flags);
  } catch (const ImageCodecError& e) {
    throw FileError(path.string(), "cannot be decoded as an image (" + std::string(e.what()) + ")");
  }
  if (image.empty()) throw FileError(path.string(), "cannot be decoded as an image");
  return image;
}

}  // namespace

cv::Mat ReadImageAsStored(const fs::path& path) { return Decode(path, cv::IMREAD_UNCHANGED); }

cv::Mat ReadColorImage(const fs::path& path) {
  return Decode(path, cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
}

void WriteImage(const fs::path& path, const cv::Mat& image, int jpeg_quality) {
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  if (error) throw FileError(path.parent_path().string(), "cannot create directory: " + error.message());
  const std::vector<int> parameters = {cv::IMWRITE_JPEG_QUALITY, jpeg_quality};
  bool written = false;
  try {
    written = WriteImageFile(path, image, parameters);
  } catch (const ImageCodecError& e) {
    throw FileError(path.string(), "cannot write the image (" + std::string(e.what()) + ")");
  }
  if (!written) throw FileError(path.string(), "cannot write the image (unknown extension or disk full?)");
}

}  // namespace sfm_pruning
