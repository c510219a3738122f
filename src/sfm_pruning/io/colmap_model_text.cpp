// COLMAP's text sparse model: cameras.txt, images.txt, points3D.txt (layouts in FORMATS.md).
// Doubles are written with 17 significant digits, so a text round trip is exact.
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "sfm_pruning/io/colmap_model_records.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning::colmap_records {
namespace fs = std::filesystem;

namespace {

// Reads a text file line by line, keeping the line number for error messages.
class LineReader {
 public:
  explicit LineReader(const fs::path& path) : path_(path), in_(ReadFileToString(path, false)) {}

  // Next line that is neither empty nor a comment; false at the end of the file.
  bool NextDataLine(std::string* line) {
    while (NextLine(line)) {
      const size_t first = line->find_first_not_of(" \t\r");
      if (first == std::string::npos) continue;
      if ((*line)[first] != '#') return true;
      ReadDeclaredCount(*line);
    }
    return false;
  }

  // After the last line: a header that says "# Number of points: N" must match the N records
  // read, else the file was cut short (or grew by hand).
  void CheckDeclaredCount(size_t records, const char* what) const {
    if (declared_count_ && *declared_count_ != records) {
      throw FileError(path_.string(), "the header declares " + std::to_string(*declared_count_) + " " + what +
                                          ", the file holds " + std::to_string(records) + " (truncated?)");
    }
  }

  // Throws when `id` was already read: COLMAP writes each record once.
  void RequireNew(bool inserted, const char* what, uint64_t id) const {
    if (!inserted) throw Fail(std::string("duplicate ") + what + " " + std::to_string(id));
  }

  // The very next line, empty or not (the POINTS2D line of an image may be empty).
  bool NextLine(std::string* line) {
    if (!std::getline(in_, *line)) return false;
    ++line_number_;
    return true;
  }

  Error Fail(const std::string& problem) const {
    return FileError(path_.string(), "line " + std::to_string(line_number_) + ": " + problem);
  }

  // Parses one value of the current line; throws naming `what` when it is missing or malformed.
  template <typename T>
  T Parse(std::istringstream& tokens, const char* what) const {
    T value;
    if (!(tokens >> value)) throw Fail(std::string("cannot read ") + what);
    return value;
  }

 private:
  // COLMAP's headers: "# Number of cameras: 3", "# Number of images: 5, mean observations ...".
  void ReadDeclaredCount(const std::string& line) {
    const std::string key = "Number of ";
    const size_t at = line.find(key);
    if (at == std::string::npos) return;
    const size_t colon = line.find(':', at);
    if (colon == std::string::npos) return;
    std::istringstream number(line.substr(colon + 1));
    size_t count = 0;
    if (number >> count) declared_count_ = count;
  }

