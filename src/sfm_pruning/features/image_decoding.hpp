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

// A JPEG file (it starts with the SOI marker) must also end its image: libjpeg decodes a file cut
// short into a picture whose missing rows are grey, with only a warning on stderr.
DecodedImage DecodeGrayImage(const std::filesystem::path& path);

// Whether `bytes`, which start with a JPEG's SOI marker, hold the end-of-image marker after the
// first scan. The segments before the scan are skipped by their lengths, so the end marker of an
// EXIF thumbnail does not count; inside a scan a 0xFF byte is always followed by 0x00 or a restart
// marker, so 0xFF 0xD9 there is the image's end. Bytes after it (camera trailers) are allowed.
bool JpegIsComplete(const std::string& bytes);

}  // namespace sfm_pruning
