// Image file decoding and encoding through OpenCV's imgcodecs, loaded on first use.
//
// Why not link it: libopencv_imgcodecs brings about 120 shared libraries with it (GDAL, Poppler,
// HDF5, libheif, ...), all bound when the process starts (Debian builds them with BIND_NOW). That
// made every prunesfm command 0.07 s slower to start, a tenth of a whole reconstruction of
// templeSparseRing, although most commands never touch an image. The codecs live in a small module
// (image_codecs_module.cpp, libprunesfm_image_codecs.so) that this facade dlopens the first time
// an image is read or written: from its build-tree path, else beside the executable.
//
// The cv::IMREAD_* / cv::IMWRITE_* constants of <opencv2/imgcodecs.hpp> apply as usual (the header
// can be included for them: it needs no linking).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace sfm_pruning {

// OpenCV threw while decoding or encoding; what() is its message.
class ImageCodecError : public std::runtime_error {
 public:
  explicit ImageCodecError(const std::string& message) : std::runtime_error(message) {}
};

// cv::imread: an empty image when the file does not decode. A JPEG or PNG cut short throws
// ImageCodecError saying so (image_file_integrity.hpp), before any codec prints to stderr.
cv::Mat ReadImageFile(const std::filesystem::path& path, int flags);
// cv::imwrite: false when OpenCV cannot write the file (unknown extension, unwritable path).
bool WriteImageFile(const std::filesystem::path& path, const cv::Mat& image, const std::vector<int>& parameters);
// cv::imencode: false when OpenCV cannot encode to `extension` (".png", ".jpg", ...).
bool EncodeImage(const std::string& extension, const cv::Mat& image, const std::vector<int>& parameters,
                 std::vector<unsigned char>* bytes);

}  // namespace sfm_pruning
