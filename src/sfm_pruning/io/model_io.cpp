#include "sfm_pruning/io/model_io.hpp"

#include <system_error>

#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/ground_truth_cameras.hpp"
#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace fs = std::filesystem;

std::string ModelFormatName(ModelFormat format) {
  switch (format) {
    case ModelFormat::kColmapModel:
      return "COLMAP model";
    case ModelFormat::kSfmData:
      return "sfm_data";
    case ModelFormat::kGroundTruthCameras:
      return "gt_cameras.txt";
    case ModelFormat::kPly:
      return "PLY";
    case ModelFormat::kOpenMvsScene:
      return "OpenMVS scene";
  }
  return "unknown";
}

ModelFormat DetectModelFormat(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || !fs::exists(status)) throw FileError(path.string(), "no such file or directory");
  if (fs::is_directory(status)) {
    if (fs::exists(path / "cameras.bin") || fs::exists(path / "cameras.txt")) return ModelFormat::kColmapModel;
    throw FileError(path.string(), "directory is not a COLMAP model (no cameras.bin or cameras.txt)");
  }
  const std::string extension = path.extension().string();
  if (extension == ".json" || extension == ".bin") return ModelFormat::kSfmData;
  if (extension == ".txt") return ModelFormat::kGroundTruthCameras;
  if (extension == ".ply") return ModelFormat::kPly;
  if (extension == ".mvs") return ModelFormat::kOpenMvsScene;
  throw FileError(path.string(),
                  "unknown model format (expected a COLMAP model folder, sfm_data.json/.bin, gt_cameras.txt, "
                  ".ply or .mvs)");
}

ModelFormat OutputModelFormat(const fs::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".json" || extension == ".bin") return ModelFormat::kSfmData;
  if (extension == ".ply") return ModelFormat::kPly;
  if (extension == ".txt") return ModelFormat::kGroundTruthCameras;
  if (extension == ".mvs") return ModelFormat::kOpenMvsScene;
  return ModelFormat::kColmapModel;
}

namespace {

SfmData ReadModelOfFormat(const fs::path& path) {
  switch (DetectModelFormat(path)) {
    case ModelFormat::kColmapModel:
      return ReadColmapModel(path);
    case ModelFormat::kSfmData:
      return ReadSfmData(path);
    case ModelFormat::kGroundTruthCameras:
      return ReadGroundTruthCameras(path);
    case ModelFormat::kPly:
      return ReadPlyPoints(path);
    case ModelFormat::kOpenMvsScene: {
      SfmData data = SfmDataFromOpenMvsScene(ReadOpenMvsScene(path), path.string());
      data.root_path = path.parent_path().string();
      return data;
    }
  }
  throw FileError(path.string(), "unknown model format");
}

}  // namespace

SfmData ReadModel(const fs::path& path) {
  SfmData data = ReadModelOfFormat(path);
  ValidateSfmDataValues(data, path.string());  // every format: no NaN or absurd camera goes on
  return data;
}

void WriteModel(const SfmData& data, const fs::path& path, const ModelWriteOptions& options) {
  options.Check();
  switch (OutputModelFormat(path)) {
    case ModelFormat::kColmapModel:
      WriteColmapModel(data, path, options.colmap_text ? ColmapModelFormat::kText : ColmapModelFormat::kBinary);
      return;
    case ModelFormat::kSfmData:
      WriteSfmData(data, path);
      return;
    case ModelFormat::kGroundTruthCameras:
      WriteGroundTruthCameras(data, path);
      return;
    case ModelFormat::kPly:
      WritePly(data, path);
      return;
    case ModelFormat::kOpenMvsScene:
      WriteOpenMvsScene(OpenMvsSceneFromSfmData(data, data.root_path), path);
      return;
  }
}

void ModelWriteOptions::Check() const {}

}  // namespace sfm_pruning
