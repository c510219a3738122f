#include "sfm_pruning/io/ply.hpp"

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

struct PlyVertex {
  Eigen::Vector3d X;
  std::array<uint8_t, 3> rgb;
};

std::vector<PlyVertex> CollectVertices(const SfmData& data, const PlyWriteOptions& options) {
  std::vector<PlyVertex> vertices;
  vertices.reserve(data.structure.size() + data.poses.size());
  for (const auto& [id, landmark] : data.structure) vertices.push_back({landmark.X, landmark.color});
  if (options.include_cameras) {
    for (const auto& [id, pose] : data.poses) vertices.push_back({pose.center, {0, 255, 0}});
  }
  if (options.include_control_points) {
    for (const auto& [id, landmark] : data.control_points) vertices.push_back({landmark.X, {255, 0, 0}});
  }
  return vertices;
}

}  // namespace

void WritePly(const SfmData& data, const std::filesystem::path& path, const PlyWriteOptions& options) {
  options.Check();
  const std::vector<PlyVertex> vertices = CollectVertices(data, options);
  WriteFileAtomically(path, options.binary, [&](std::ostream& out) {
    out << "ply\nformat " << (options.binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "comment written by PruneSfM\n"
        << "element vertex " << vertices.size() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    if (options.binary) {
      static_assert(sizeof(double) == 8, "PLY double must be 8 bytes");
      for (const PlyVertex& v : vertices) {
        out.write(reinterpret_cast<const char*>(v.X.data()), 3 * sizeof(double));
        out.write(reinterpret_cast<const char*>(v.rgb.data()), 3);
      }
    } else {
      out.precision(17);
      for (const PlyVertex& v : vertices) {
        out << v.X.x() << ' ' << v.X.y() << ' ' << v.X.z() << ' ' << int(v.rgb[0]) << ' ' << int(v.rgb[1])
            << ' ' << int(v.rgb[2]) << '\n';
      }
    }
  });
}

namespace {

size_t PlyTypeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// A colour channel of vertex `vertex` stored as `type`, as a byte: 16-bit colours are scaled from
// 0-65535, every other type is read as 0-255. A value outside its range or a NaN is refused (it
// would not convert to a byte).
uint8_t ColorChannel(double stored, const std::string& type, size_t vertex, const std::string& source) {
  const bool sixteen_bits = type == "ushort" || type == "uint16";
  const double value = sixteen_bits ? stored * 255.0 / 65535.0 : stored;
  if (!(value >= 0.0 && value <= 255.0)) {
    throw FileError(source, "vertex " + std::to_string(vertex) + ": colour value " + std::to_string(stored) +
                                " is outside " + (sixteen_bits ? "0-65535" : "0-255"));
  }
  return static_cast<uint8_t>(std::lround(value));
}

double ReadBinaryScalar(const char* p, const std::string& type) {
  if (PlyTypeSize(type) == 8) {
    double v;
    std::memcpy(&v, p, 8);
    return v;
  }
  if (type == "float" || type == "float32") {
    float v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (PlyTypeSize(type) == 1) return static_cast<unsigned char>(*p);
  if (type == "int" || type == "int32") {
    int32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (type == "uint" || type == "uint32") {
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  }
  if (type == "short" || type == "int16") {
    int16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  uint16_t v;
  std::memcpy(&v, p, 2);
  return v;
}

}  // namespace

SfmData ReadPlyPoints(const std::filesystem::path& path) {
  const std::string bytes = ReadFileToString(path);
  const std::string source = path.string();
  const size_t header_end = bytes.find("end_header\n");
  if (bytes.compare(0, 4, "ply\n") != 0 || header_end == std::string::npos) {
    throw FileError(source, "not a PLY file (missing 'ply' magic or 'end_header')");
  }
  std::istringstream header(bytes.substr(0, header_end));
  std::string line, format;
  size_t vertex_count = 0;
  bool in_vertex = false, vertex_seen = false;
  std::vector<std::pair<std::string, std::string>> properties;  // (type, name)
  while (std::getline(header, line)) {
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "format") {
      tokens >> format;
    } else if (keyword == "element") {
      std::string name;
      tokens >> name;
      if (vertex_seen && name != "vertex") break;  // we only read the leading vertex element
      in_vertex = name == "vertex";
      if (in_vertex) {
        if (!(tokens >> vertex_count)) throw FileError(source, "bad vertex count in PLY header");
        vertex_seen = true;
      }
    } else if (keyword == "property" && in_vertex) {
      std::string type, name;
      tokens >> type >> name;
      if (type == "list") throw FileError(source, "list properties in the vertex element are not supported");
      if (PlyTypeSize(type) == 0) throw FileError(source, "unknown PLY property type '" + type + "'");
      properties.emplace_back(type, name);
    }
  }
  if (!vertex_seen || properties.size() < 3 || properties[0].second != "x" || properties[1].second != "y" ||
      properties[2].second != "z") {
    throw FileError(source, "PLY vertex element must start with x y z");
  }
  SfmData data;
  const char* body = bytes.data() + header_end + std::strlen("end_header\n");
  const size_t body_size = bytes.size() - (header_end + std::strlen("end_header\n"));
  const auto property_index = [&](const char* name) -> int {
    for (size_t i = 0; i < properties.size(); ++i) {
      if (properties[i].second == name) return static_cast<int>(i);
    }
    return -1;
  };
  const int red = property_index("red"), green = property_index("green"), blue = property_index("blue");
  if (format == "binary_little_endian") {
    size_t stride = 0;
    std::vector<size_t> offsets;
    for (const auto& property : properties) {
      offsets.push_back(stride);
      stride += PlyTypeSize(property.first);
    }
    if (body_size < stride * vertex_count) throw FileError(source, "PLY file is truncated");
    for (size_t v = 0; v < vertex_count; ++v) {
      const char* row = body + v * stride;
      Landmark landmark;
      for (int axis = 0; axis < 3; ++axis) landmark.X[axis] = ReadBinaryScalar(row + offsets[axis], properties[axis].first);
      if (red >= 0 && green >= 0 && blue >= 0) {
        landmark.color = {ColorChannel(ReadBinaryScalar(row + offsets[red], properties[red].first), properties[red].first, v, source),
                          ColorChannel(ReadBinaryScalar(row + offsets[green], properties[green].first), properties[green].first, v, source),
                          ColorChannel(ReadBinaryScalar(row + offsets[blue], properties[blue].first), properties[blue].first, v, source)};
      }
      data.structure[static_cast<IndexT>(v)] = landmark;
    }
  } else if (format == "ascii") {
    std::istringstream in(std::string(body, body_size));
    for (size_t v = 0; v < vertex_count; ++v) {
      std::vector<double> values(properties.size());
      for (double& value : values) {
        if (!(in >> value)) throw FileError(source, "PLY file is truncated or has a non-numeric value");
      }
      Landmark landmark;
      landmark.X = {values[0], values[1], values[2]};
      if (red >= 0 && green >= 0 && blue >= 0) {
        landmark.color = {ColorChannel(values[red], properties[red].first, v, source), ColorChannel(values[green], properties[green].first, v, source),
                          ColorChannel(values[blue], properties[blue].first, v, source)};
      }
      data.structure[static_cast<IndexT>(v)] = landmark;
    }
  } else {
    throw FileError(source, "unsupported PLY format '" + format + "'");
  }
  return data;
}

void PlyWriteOptions::Check() const {}

}  // namespace sfm_pruning
