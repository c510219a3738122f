#include "sfm_pruning/io/openmvs_scene.hpp"

#include <cstring>
#include <ostream>
#include <type_traits>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

constexpr char kMagic[4] = {'M', 'V', 'S', 'I'};
// The archive is described once, by the Serialize functions below, and run by two archives with
// the same interface: ArchiveReader fills the scene, ArchiveWriter emits it.
//   Value(field)                      a scalar, string, matrix or point
//   Array(vector, min_bytes, label, element)   uint64 count + elements; `label` (or nullptr for a
//                                     nested array) names the element in error messages
//   Label(name)                       names what follows in error messages

// Reads the archive front to back; every failure names the byte offset and the element being read.
class ArchiveReader {
 public:
  ArchiveReader(const std::string& bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  template <typename T>
  void Value(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    Require(sizeof(T));
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
  }
  void Value(std::string& value) {
    uint64_t length = 0;
    Value(length);
    Require(length);
    value = bytes_.substr(offset_, length);
    offset_ += length;
  }
  void Value(Eigen::Matrix3d& m) { m = ReadRowMajor<3>(); }
  void Value(Eigen::Matrix4d& m) { m = ReadRowMajor<4>(); }
  void Value(Eigen::Vector3d& v) { ReadCoefficients(v.data(), 3); }
  void Value(Eigen::Vector3f& v) { ReadCoefficients(v.data(), 3); }

  template <typename T, typename Element>
  void Array(std::vector<T>& values, size_t min_element_bytes, const char* label, const Element& element) {
    if (label != nullptr) Label(label);
    values.resize(ReadCount(min_element_bytes));
    for (size_t i = 0; i < values.size(); ++i) {
      if (label != nullptr) Label(label, i);
      element(values[i]);
    }
  }

  // Names the part being read, for error messages: "vertices[17]", "transform".
  void Label(const char* section, uint64_t index = kNoIndex) {
    section_ = section;
    index_ = index;
  }
  size_t offset() const { return offset_; }
  size_t Remaining() const { return bytes_.size() - offset_; }

 private:
  // An array length, checked against the bytes left so that the caller may allocate it: a
  // corrupt count must give an Error, not a bad_alloc.
  uint64_t ReadCount(size_t min_element_bytes) {
    const size_t count_offset = offset_;
    uint64_t count = 0;
    Value(count);
    if (count > Remaining() / min_element_bytes) {
      throw FileError(source_, "corrupt or truncated: " + Where() + " has a count of " +
                                   std::to_string(count) + " at byte " + std::to_string(count_offset) +
                                   ", more than the " + std::to_string(Remaining()) + " bytes left can hold");
    }
    return count;
  }
  template <typename Scalar>
  void ReadCoefficients(Scalar* data, int n) {
    for (int k = 0; k < n; ++k) Value(data[k]);
  }
  template <int N>
  Eigen::Matrix<double, N, N> ReadRowMajor() {
    Eigen::Matrix<double, N, N, Eigen::RowMajor> m;
    ReadCoefficients(m.data(), N * N);
    return m;
  }
  std::string Where() const {
    return index_ == kNoIndex ? std::string(section_)
                              : std::string(section_) + "[" + std::to_string(index_) + "]";
  }
  void Require(uint64_t n) const {
    if (Remaining() < n) {
      throw FileError(source_, "truncated: " + Where() + " needs " + std::to_string(n) + " bytes at byte " +
                                   std::to_string(offset_) + " but the file ends at " +
                                   std::to_string(bytes_.size()));
    }
  }

  static constexpr uint64_t kNoIndex = ~uint64_t{0};
  const std::string& bytes_;
  std::string source_;
  size_t offset_ = 0;
  const char* section_ = "header";
  uint64_t index_ = kNoIndex;
};

class ArchiveWriter {
 public:
  explicit ArchiveWriter(std::ostream& out) : out_(out) {}

