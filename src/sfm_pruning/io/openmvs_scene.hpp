// OpenMVS scene files (.mvs): the binary "interface" archive that OpenMVS' tools (DensifyPointCloud,
// ReconstructMesh, ...) read, as laid out by OpenMVS' libs/MVS/Interface.h (facts in docs/formats.md).
//
// Layout, little endian, no padding: optional header "MVSI" + uint32 version + uint32 reserved
// (absent in version 0 files); then platforms, images, vertices, vertex normals, vertex colours,
// and from version 1 lines, line normals, line colours, from version 2 a 4x4 transform, from
// version 6 an oriented bounding box. Every array is a uint64 count followed by its elements,
// every string a uint64 length followed by its bytes, matrices are row-major float64, 3D points
// of vertices and lines are float32. Fields that only some versions carry are noted below.
//
// OpenMvsScene mirrors the archive field by field, so reading and writing back at the same version
// reproduces the file byte for byte. Conversion to and from SfmData is in openmvs_conversion.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sfm_pruning {

// OpenMVS' NO_ID: an image without pose, a reference to nothing.
inline constexpr uint32_t kOpenMvsNoId = std::numeric_limits<uint32_t>::max();
// The newest archive version this reader understands (OpenMVS 2.3).
inline constexpr uint32_t kOpenMvsNewestVersion = 7;
// What our exporter writes by default: the version of OpenMVG's openMVG2openMVS and of the shared
// sample, which every OpenMVS release since 2017 reads (a reader refuses newer versions than its own).
inline constexpr uint32_t kOpenMvsExportVersion = 3;

struct OpenMvsScene {
  // A camera mounted on a platform. K follows our pixel convention (the centre of the top-left
  // pixel is (0, 0)); with width = height = 0 it is normalized by max(width, height) of the image.
  struct Camera {
    std::string name;
    std::string band_name;  // version >= 4
    uint32_t width = 0;     // version >= 1
    uint32_t height = 0;    // version >= 1
    Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // platform -> camera rotation
    Eigen::Vector3d C = Eigen::Vector3d::Zero();      // camera position in the platform frame
  };
  // A pose of a platform: R world -> platform, C its position in the world (pose.hpp's convention).
  struct PlatformPose {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d C = Eigen::Vector3d::Zero();
  };
  struct Platform {
    std::string name;
    std::vector<Camera> cameras;
    std::vector<PlatformPose> poses;
  };
  // How well another image suits this one for dense matching (version >= 7).
  struct ViewScore {
    uint32_t id = 0;
    uint32_t points = 0;
    float scale = 0, angle = 0, area = 0, score = 0;
  };
  struct Image {
    std::string name;       // image path, relative to the folder of the .mvs file or absolute
    std::string mask_name;  // version >= 5
    uint32_t platform_id = kOpenMvsNoId;
    uint32_t camera_id = kOpenMvsNoId;
    uint32_t pose_id = kOpenMvsNoId;  // kOpenMvsNoId: not posed
    uint32_t id = kOpenMvsNoId;       // version >= 3: the id outside this scene (our view id)
    float min_depth = 0, avg_depth = 0, max_depth = 0;  // version >= 7
    std::vector<ViewScore> view_scores;                 // version >= 7
  };
  struct View {
    uint32_t image_id = 0;  // index into images
    float confidence = 0;   // 0: not available
  };
  struct Vertex {
    Eigen::Vector3f X = Eigen::Vector3f::Zero();
    std::vector<View> views;  // sorted by image_id, as OpenMVS expects
  };
  struct Line {
    Eigen::Vector3f pt1 = Eigen::Vector3f::Zero();
    Eigen::Vector3f pt2 = Eigen::Vector3f::Zero();
    std::vector<View> views;
  };
  // Colours are stored blue, green, red (OpenMVS' Col3 is x = B, y = G, z = R).
  using ColorBgr = std::array<uint8_t, 3>;
  // Oriented bounding box (version >= 6); the default (all zero extent) means "none".
  struct BoundingBox {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d min = Eigen::Vector3d::Zero();
    Eigen::Vector3d max = Eigen::Vector3d::Zero();
  };

  uint32_t version = kOpenMvsExportVersion;
  uint32_t reserved = 0;  // the header's reserved word, kept for byte-identical rewrites
  std::vector<Platform> platforms;
  std::vector<Image> images;
  std::vector<Vertex> vertices;
  std::vector<Eigen::Vector3f> vertex_normals;              // empty or one per vertex
  std::vector<ColorBgr> vertex_colors;                      // empty or one per vertex
  std::vector<Line> lines;                                  // version >= 1
  std::vector<Eigen::Vector3f> line_normals;                // version >= 1
  std::vector<ColorBgr> line_colors;                        // version >= 1
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();  // version >= 2
  BoundingBox bounding_box;                                 // version >= 6
};

// Reads a .mvs file of any version 0..kOpenMvsNewestVersion (version 0 has no header). Throws
// Error naming the file and the problem: missing file, unknown magic, a version newer than 7,
// truncation (with the byte offset and the field being read), counts larger than the file,
// bytes after the scene, and references that resolve to nothing (checked by ValidateOpenMvsScene).
OpenMvsScene ReadOpenMvsScene(const std::filesystem::path& path);

// Writes `scene` at scene.version (0 writes no header), atomically. Throws Error for a version
// newer than kOpenMvsNewestVersion.
void WriteOpenMvsScene(const OpenMvsScene& scene, const std::filesystem::path& path);

// Checks what OpenMVS assumes when it loads a scene: every image names an existing platform and
// camera and, when posed, an existing pose; vertex views name existing images, in increasing
// order; normal and colour arrays are empty or as long as the points they describe. Throws Error
// starting with `source`.
void ValidateOpenMvsScene(const OpenMvsScene& scene, const std::string& source);

}  // namespace sfm_pruning
