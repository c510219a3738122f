// Dispatch of sfm_data files by extension; the formats live in openmvg_sfm_data_{json,binary}*.
#include "sfm_pruning/io/openmvg_sfm_data.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "sfm_pruning/io/openmvg_sfm_data_format.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

enum class SfmDataFormat { kJson, kBinary };

SfmDataFormat FormatFromExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".json") return SfmDataFormat::kJson;
  if (ext == ".bin") return SfmDataFormat::kBinary;
  throw FileError(path.string(), "unsupported sfm_data extension '" + path.extension().string() +
                                     "' (expected .json or .bin)");
}

}  // namespace

SfmData ReadSfmData(const std::filesystem::path& path, SfmDataParts parts) {
  const SfmDataFormat format = FormatFromExtension(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path.string(), "file not found");
  const std::string bytes = ReadFileToString(path, /*binary=*/true);
  SfmData data = format == SfmDataFormat::kJson
                     ? openmvg_format::ParseSfmDataJson(bytes, path.string(), parts)
                     : openmvg_format::ParseSfmDataBinary(bytes, path.string(), parts);
  // OpenMVG checks references only when the views are there to be referenced.
  if (HasParts(parts, SfmDataParts::kViews)) {
    ValidateSfmData(data, path.string(), HasParts(parts, SfmDataParts::kIntrinsics));
  } else {
    ValidateSfmDataValues(data, path.string());
  }
  return data;
}

void WriteSfmData(const SfmData& data, const std::filesystem::path& path, SfmDataParts parts) {
  const SfmDataFormat format = FormatFromExtension(path);
  WriteFileAtomically(path, format == SfmDataFormat::kBinary, [&](std::ostream& out) {
    if (format == SfmDataFormat::kJson) {
      openmvg_format::WriteSfmDataJson(data, parts, out);
    } else {
      openmvg_format::WriteSfmDataBinary(data, parts, out, path.string());
    }
  });
}

}  // namespace sfm_pruning