  template <typename T>
  void Value(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.write(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void Value(const std::string& value) {
    Value(static_cast<uint64_t>(value.size()));
    out_.write(value.data(), static_cast<std::streamsize>(value.size()));
  }
  void Value(const Eigen::Matrix3d& m) { WriteRowMajor<3>(m); }
  void Value(const Eigen::Matrix4d& m) { WriteRowMajor<4>(m); }
  void Value(const Eigen::Vector3d& v) { WriteCoefficients(v.data(), 3); }
  void Value(const Eigen::Vector3f& v) { WriteCoefficients(v.data(), 3); }

  template <typename T, typename Element>
  void Array(const std::vector<T>& values, size_t /*min_element_bytes*/, const char* /*label*/,
             const Element& element) {
    Value(static_cast<uint64_t>(values.size()));
    for (const T& value : values) element(value);
  }
  void Label(const char* /*section*/) {}

 private:
  template <typename Scalar>
  void WriteCoefficients(const Scalar* data, int n) {
    for (int k = 0; k < n; ++k) Value(data[k]);
  }
  template <int N>
  void WriteRowMajor(const Eigen::Matrix<double, N, N>& m) {
    const Eigen::Matrix<double, N, N, Eigen::RowMajor> row_major = m;
    WriteCoefficients(row_major.data(), N * N);
  }

  std::ostream& out_;
};

// Smallest encoded size of the array elements (the reader's guard against corrupt counts).
constexpr size_t kMinPlatformBytes = 8 + 8 + 8;
constexpr size_t kMinCameraBytes = 8 + 9 * 8 + 9 * 8 + 3 * 8;
constexpr size_t kPoseBytes = 9 * 8 + 3 * 8;
constexpr size_t kMinImageBytes = 8 + 3 * 4;
constexpr size_t kViewScoreBytes = 2 * 4 + 4 * 4;
constexpr size_t kViewBytes = 4 + 4;
constexpr size_t kMinVertexBytes = 3 * 4 + 8;
constexpr size_t kMinLineBytes = 6 * 4 + 8;
constexpr size_t kNormalBytes = 3 * 4;
constexpr size_t kColorBytes = 3;

// The field lists: `Scene` is OpenMvsScene (reading) or const OpenMvsScene (writing), and the
// element types follow its constness through the `auto&` lambdas.
template <typename Archive, typename Views>
void SerializeViews(Archive& ar, Views& views) {
  ar.Array(views, kViewBytes, nullptr, [&](auto& view) {
    ar.Value(view.image_id);
    ar.Value(view.confidence);
  });
}

template <typename Archive, typename Camera>
void SerializeCamera(Archive& ar, Camera& camera, uint32_t version) {
  ar.Value(camera.name);
  if (version >= 4) ar.Value(camera.band_name);
  if (version >= 1) {
    ar.Value(camera.width);
    ar.Value(camera.height);
  }
  ar.Value(camera.K);
  ar.Value(camera.R);
  ar.Value(camera.C);
}

template <typename Archive, typename Image>
void SerializeImage(Archive& ar, Image& image, uint32_t version) {
  ar.Value(image.name);
  if (version >= 5) ar.Value(image.mask_name);
  ar.Value(image.platform_id);
  ar.Value(image.camera_id);
  ar.Value(image.pose_id);
  if (version >= 3) ar.Value(image.id);
  if (version >= 7) {
    ar.Value(image.min_depth);
    ar.Value(image.avg_depth);
    ar.Value(image.max_depth);
    ar.Array(image.view_scores, kViewScoreBytes, nullptr, [&](auto& score) {
      ar.Value(score.id);
      ar.Value(score.points);
      ar.Value(score.scale);
      ar.Value(score.angle);
      ar.Value(score.area);
      ar.Value(score.score);
    });
  }
}

template <typename Archive, typename Scene>
void SerializeScene(Archive& ar, Scene& scene) {
  const uint32_t version = scene.version;
  ar.Array(scene.platforms, kMinPlatformBytes, "platforms", [&](auto& platform) {
    ar.Value(platform.name);
    ar.Array(platform.cameras, kMinCameraBytes, nullptr,
             [&](auto& camera) { SerializeCamera(ar, camera, version); });
    ar.Array(platform.poses, kPoseBytes, nullptr, [&](auto& pose) {
      ar.Value(pose.R);
      ar.Value(pose.C);
    });
  });
  ar.Array(scene.images, kMinImageBytes, "images", [&](auto& image) { SerializeImage(ar, image, version); });
  ar.Array(scene.vertices, kMinVertexBytes, "vertices", [&](auto& vertex) {
    ar.Value(vertex.X);
    SerializeViews(ar, vertex.views);
  });
  ar.Array(scene.vertex_normals, kNormalBytes, "vertex normals", [&](auto& n) { ar.Value(n); });
  ar.Array(scene.vertex_colors, kColorBytes, "vertex colours", [&](auto& c) { ar.Value(c); });
  if (version >= 1) {
    ar.Array(scene.lines, kMinLineBytes, "lines", [&](auto& line) {
      ar.Value(line.pt1);
      ar.Value(line.pt2);
      SerializeViews(ar, line.views);
    });
    ar.Array(scene.line_normals, kNormalBytes, "line normals", [&](auto& n) { ar.Value(n); });
    ar.Array(scene.line_colors, kColorBytes, "line colours", [&](auto& c) { ar.Value(c); });
  }
  if (version >= 2) {
    ar.Label("transform");
    ar.Value(scene.transform);
  }
  if (version >= 6) {
    ar.Label("bounding box");
    ar.Value(scene.bounding_box.rotation);
    ar.Value(scene.bounding_box.min);
    ar.Value(scene.bounding_box.max);
  }
}

// Header: "MVSI", version, reserved. A file without the magic is a version 0 archive, which
// OpenMVS accepts only under the .mvs extension; so do we.
void ReadHeader(ArchiveReader& in, const std::string& bytes, const std::filesystem::path& path,
                OpenMvsScene* scene) {
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), kMagic, 4) == 0) {
    std::array<char, 4> magic;
    in.Value(magic);
    in.Value(scene->version);
    if (scene->version > kOpenMvsNewestVersion) {
      throw FileError(path.string(), "OpenMVS scene version " + std::to_string(scene->version) +
                                         " is newer than the newest supported (" +
                                         std::to_string(kOpenMvsNewestVersion) + ")");
    }
    in.Value(scene->reserved);
    return;
  }
  if (path.extension() != ".mvs") {
    throw FileError(path.string(), "not an OpenMVS scene (no MVSI header, and not a headerless .mvs file)");
  }
  scene->version = 0;
}

