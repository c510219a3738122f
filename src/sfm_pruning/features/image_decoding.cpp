#include "sfm_pruning/features/image_decoding.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/image_codecs.hpp"

namespace sfm_pruning {

namespace {

constexpr unsigned char kMarker = 0xFF, kStartOfImage = 0xD8, kEndOfImage = 0xD9, kStartOfScan = 0xDA;

bool StartsAsJpeg(const std::string& bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == kMarker &&
         static_cast<unsigned char>(bytes[1]) == kStartOfImage;
}

}  // namespace

bool JpegIsComplete(const std::string& bytes) {
  const auto at = [&](size_t k) { return static_cast<unsigned char>(bytes[k]); };
  size_t pos = 2;
  // Segments up to the first scan, each skipped by its length.
  while (true) {
    if (pos + 1 >= bytes.size()) return false;
    if (at(pos) != kMarker) {  // stray bytes before a marker: libjpeg skips them with a warning
      ++pos;
      continue;
    }
    const unsigned char marker = at(pos + 1);
    if (marker == kMarker) {  // fill byte
      ++pos;
      continue;
    }
    if (marker == kEndOfImage) return false;  // an image without a scan
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {  // markers without a length
      pos += 2;
      continue;
    }
    if (pos + 3 >= bytes.size()) return false;
    const size_t length = (static_cast<size_t>(at(pos + 2)) << 8) | at(pos + 3);
    pos += 2 + length;
    if (marker == kStartOfScan) break;
  }
  for (size_t k = pos; k + 1 < bytes.size(); ++k) {
    if (at(k) == kMarker && at(k + 1) == kEndOfImage) return true;
  }
  return false;
}

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
    const std::string bytes = ReadFileToString(path);
    if (StartsAsJpeg(bytes) && !JpegIsComplete(bytes)) {
      image.problem = "does not decode (a JPEG cut short: no end-of-image marker)";
      return image;
    }
  } catch (const Error&) {
    image.problem = "not a readable file";
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
