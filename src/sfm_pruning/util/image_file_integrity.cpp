#include "sfm_pruning/util/image_file_integrity.hpp"

#include <cstdint>

namespace sfm_pruning {
namespace {

constexpr unsigned char kMarker = 0xFF, kStartOfImage = 0xD8, kEndOfImage = 0xD9, kStartOfScan = 0xDA;
constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";
constexpr size_t kPngSignatureSize = 8;

unsigned char Byte(const std::string& bytes, size_t k) { return static_cast<unsigned char>(bytes[k]); }

bool StartsAsJpeg(const std::string& bytes) {
  return bytes.size() >= 2 && Byte(bytes, 0) == kMarker && Byte(bytes, 1) == kStartOfImage;
}

bool StartsAsPng(const std::string& bytes) { return bytes.compare(0, kPngSignatureSize, kPngSignature) == 0; }

}  // namespace

bool JpegIsComplete(const std::string& bytes) {
  size_t pos = 2;
  // Segments up to the first scan, each skipped by its length.
  while (true) {
    if (pos + 1 >= bytes.size()) return false;
    if (Byte(bytes, pos) != kMarker) {  // stray bytes before a marker: libjpeg skips them with a warning
      ++pos;
      continue;
    }
    const unsigned char marker = Byte(bytes, pos + 1);
    if (marker == kMarker) {  // fill byte
      ++pos;
      continue;
    }
    if (marker == kEndOfImage) return false;                     // an image without a scan
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {  // markers without a length
      pos += 2;
      continue;
    }
    if (pos + 3 >= bytes.size()) return false;
    const size_t length = (static_cast<size_t>(Byte(bytes, pos + 2)) << 8) | Byte(bytes, pos + 3);
    pos += 2 + length;
    if (marker == kStartOfScan) break;
  }
  for (size_t k = pos; k + 1 < bytes.size(); ++k) {
    if (Byte(bytes, k) == kMarker && Byte(bytes, k + 1) == kEndOfImage) return true;
  }
  return false;
}

bool PngIsComplete(const std::string& bytes) {
  size_t pos = kPngSignatureSize;
  while (pos + 8 <= bytes.size()) {
    const uint64_t length = (uint64_t{Byte(bytes, pos)} << 24) | (uint64_t{Byte(bytes, pos + 1)} << 16) |
                            (uint64_t{Byte(bytes, pos + 2)} << 8) | uint64_t{Byte(bytes, pos + 3)};
    const bool end = bytes.compare(pos + 4, 4, "IEND") == 0;
    pos += 8 + length + 4;  // length and type, data, CRC
    if (end) return pos <= bytes.size();
  }
  return false;
}

std::string ImageCutShortProblem(const std::string& bytes) {
  if (StartsAsJpeg(bytes) && !JpegIsComplete(bytes)) return "a JPEG cut short: no end-of-image marker";
  if (StartsAsPng(bytes) && !PngIsComplete(bytes)) return "a PNG cut short: no IEND chunk";
  return {};
}

}  // namespace sfm_pruning