void CheckViews(const std::vector<OpenMvsScene::View>& views, size_t num_images, const std::string& source,
                const std::string& owner) {
  for (size_t k = 0; k < views.size(); ++k) {
    if (views[k].image_id >= num_images) {
      throw Error(source + ": " + owner + " is seen by image " + std::to_string(views[k].image_id) +
                  " but there are " + std::to_string(num_images) + " images");
    }
    if (k > 0 && views[k].image_id <= views[k - 1].image_id) {
      throw Error(source + ": " + owner + " lists its views out of order (image " +
                  std::to_string(views[k].image_id) + " after image " +
                  std::to_string(views[k - 1].image_id) + ")");
    }
  }
}

void CheckOptionalArray(size_t size, size_t expected, const std::string& source, const std::string& what,
                        const std::string& of) {
  if (size != 0 && size != expected) {
    throw Error(source + ": " + std::to_string(size) + " " + what + " for " + std::to_string(expected) + " " +
                of);
  }
}

}  // namespace

OpenMvsScene ReadOpenMvsScene(const std::filesystem::path& path) {
  const std::string bytes = ReadFileToString(path);
  ArchiveReader in(bytes, path.string());
  OpenMvsScene scene;
  ReadHeader(in, bytes, path, &scene);
  SerializeScene(in, scene);
  if (in.Remaining() != 0) {
    throw FileError(path.string(), std::to_string(in.Remaining()) +
                                       " unexpected bytes after the scene (at byte " +
                                       std::to_string(in.offset()) + "; corrupt file or a version " +
                                       std::to_string(scene.version) + " header on a newer archive)");
  }
  ValidateOpenMvsScene(scene, path.string());
  return scene;
}

void WriteOpenMvsScene(const OpenMvsScene& scene, const std::filesystem::path& path) {
  if (scene.version > kOpenMvsNewestVersion) {
    throw FileError(path.string(), "cannot write OpenMVS scene version " + std::to_string(scene.version) +
                                       " (newest supported: " + std::to_string(kOpenMvsNewestVersion) + ")");
  }
  WriteFileAtomically(path, true, [&](std::ostream& out) {
    ArchiveWriter writer(out);
    if (scene.version >= 1) {  // version 0 archives have no header
      out.write(kMagic, 4);
      writer.Value(scene.version);
      writer.Value(scene.reserved);
    }
    SerializeScene(writer, scene);
  });
}

void ValidateOpenMvsScene(const OpenMvsScene& scene, const std::string& source) {
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const OpenMvsScene::Image& image = scene.images[i];
    const std::string name = "image " + std::to_string(i) + " (" + image.name + ")";
    if (image.platform_id >= scene.platforms.size()) {
      throw Error(source + ": " + name + " names platform " + std::to_string(image.platform_id) +
                  " but there are " + std::to_string(scene.platforms.size()) + " platforms");
    }
    const OpenMvsScene::Platform& platform = scene.platforms[image.platform_id];
    if (image.camera_id >= platform.cameras.size()) {
      throw Error(source + ": " + name + " names camera " + std::to_string(image.camera_id) +
                  " but platform " + std::to_string(image.platform_id) + " has " +
                  std::to_string(platform.cameras.size()) + " cameras");
    }
    if (image.pose_id != kOpenMvsNoId && image.pose_id >= platform.poses.size()) {
      throw Error(source + ": " + name + " names pose " + std::to_string(image.pose_id) + " but platform " +
                  std::to_string(image.platform_id) + " has " + std::to_string(platform.poses.size()) +
                  " poses");
    }
  }
  for (size_t i = 0; i < scene.vertices.size(); ++i) {
    CheckViews(scene.vertices[i].views, scene.images.size(), source, "vertex " + std::to_string(i));
  }
  for (size_t i = 0; i < scene.lines.size(); ++i) {
    CheckViews(scene.lines[i].views, scene.images.size(), source, "line " + std::to_string(i));
  }
  CheckOptionalArray(scene.vertex_normals.size(), scene.vertices.size(), source, "vertex normals",
                     "vertices");
  CheckOptionalArray(scene.vertex_colors.size(), scene.vertices.size(), source, "vertex colours", "vertices");
  CheckOptionalArray(scene.line_normals.size(), scene.lines.size(), source, "line normals", "lines");
  CheckOptionalArray(scene.line_colors.size(), scene.lines.size(), source, "line colours", "lines");
}

}  // namespace sfm_pruning
