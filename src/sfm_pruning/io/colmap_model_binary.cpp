// COLMAP's binary sparse model: cameras.bin, images.bin, points3D.bin (layouts in FORMATS.md).
#include <string>

#include "sfm_pruning/io/colmap_binary.hpp"
#include "sfm_pruning/io/colmap_model_records.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::colmap_records {
namespace fs = std::filesystem;
using colmap_binary::Reader;
using colmap_binary::Write;

namespace {

Error Duplicate(const fs::path& path, const char* what, uint64_t id) {
  return FileError(path.string(), std::string("duplicate ") + what + " id " + std::to_string(id));
}

void ReadCameras(const fs::path& path, Model* model) {
  const std::string bytes = ReadFileToString(path);
  Reader in(bytes, path.string());
  const uint64_t count = in.Read<uint64_t>();
  in.RequireRecords(count, 24);
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t id = in.Read<uint32_t>();
    ColmapCamera camera;
    camera.model_id = in.Read<int32_t>();
    camera.width = in.Read<uint64_t>();
    camera.height = in.Read<uint64_t>();
    const size_t num_params = ColmapCameraNumParams(camera.model_id);
    // The record size depends on the model, so an unknown model cannot be skipped.
    if (num_params == 0) {
      throw FileError(path.string(),
                      "camera model " + ColmapCameraModelName(camera.model_id) + " is not supported");
    }
    for (size_t k = 0; k < num_params; ++k) camera.params.push_back(in.Read<double>());
    if (!model->cameras.emplace(id, camera).second) throw Duplicate(path, "camera", id);
  }
  if (!in.AtEnd()) throw FileError(path.string(), "unexpected bytes after the last camera");
}

void ReadImages(const fs::path& path, Model* model) {
  const std::string bytes = ReadFileToString(path);
  Reader in(bytes, path.string());
  const uint64_t count = in.Read<uint64_t>();
  in.RequireRecords(count, 73);
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t id = in.Read<uint32_t>();
    Image image;
    for (int k = 0; k < 4; ++k) image.qvec[k] = in.Read<double>();
    for (int k = 0; k < 3; ++k) image.tvec[k] = in.Read<double>();
    image.camera_id = in.Read<uint32_t>();
    image.name = in.ReadString();
    const uint64_t num_points = in.Read<uint64_t>();
    in.RequireRecords(num_points, 24);
    image.points2d.resize(num_points);
    for (Point2D& point : image.points2d) {
      point.xy.x() = in.Read<double>();
      point.xy.y() = in.Read<double>();
      point.point3d_id = in.Read<int64_t>();
    }
    if (!model->images.emplace(id, std::move(image)).second) throw Duplicate(path, "image", id);
  }
  if (!in.AtEnd()) throw FileError(path.string(), "unexpected bytes after the last image");
}

void ReadPoints3D(const fs::path& path, Model* model) {
  const std::string bytes = ReadFileToString(path);
  Reader in(bytes, path.string());
  const uint64_t count = in.Read<uint64_t>();
  in.RequireRecords(count, 43);
  for (uint64_t i = 0; i < count; ++i) {
    const uint64_t id = in.Read<uint64_t>();
    Point3D point;
    for (int k = 0; k < 3; ++k) point.xyz[k] = in.Read<double>();
    for (int k = 0; k < 3; ++k) point.rgb[k] = in.Read<uint8_t>();
    point.error = in.Read<double>();
    const uint64_t track_length = in.Read<uint64_t>();
    in.RequireRecords(track_length, 8);
    point.track.resize(track_length);
    for (auto& element : point.track) {
      element.first = in.Read<uint32_t>();
      element.second = in.Read<uint32_t>();
    }
    if (!model->points3d.emplace(id, std::move(point)).second) throw Duplicate(path, "point3D", id);
  }
  if (!in.AtEnd()) throw FileError(path.string(), "unexpected bytes after the last point");
}

// rigs.bin: uint64 count, then per rig uint32 rig id, uint32 sensor count, the reference sensor
// (int32 type, uint32 id) and, for multi-sensor rigs, further sensors we do not read.
void CheckSingleCameraRigs(const fs::path& path) {
  if (!fs::exists(path)) return;
  const std::string bytes = ReadFileToString(path);
  Reader in(bytes, path.string());
  const uint64_t count = in.Read<uint64_t>();
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t rig_id = in.Read<uint32_t>();
    const uint32_t num_sensors = in.Read<uint32_t>();
    if (num_sensors != 1) {
      throw FileError(path.string(), "rig " + std::to_string(rig_id) + " has " + std::to_string(num_sensors) +
                                         " sensors; only single-camera rigs are supported");
    }
    in.Read<int32_t>();
    in.Read<uint32_t>();
  }
}

}  // namespace

Model ReadBinaryModel(const fs::path& dir) {
  Model model;
  ReadCameras(dir / CamerasFile(true), &model);
  ReadImages(dir / ImagesFile(true), &model);
  ReadPoints3D(dir / Points3DFile(true), &model);
  CheckSingleCameraRigs(dir / RigsFile(true));
  return model;
}

void WriteBinaryModel(const Model& model, const fs::path& dir) {
  WriteFileAtomically(dir / CamerasFile(true), true, [&](std::ostream& out) {
    Write<uint64_t>(out, model.cameras.size());
    for (const auto& [id, camera] : model.cameras) {
      Write<uint32_t>(out, id);
      Write<int32_t>(out, camera.model_id);
      Write<uint64_t>(out, camera.width);
      Write<uint64_t>(out, camera.height);
      for (double p : camera.params) Write<double>(out, p);
    }
  });
  WriteFileAtomically(dir / ImagesFile(true), true, [&](std::ostream& out) {
    Write<uint64_t>(out, model.images.size());
    for (const auto& [id, image] : model.images) {
      Write<uint32_t>(out, id);
      for (int k = 0; k < 4; ++k) Write<double>(out, image.qvec[k]);
      for (int k = 0; k < 3; ++k) Write<double>(out, image.tvec[k]);
      Write<uint32_t>(out, image.camera_id);
      colmap_binary::WriteString(out, image.name);
      Write<uint64_t>(out, image.points2d.size());
      for (const Point2D& point : image.points2d) {
        Write<double>(out, point.xy.x());
        Write<double>(out, point.xy.y());
        Write<int64_t>(out, point.point3d_id);
      }
    }
  });
  WriteFileAtomically(dir / Points3DFile(true), true, [&](std::ostream& out) {
    Write<uint64_t>(out, model.points3d.size());
    for (const auto& [id, point] : model.points3d) {
      Write<uint64_t>(out, id);
      for (int k = 0; k < 3; ++k) Write<double>(out, point.xyz[k]);
      for (int k = 0; k < 3; ++k) Write<uint8_t>(out, point.rgb[k]);
      Write<double>(out, point.error);
      Write<uint64_t>(out, point.track.size());
      for (const auto& [image_id, point2d_idx] : point.track) {
        Write<uint32_t>(out, image_id);
        Write<uint32_t>(out, point2d_idx);
      }
    }
  });
}

}  // namespace sfm_pruning::colmap_records