  fs::path path_;
  std::istringstream in_;
  size_t line_number_ = 0;
  std::optional<size_t> declared_count_;
};

bool HasMoreTokens(std::istringstream& tokens) {
  tokens >> std::ws;
  return !tokens.eof();
}

void ReadCameras(const fs::path& path, Model* model) {
  LineReader reader(path);
  std::string line;
  while (reader.NextDataLine(&line)) {
    std::istringstream tokens(line);
    const auto id = reader.Parse<uint32_t>(tokens, "CAMERA_ID");
    const auto model_name = reader.Parse<std::string>(tokens, "MODEL");
    ColmapCamera camera;
    if (!ColmapCameraModelIdFromName(model_name, &camera.model_id)) {
      throw reader.Fail("unknown camera model " + model_name);
    }
    camera.width = reader.Parse<uint64_t>(tokens, "WIDTH");
    camera.height = reader.Parse<uint64_t>(tokens, "HEIGHT");
    while (HasMoreTokens(tokens)) camera.params.push_back(reader.Parse<double>(tokens, "PARAMS"));
    if (camera.params.size() != ColmapCameraNumParams(camera.model_id)) {
      throw reader.Fail("camera model " + model_name + " takes " +
                        std::to_string(ColmapCameraNumParams(camera.model_id)) + " parameters, got " +
                        std::to_string(camera.params.size()));
    }
    reader.RequireNew(model->cameras.emplace(id, camera).second, "CAMERA_ID", id);
  }
  reader.CheckDeclaredCount(model->cameras.size(), "cameras");
}

void ReadImages(const fs::path& path, Model* model) {
  LineReader reader(path);
  std::string line;
  while (reader.NextDataLine(&line)) {
    std::istringstream tokens(line);
    const auto id = reader.Parse<uint32_t>(tokens, "IMAGE_ID");
    Image image;
    for (int k = 0; k < 4; ++k) image.qvec[k] = reader.Parse<double>(tokens, "QVEC");
    for (int k = 0; k < 3; ++k) image.tvec[k] = reader.Parse<double>(tokens, "TVEC");
    image.camera_id = reader.Parse<uint32_t>(tokens, "CAMERA_ID");
    // The name is the rest of the line, so names with spaces survive.
    std::getline(tokens >> std::ws, image.name);
    while (!image.name.empty() && (image.name.back() == '\r' || image.name.back() == ' '))
      image.name.pop_back();
    if (image.name.empty()) throw reader.Fail("cannot read NAME");
    if (!reader.NextLine(&line))
      throw reader.Fail("missing the POINTS2D line of image " + std::to_string(id));
    std::istringstream points(line);
    while (HasMoreTokens(points)) {
      Point2D point;
      point.xy.x() = reader.Parse<double>(points, "POINTS2D X");
      point.xy.y() = reader.Parse<double>(points, "POINTS2D Y");
      point.point3d_id = reader.Parse<int64_t>(points, "POINT3D_ID");
      image.points2d.push_back(point);
    }
    reader.RequireNew(model->images.emplace(id, std::move(image)).second, "IMAGE_ID", id);
  }
  reader.CheckDeclaredCount(model->images.size(), "images");
}

void ReadPoints3D(const fs::path& path, Model* model) {
  LineReader reader(path);
  std::string line;
  while (reader.NextDataLine(&line)) {
    std::istringstream tokens(line);
    const auto id = reader.Parse<uint64_t>(tokens, "POINT3D_ID");
    Point3D point;
    for (int k = 0; k < 3; ++k) point.xyz[k] = reader.Parse<double>(tokens, "XYZ");
    for (int k = 0; k < 3; ++k) {
      const auto channel = reader.Parse<int>(tokens, "RGB");
      if (channel < 0 || channel > 255) throw reader.Fail("colour channel out of range");
      point.rgb[k] = static_cast<uint8_t>(channel);
    }
    point.error = reader.Parse<double>(tokens, "ERROR");
    while (HasMoreTokens(tokens)) {
      const auto image_id = reader.Parse<uint32_t>(tokens, "TRACK IMAGE_ID");
      const auto point2d_idx = reader.Parse<uint32_t>(tokens, "TRACK POINT2D_IDX");
      point.track.emplace_back(image_id, point2d_idx);
    }
    reader.RequireNew(model->points3d.emplace(id, std::move(point)).second, "POINT3D_ID", id);
  }
  reader.CheckDeclaredCount(model->points3d.size(), "points");
}

// rigs.txt: RIG_ID NUM_SENSORS REF_SENSOR_TYPE REF_SENSOR_ID [further sensors].
void CheckSingleCameraRigs(const fs::path& path) {
  if (!fs::exists(path)) return;
  LineReader reader(path);
  std::string line;
  while (reader.NextDataLine(&line)) {
    std::istringstream tokens(line);
    const auto rig_id = reader.Parse<uint32_t>(tokens, "RIG_ID");
    const auto num_sensors = reader.Parse<uint32_t>(tokens, "NUM_SENSORS");
    if (num_sensors != 1) {
      throw reader.Fail("rig " + std::to_string(rig_id) + " has " + std::to_string(num_sensors) +
                        " sensors; only single-camera rigs are supported");
    }
  }
}

void ExactDoubles(std::ostream& out) { out << std::setprecision(std::numeric_limits<double>::max_digits10); }

}  // namespace

Model ReadTextModel(const fs::path& dir) {
  Model model;
  ReadCameras(dir / CamerasFile(false), &model);
  ReadImages(dir / ImagesFile(false), &model);
  ReadPoints3D(dir / Points3DFile(false), &model);
  CheckSingleCameraRigs(dir / RigsFile(false));
  return model;
}

void WriteTextModel(const Model& model, const fs::path& dir) {
  WriteFileAtomically(dir / CamerasFile(false), false, [&](std::ostream& out) {
    ExactDoubles(out);
    out << "# Camera list with one line of data per camera:\n"
        << "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
        << "# Number of cameras: " << model.cameras.size() << "\n";
    for (const auto& [id, camera] : model.cameras) {
      out << id << ' ' << ColmapCameraModelName(camera.model_id) << ' ' << camera.width << ' '
          << camera.height;
      for (double p : camera.params) out << ' ' << p;
      out << '\n';
    }
  });
  WriteFileAtomically(dir / ImagesFile(false), false, [&](std::ostream& out) {
    ExactDoubles(out);
    out << "# Image list with two lines of data per image:\n"
        << "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
        << "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
        << "# Number of images: " << model.images.size() << "\n";
    for (const auto& [id, image] : model.images) {
      out << id;
      for (int k = 0; k < 4; ++k) out << ' ' << image.qvec[k];
      for (int k = 0; k < 3; ++k) out << ' ' << image.tvec[k];
      out << ' ' << image.camera_id << ' ' << image.name << '\n';
      for (size_t k = 0; k < image.points2d.size(); ++k) {
        const Point2D& point = image.points2d[k];
        out << (k == 0 ? "" : " ") << point.xy.x() << ' ' << point.xy.y() << ' ' << point.point3d_id;
      }
      out << '\n';
    }
  });
  WriteFileAtomically(dir / Points3DFile(false), false, [&](std::ostream& out) {
    ExactDoubles(out);
    out << "# 3D point list with one line of data per point:\n"
        << "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
        << "# Number of points: " << model.points3d.size() << "\n";
    for (const auto& [id, point] : model.points3d) {
      out << id;
      for (int k = 0; k < 3; ++k) out << ' ' << point.xyz[k];
      for (int k = 0; k < 3; ++k) out << ' ' << static_cast<int>(point.rgb[k]);
      out << ' ' << point.error;
      for (const auto& [image_id, point2d_idx] : point.track) out << ' ' << image_id << ' ' << point2d_idx;
      out << '\n';
    }
  });
}

}  // namespace sfm_pruning::colmap_records
