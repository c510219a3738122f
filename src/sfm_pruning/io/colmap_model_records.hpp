// A COLMAP sparse model exactly as its files store it (ids, COLMAP pixel convention, qvec/tvec),
// the intermediate between the .bin / .txt codecs and the conversion to SfmData.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sfm_pruning/io/colmap_camera.hpp"

namespace sfm_pruning::colmap_records {

inline constexpr int64_t kNoPoint3D = -1;  // POINT3D_ID of an unmatched point2D

struct Point2D {
  Eigen::Vector2d xy = Eigen::Vector2d::Zero();  // COLMAP pixel convention
  int64_t point3d_id = kNoPoint3D;
};

struct Image {
  Eigen::Vector4d qvec = {1, 0, 0, 0};  // Hamilton, w first, world -> camera
  Eigen::Vector3d tvec = Eigen::Vector3d::Zero();
  uint32_t camera_id = 0;
  std::string name;
  std::vector<Point2D> points2d;
};

struct Point3D {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  std::array<uint8_t, 3> rgb = {0, 0, 0};
  double error = -1.0;
  std::vector<std::pair<uint32_t, uint32_t>> track;  // (image id, point2D index)
};

struct Model {
  std::map<uint32_t, ColmapCamera> cameras;
  std::map<uint32_t, Image> images;
  std::map<uint64_t, Point3D> points3d;
};

// The file names of each encoding, without the directory.
inline const char* CamerasFile(bool binary) { return binary ? "cameras.bin" : "cameras.txt"; }
inline const char* ImagesFile(bool binary) { return binary ? "images.bin" : "images.txt"; }
inline const char* Points3DFile(bool binary) { return binary ? "points3D.bin" : "points3D.txt"; }
inline const char* RigsFile(bool binary) { return binary ? "rigs.bin" : "rigs.txt"; }

// Codecs (colmap_model_binary.cpp, colmap_model_text.cpp). Readers throw Error naming the file.
// The rigs file of COLMAP 4.x models is checked to hold only single-camera rigs (which carry no
// information beyond the images' poses) and otherwise ignored, as is the frames file.
Model ReadBinaryModel(const std::filesystem::path& dir);
void WriteBinaryModel(const Model& model, const std::filesystem::path& dir);
Model ReadTextModel(const std::filesystem::path& dir);
void WriteTextModel(const Model& model, const std::filesystem::path& dir);

}  // namespace sfm_pruning::colmap_records
