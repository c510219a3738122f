// Whether an image file ends where its format says it ends. libjpeg decodes a JPEG cut short into
// a picture whose missing rows are grey, with only a warning on stderr; libpng prints "libpng
// error: Read Error" before OpenCV returns nothing. Both are caught here first, so the caller can
// say "cut short" in its own one-line message and no codec prints anything.
#pragma once

#include <string>

namespace sfm_pruning {

// Why the bytes of an image file are cut short (empty when they are not, or when the format is
// neither JPEG nor PNG, whose codecs report truncation themselves).
std::string ImageCutShortProblem(const std::string& bytes);

// Whether `bytes`, which start with a JPEG's SOI marker, hold the end-of-image marker after the
// first scan. The segments before the scan are skipped by their lengths, so the end marker of an
// EXIF thumbnail does not count; inside a scan a 0xFF byte is always followed by 0x00 or a restart
// marker, so 0xFF 0xD9 there is the image's end. Bytes after it (camera trailers) are allowed.
bool JpegIsComplete(const std::string& bytes);

// Whether `bytes`, which start with the PNG signature, reach the IEND chunk when walked chunk by
// chunk (length, type, data, CRC). Bytes after IEND are allowed, as libpng allows them.
bool PngIsComplete(const std::string& bytes);

}  // namespace sfm_pruning
